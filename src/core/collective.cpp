#include "halfeti/core/collective.hpp"

#include <climits>

namespace halfeti {

int first_rank(MPI_Comm comm, bool has, long key) {
  long local = has ? key : LONG_MAX;
  long best = LONG_MAX;
  MPI_Allreduce(&local, &best, 1, MPI_LONG, MPI_MIN, comm);
  if (best == LONG_MAX) return -1;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int mine = (has && key == best) ? rank : INT_MAX, root = INT_MAX;
  MPI_Allreduce(&mine, &root, 1, MPI_INT, MPI_MIN, comm);
  return root;
}

std::string broadcast_from(MPI_Comm comm, int root, const std::string& message) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int len = rank == root ? static_cast<int>(message.size()) : 0;
  MPI_Bcast(&len, 1, MPI_INT, root, comm);
  std::string out(rank == root ? message : std::string(len, ' '));
  MPI_Bcast(out.data(), len, MPI_CHAR, root, comm);
  return out;
}

std::string first_problem(MPI_Comm comm, bool has_problem, long key, const std::string& message) {
  const int root = first_rank(comm, has_problem, key);
  return root < 0 ? std::string() : broadcast_from(comm, root, message);
}

}  // namespace halfeti
