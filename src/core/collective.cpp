#include "halfeti/core/collective.hpp"

#include <climits>

namespace halfeti {

std::string first_problem(MPI_Comm comm, bool has_problem, long key, const std::string& message) {
  long local = has_problem ? key : LONG_MAX;
  long best = LONG_MAX;
  MPI_Allreduce(&local, &best, 1, MPI_LONG, MPI_MIN, comm);
  if (best == LONG_MAX) return {};
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int mine = (has_problem && key == best) ? rank : INT_MAX, root = INT_MAX;
  MPI_Allreduce(&mine, &root, 1, MPI_INT, MPI_MIN, comm);
  int len = rank == root ? static_cast<int>(message.size()) : 0;
  MPI_Bcast(&len, 1, MPI_INT, root, comm);
  std::string out(rank == root ? message : std::string(len, ' '));
  MPI_Bcast(out.data(), len, MPI_CHAR, root, comm);
  return out;
}

}  // namespace halfeti
