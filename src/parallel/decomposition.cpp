#include "halfeti/parallel/decomposition.hpp"

#include <metis.h>

#include <algorithm>

#include "halfeti/core/error.hpp"

namespace halfeti::parallel {

std::vector<double> part_targets(int nparts, double first_share) {
  HALFETI_CHECK(nparts >= 1 && first_share > 0.0, "part_targets(" << nparts << ", " << first_share << ")");
  std::vector<double> t(static_cast<std::size_t>(nparts), 1.0 / (first_share + nparts - 1));
  t[0] *= first_share;
  return t;
}

std::vector<int> partition_cells(const CellGrid& grid, const std::vector<long>& cell_weights, int nparts,
                                 double first_share) {
  const int n = grid.cell_count();
  HALFETI_CHECK(static_cast<int>(cell_weights.size()) == n, "one weight per cell expected");
  std::vector<int> owner(n, 0);
  if (nparts <= 1) return owner;

  // 8-neighbour cell graph in CSR form; edges are the cell pairs whose particles interact.
  std::vector<idx_t> xadj(n + 1, 0), adjncy;
  adjncy.reserve(static_cast<std::size_t>(n) * 8);
  for (int c = 0; c < n; ++c) {
    grid.for_each_neighbour(c, [&](int j) { adjncy.push_back(j); });
    xadj[c + 1] = static_cast<idx_t>(adjncy.size());
  }
  // Empty cells weigh a little so that METIS still places them sensibly (they fill as water moves).
  std::vector<idx_t> vwgt(n);
  for (int c = 0; c < n; ++c) vwgt[c] = static_cast<idx_t>(16 * cell_weights[c] + 1);

  idx_t nvtxs = n, ncon = 1, np = nparts, objval = 0;
  std::vector<idx_t> part(n, 0);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 7;
  options[METIS_OPTION_CONTIG] = 1;
  std::vector<real_t> tpwgts;
  for (double t : part_targets(nparts, first_share)) tpwgts.push_back(static_cast<real_t>(t));
  const int status = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr,
                                         nullptr, &np, tpwgts.data(), nullptr, options, &objval, part.data());
  HALFETI_CHECK(status == METIS_OK, "METIS_PartGraphKway failed with status " << status);
  for (int c = 0; c < n; ++c) owner[c] = static_cast<int>(part[c]);
  return owner;
}

std::vector<int> partition_cells_collective(MPI_Comm comm, const CellGrid& grid,
                                            const std::vector<long>& cell_weights, double first_share) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::vector<int> owner(grid.cell_count(), 0);
  if (size == 1) return owner;
  if (rank == 0) owner = partition_cells(grid, cell_weights, size, first_share);
  MPI_Bcast(owner.data(), grid.cell_count(), MPI_INT, 0, comm);
  return owner;
}

double imbalance(const std::vector<int>& owner, const std::vector<long>& cell_weights, int nparts,
                 double first_share) {
  std::vector<long> load(std::max(nparts, 1), 0);
  long total = 0;
  for (std::size_t c = 0; c < owner.size(); ++c) {
    load[owner[c]] += cell_weights[c];
    total += cell_weights[c];
  }
  if (total == 0) return 1.0;
  const std::vector<double> target = part_targets(std::max(nparts, 1), first_share);
  double worst = 0.0;
  for (std::size_t r = 0; r < load.size(); ++r)
    worst = std::max(worst, static_cast<double>(load[r]) / (target[r] * static_cast<double>(total)));
  return worst;
}

}  // namespace halfeti::parallel
