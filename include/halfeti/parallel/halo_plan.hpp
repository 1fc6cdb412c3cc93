// A halo plan: which owned particles each rank sends to which neighbour ranks as ghosts. It holds ids and ranks
// only, never fields; build it once per neighbour-list rebuild and reuse it for every field (positions,
// velocities, densities, then the renormalised density gradient). The MPI calls live in halo_plan.cpp.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

#include "halfeti/parallel/cell_grid.hpp"

namespace halfeti::parallel {

class HaloPlan {
 public:
  HaloPlan() = default;
  // Collective. `cells[i]` is the cell of owned particle i, `owner` the cell -> rank map. A particle is sent to
  // every other rank that owns one of the 8 cells around its own (its kernel support may reach there).
  HaloPlan(MPI_Comm comm, const CellGrid& grid, const std::vector<int>& owner, const std::vector<int>& cells);

  std::size_t ghost_count() const { return static_cast<std::size_t>(recv_total_); }
  std::size_t send_count() const { return send_ids_.size(); }

  // Copies `ncomp` doubles per particle from the owned rows of `field` (row-major, ncomp per particle) into
  // rows [owned, owned + ghosts) of the same array (it is resized to (owned + ghosts) * ncomp).
  void update(std::vector<double>& field, std::size_t owned, int ncomp = 1) const;
  void update(std::vector<std::int64_t>& field, std::size_t owned) const;

 private:
  void exchange(const void* send, void* recv, int ncomp, MPI_Datatype type) const;

  MPI_Comm comm_ = MPI_COMM_NULL;
  std::vector<int> send_ids_;  // owned indices, grouped by destination rank
  std::vector<int> send_counts_, send_displs_, recv_counts_, recv_displs_;
  int recv_total_ = 0;
};

}  // namespace halfeti::parallel
