// Gather to one rank: every rank's records concatenated on the root in rank order. The callers then sort by global
// id (principle 5: what the root computes from them must not depend on how the particles are split over ranks):
// the ordered sums (ordered_reduce.cpp), the contact's invaders (interface_exchange.cpp) and the plate-wall loads
// (contact_coupling.cpp).
#pragma once

#include <mpi.h>

#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include "halfeti/core/error.hpp"

namespace halfeti::parallel {

// Returns all ranks' `local` on `root` (rank 0's first), an empty vector elsewhere. Collective. The ranks are
// homogeneous, so the records travel as bytes; T must be trivially copyable.
template <class T>
std::vector<T> gather_to_root(MPI_Comm comm, int root, const std::vector<T>& local) {
  static_assert(std::is_trivially_copyable_v<T>, "gather_to_root sends records as bytes");
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  HALFETI_CHECK(
      local.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()) / sizeof(T),
      "gather_to_root: " << local.size() << " records of " << sizeof(T) << " bytes exceed one MPI message");
  const int bytes = static_cast<int>(local.size() * sizeof(T));
  std::vector<int> counts(rank == root ? size : 0), displs(rank == root ? size : 0);
  MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm);
  std::vector<T> all;
  if (rank == root) {
    long long total = 0;
    for (int r = 0; r < size; ++r) {
      displs[r] = static_cast<int>(total);
      total += counts[r];
    }
    HALFETI_CHECK(total <= std::numeric_limits<int>::max(),
                  "gather_to_root: " << total << " bytes on the root exceed one MPI message");
    all.resize(static_cast<std::size_t>(total) / sizeof(T));
  }
  MPI_Gatherv(local.data(), bytes, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, root, comm);
  return all;
}

}  // namespace halfeti::parallel
