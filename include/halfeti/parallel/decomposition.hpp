// Deciding where cells (and so particles) live: a partition of the cell graph by METIS, weighted by particle
// count. Only decides; moving particles is ParticleMigration's job.
#pragma once

#include <mpi.h>

#include <vector>

#include "halfeti/parallel/cell_grid.hpp"

namespace halfeti::parallel {

// Partitions the cells of `grid` into `nparts` parts, balancing `cell_weights` (e.g. particles per cell) with
// METIS_PartGraphKway on the 8-neighbour cell graph. Deterministic (fixed seed). nparts == 1 needs no METIS.
std::vector<int> partition_cells(const CellGrid& grid, const std::vector<long>& cell_weights, int nparts);

// Collective: every rank passes the same grid and the (already global) weights; rank 0 partitions and
// broadcasts, so every rank holds the same owner map whatever METIS would do on each.
std::vector<int> partition_cells_collective(MPI_Comm comm, const CellGrid& grid,
                                            const std::vector<long>& cell_weights);

// Load imbalance max_r(w_r) / mean_r(w_r) of a given owner map (1 = perfect).
double imbalance(const std::vector<int>& owner, const std::vector<long>& cell_weights, int nparts);

}  // namespace halfeti::parallel
