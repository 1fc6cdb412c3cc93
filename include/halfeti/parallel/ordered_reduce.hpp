// Sums that give the same bits on any number of ranks: contributions tagged with global particle ids are gathered
// to rank 0, sorted by id, summed in that order and broadcast. Used for probes and global diagnostics (a plain
// MPI_Allreduce sum depends on how the terms are split over ranks).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace halfeti::parallel {

// values holds ncomp entries per local contribution (row-major). Returns the ncomp sums on every rank.
std::vector<double> ordered_sum(MPI_Comm comm, const std::vector<std::int64_t>& gids,
                                const std::vector<double>& values, int ncomp);

// Gathers (gid, ncomp values) from every rank onto every rank, sorted by gid (for tests and small outputs).
void gather_sorted(MPI_Comm comm, const std::vector<std::int64_t>& gids, const std::vector<double>& values,
                   int ncomp, std::vector<std::int64_t>& all_gids, std::vector<double>& all_values);

}  // namespace halfeti::parallel
