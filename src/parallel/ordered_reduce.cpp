#include "halfeti/parallel/ordered_reduce.hpp"

#include <algorithm>
#include <numeric>

#include "halfeti/parallel/gather.hpp"

namespace halfeti::parallel {

namespace {
// Gathers everything onto rank 0 (gids and values), sorted by gid there.
void gather_sorted_on_root(MPI_Comm comm, const std::vector<std::int64_t>& gids,
                           const std::vector<double>& values, int ncomp, std::vector<std::int64_t>& all_gids,
                           std::vector<double>& all_values) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::vector<std::int64_t> g = gather_to_root(comm, 0, gids);
  const std::vector<double> v = gather_to_root(comm, 0, values);
  const int total = static_cast<int>(g.size());
  all_gids.clear();
  all_values.clear();
  if (rank != 0) return;
  std::vector<int> perm(total);
  std::iota(perm.begin(), perm.end(), 0);
  std::sort(perm.begin(), perm.end(), [&](int a, int b) { return g[a] < g[b]; });
  all_gids.resize(total);
  all_values.resize(static_cast<std::size_t>(total) * ncomp);
  for (int k = 0; k < total; ++k) {
    all_gids[k] = g[perm[k]];
    for (int c = 0; c < ncomp; ++c)
      all_values[static_cast<std::size_t>(k) * ncomp + c] = v[static_cast<std::size_t>(perm[k]) * ncomp + c];
  }
}
}  // namespace

std::vector<double> ordered_sum(MPI_Comm comm, const std::vector<std::int64_t>& gids,
                                const std::vector<double>& values, int ncomp) {
  std::vector<std::int64_t> g;
  std::vector<double> v;
  gather_sorted_on_root(comm, gids, values, ncomp, g, v);
  std::vector<double> sums(ncomp, 0.0);
  for (std::size_t k = 0; k < g.size(); ++k)
    for (int c = 0; c < ncomp; ++c) sums[c] += v[k * ncomp + c];
  MPI_Bcast(sums.data(), ncomp, MPI_DOUBLE, 0, comm);
  return sums;
}

void gather_sorted(MPI_Comm comm, const std::vector<std::int64_t>& gids, const std::vector<double>& values,
                   int ncomp, std::vector<std::int64_t>& all_gids, std::vector<double>& all_values) {
  gather_sorted_on_root(comm, gids, values, ncomp, all_gids, all_values);
  long n = static_cast<long>(all_gids.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, comm);
  all_gids.resize(n);
  all_values.resize(static_cast<std::size_t>(n) * ncomp);
  MPI_Bcast(all_gids.data(), static_cast<int>(n), MPI_INT64_T, 0, comm);
  MPI_Bcast(all_values.data(), static_cast<int>(n * ncomp), MPI_DOUBLE, 0, comm);
}

}  // namespace halfeti::parallel
