// halfeti: the thin main. Starts MPI, reads the command, and hands over to the run, the check or a tool.
//
//   mpirun -n 2 halfeti run inputs/validation/dambreak.yaml --out out/dambreak
//   halfeti check inputs/paper/cosine_cable.yaml --set fluid.spacing=0.002
//   halfeti cable --from 0,0.01 --to 0.1485,0.08 --modulus 1.14e6 --area 4e-6 --density 1150 --tension-stress 135e3
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "halfeti/app/commands.hpp"
#include "halfeti/core/error.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::vector<std::string> args(argv + 1, argv + argc);
  int status = 0;
  try {
    status = halfeti::app::execute(args, MPI_COMM_WORLD);
  } catch (const halfeti::InternalError& e) {
    // Not known to be collective: other ranks may wait in a collective call, so abort them all.
    std::fprintf(stderr, "halfeti: %s\n", e.what());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, halfeti::exit_status(e.kind()));
  } catch (const halfeti::Error& e) {
    // User and numerical errors are raised on every rank together (collective checks); rank 0 says it once, one
    // prefixed line per error (a scene's check reports all it found).
    if (rank == 0) {
      const std::string text = e.what();
      for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::fprintf(stderr, "halfeti: error: %s\n", text.substr(start, end - start).c_str());
        start = end + 1;
      }
    }
    status = halfeti::exit_status(e.kind());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "halfeti: internal error: %s\n", e.what());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 4);
  }
  MPI_Finalize();
  return status;
}
