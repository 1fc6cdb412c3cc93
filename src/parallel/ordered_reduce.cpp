#include "halfeti/parallel/ordered_reduce.hpp"

#include <algorithm>
#include <numeric>

namespace halfeti::parallel {

namespace {
// Gathers everything onto rank 0 (gids and values), sorted by gid there.
void gather_to_root(MPI_Comm comm, const std::vector<std::int64_t>& gids, const std::vector<double>& values,
                    int ncomp, std::vector<std::int64_t>& all_gids, std::vector<double>& all_values) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(gids.size());
  std::vector<int> counts(size), displs(size, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  int total = 0;
  if (rank == 0)
    for (int r = 0; r < size; ++r) {
      displs[r] = total;
      total += counts[r];
    }
  std::vector<std::int64_t> g(rank == 0 ? total : 0);
  MPI_Gatherv(gids.data(), n, MPI_INT64_T, g.data(), counts.data(), displs.data(), MPI_INT64_T, 0, comm);
  std::vector<int> vc(size), vd(size);
  for (int r = 0; r < size; ++r) {
    vc[r] = counts[r] * ncomp;
    vd[r] = displs[r] * ncomp;
  }
  std::vector<double> v(rank == 0 ? static_cast<std::size_t>(total) * ncomp : 0);
  MPI_Gatherv(values.data(), n * ncomp, MPI_DOUBLE, v.data(), vc.data(), vd.data(), MPI_DOUBLE, 0, comm);
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
  gather_to_root(comm, gids, values, ncomp, g, v);
  std::vector<double> sums(ncomp, 0.0);
  for (std::size_t k = 0; k < g.size(); ++k)
    for (int c = 0; c < ncomp; ++c) sums[c] += v[k * ncomp + c];
  MPI_Bcast(sums.data(), ncomp, MPI_DOUBLE, 0, comm);
  return sums;
}

void gather_sorted(MPI_Comm comm, const std::vector<std::int64_t>& gids, const std::vector<double>& values,
                   int ncomp, std::vector<std::int64_t>& all_gids, std::vector<double>& all_values) {
  gather_to_root(comm, gids, values, ncomp, all_gids, all_values);
  long n = static_cast<long>(all_gids.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, comm);
  all_gids.resize(n);
  all_values.resize(static_cast<std::size_t>(n) * ncomp);
  MPI_Bcast(all_gids.data(), static_cast<int>(n), MPI_INT64_T, 0, comm);
  MPI_Bcast(all_values.data(), static_cast<int>(n * ncomp), MPI_DOUBLE, 0, comm);
}

}  // namespace halfeti::parallel
