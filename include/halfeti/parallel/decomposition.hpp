// Deciding where cells (and so particles) live: a partition of the cell graph by METIS, weighted by particle
// count. Only decides; moving particles is ParticleMigration's job.
#pragma once

#include <mpi.h>

#include <vector>

#include "halfeti/parallel/cell_grid.hpp"

namespace halfeti::parallel {

// The share of the whole weight each part should hold: part 0 carries `first_share` times what each other part
// carries (part 0 is the rank that also solves the structure while the others wait; 1 = equal shares).
std::vector<double> part_targets(int nparts, double first_share);

// Partitions the cells of `grid` into `nparts` parts, balancing `cell_weights` (e.g. particles per cell) with
// METIS_PartGraphKway on the 8-neighbour cell graph towards part_targets(nparts, first_share). Deterministic
// (fixed seed). nparts == 1 needs no METIS.
std::vector<int> partition_cells(const CellGrid& grid, const std::vector<long>& cell_weights, int nparts,
                                 double first_share = 1.0);

// Collective: every rank passes the same grid and the (already global) weights; rank 0 partitions and
// broadcasts, so every rank holds the same owner map whatever METIS would do on each.
std::vector<int> partition_cells_collective(MPI_Comm comm, const CellGrid& grid,
                                            const std::vector<long>& cell_weights, double first_share = 1.0);

// Load imbalance max_r(w_r / target_r) of a given owner map, target_r = total * part_targets(...)[r] (1 = perfect).
double imbalance(const std::vector<int>& owner, const std::vector<long>& cell_weights, int nparts,
                 double first_share = 1.0);

}  // namespace halfeti::parallel
