// The commands of the `halfeti` program, callable from tests as well as from main.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

namespace halfeti::app {

// Runs one command line (without the program name) on `comm`; returns the exit status. Errors are thrown as
// halfeti::Error (UserError, NumericalError) on every rank together.
int execute(const std::vector<std::string>& args, MPI_Comm comm);

}  // namespace halfeti::app
