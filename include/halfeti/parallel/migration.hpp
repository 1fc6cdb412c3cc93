// Moving particles to the rank that owns their cell. ParticleMigration is a plan (ids and ranks) built from each
// particle's destination; apply() moves one field at a time. Particles that stay keep their relative order,
// arrivals follow in order of source rank, then of their position on the source. Its messages go to the ranks
// that send or receive particles only (CommPlan::discover), whatever the destinations (a new partition moves
// particles between ranks that were not neighbours), or, when the destinations are known to be neighbours, to
// those (CommPlan::with_peers).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

#include "halfeti/parallel/comm_plan.hpp"

namespace halfeti::parallel {

class ParticleMigration {
 public:
  // Collective. destination[i] = rank that must own particle i after the move. `traffic`, if given, counts the
  // plan's messages.
  ParticleMigration(MPI_Comm comm, const std::vector<int>& destination, Traffic* traffic = nullptr);
  // The same when every destination is this rank or one of `peers` (CommPlan::with_peers: the counts are swapped
  // with the peers only, nothing goes over the whole communicator). For a step's moves, which take a particle at
  // most to a cell next to its own: the caller knows, and uses the constructor above when it does not hold.
  ParticleMigration(MPI_Comm comm, const std::vector<int>& destination, const std::vector<int>& peers,
                    Traffic* traffic = nullptr);

  std::size_t new_count() const { return plan_.recv_total(); }
  // Whether this rank's particles change (some leave or arrive); apply() on a rank where none does leaves the
  // fields as they are, so it may be skipped there (it is not collective).
  bool anything_moves() const { return plan_.exchanges_anything(); }

  // Row-major fields with ncomp values per particle; replaced by the migrated rows.
  void apply(std::vector<double>& field, int ncomp = 1) const;
  void apply(std::vector<std::int64_t>& field) const;

 private:
  std::vector<int> order_;  // local indices grouped by destination (stable)
  CommPlan plan_;
};

// Destination rank of each particle: owner of its cell.
std::vector<int> destinations(const std::vector<int>& cells, const std::vector<int>& owner);

}  // namespace halfeti::parallel
