// The one all-to-all exchange the halo plan and the migration share: per-rank counts and displacements in items,
// each item `ncomp` values of `type`.
#pragma once

#include <mpi.h>

#include <vector>

namespace halfeti::parallel {

void exchange_items(MPI_Comm comm, const std::vector<int>& send_counts, const std::vector<int>& send_displs,
                    const std::vector<int>& recv_counts, const std::vector<int>& recv_displs, int ncomp,
                    const void* send, void* recv, MPI_Datatype type);

}  // namespace halfeti::parallel
