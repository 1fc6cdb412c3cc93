// Health monitors of the fluid (DESIGN.md): density variation (warning), particle outside the tank (fatal),
// spacing collapse (warning), NaN/Inf (fatal), dt below the floor (fatal). Checks are collective; a fatal one
// throws halfeti::NumericalError with the same single message on every rank.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "halfeti/core/health.hpp"

namespace halfeti::sph {

using HealthEvent = halfeti::HealthEvent;  // one record for every part's monitors (core/health.hpp)

// Collective: among the ranks with has_problem, the message of the one with the smallest `key` (e.g. particle
// gid) is returned on every rank; empty when no rank has one.
std::string first_problem(MPI_Comm comm, bool has_problem, long key, const std::string& message);

}  // namespace halfeti::sph
