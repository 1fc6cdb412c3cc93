// A halo plan: which owned particles each rank sends to which neighbour ranks as ghosts. It holds ids and ranks
// only, never fields; build it once per neighbour-list rebuild and reuse it for every field (positions,
// velocities, densities, then the renormalised density gradient). Its messages go to the neighbour ranks only
// (CommPlan::with_peers).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "halfeti/parallel/cell_grid.hpp"
#include "halfeti/parallel/comm_plan.hpp"

namespace halfeti::parallel {

// The ranks other than `rank` that own a cell among the 8 around a cell `rank` owns: whom its halo talks to. The
// relation is symmetric, so it serves CommPlan::with_peers. In increasing rank.
std::vector<int> neighbour_ranks(const CellGrid& grid, const std::vector<int>& owner, int rank);

class HaloPlan {
 public:
  HaloPlan() = default;
  // Collective over the neighbour ranks. `cells[i]` is the cell of owned particle i (sorted by cell or not),
  // `owner` the cell -> rank map, `peers` its neighbour_ranks() for this rank (kept by the caller while the map
  // holds). A particle is sent to every other rank that owns one of the 8 cells around its own (its kernel
  // support may reach there). `traffic`, if given, counts the plan's messages.
  HaloPlan(MPI_Comm comm, const CellGrid& grid, const std::vector<int>& owner, const std::vector<int>& cells,
           const std::vector<int>& peers, Traffic* traffic = nullptr);
  // The same, the peers found from the map.
  HaloPlan(MPI_Comm comm, const CellGrid& grid, const std::vector<int>& owner, const std::vector<int>& cells);

  std::size_t ghost_count() const { return plan_.recv_total(); }
  std::size_t send_count() const { return send_ids_.size(); }

  // Copies `ncomp` doubles per particle from the owned rows of `field` (row-major, ncomp per particle) into
  // rows [owned, owned + ghosts) of the same array (it is resized to (owned + ghosts) * ncomp).
  void update(std::vector<double>& field, std::size_t owned, int ncomp = 1) const;
  void update(std::vector<std::int64_t>& field, std::size_t owned) const;
  // The same for several fields kept one array each (each holds at least `owned` values): the messages of
  // update() on their interleaved array (one item a particle, the fields in the order given), but only the rows
  // sent are packed, so a rank with few ghosts does not copy every owned particle's state.
  void update(std::initializer_list<std::vector<double>*> fields, std::size_t owned) const;

 private:
  bool single_ = true;         // one rank: no ghosts
  std::vector<int> send_ids_;  // owned indices, grouped by destination rank in increasing order
  CommPlan plan_;
};

}  // namespace halfeti::parallel
