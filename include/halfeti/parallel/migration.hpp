// Moving particles to the rank that owns their cell. ParticleMigration is a plan (ids and ranks) built from each
// particle's destination; apply() moves one field at a time. Particles that stay keep their relative order,
// arrivals follow in order of source rank, then of their position on the source.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace halfeti::parallel {

class ParticleMigration {
 public:
  // Collective. destination[i] = rank that must own particle i after the move.
  ParticleMigration(MPI_Comm comm, const std::vector<int>& destination);

  std::size_t new_count() const { return static_cast<std::size_t>(recv_total_); }
  bool anything_moves() const { return anything_moves_; }

  // Row-major fields with ncomp values per particle; replaced by the migrated rows.
  void apply(std::vector<double>& field, int ncomp = 1) const;
  void apply(std::vector<std::int64_t>& field) const;

 private:
  void move(const void* send, void* recv, int ncomp, MPI_Datatype type, std::size_t elem) const;

  MPI_Comm comm_;
  std::vector<int> order_;  // local indices grouped by destination (stable)
  std::vector<int> send_counts_, send_displs_, recv_counts_, recv_displs_;
  int recv_total_ = 0;
  bool anything_moves_ = false;
};

// Destination rank of each particle: owner of its cell.
std::vector<int> destinations(const std::vector<int>& cells, const std::vector<int>& owner);

}  // namespace halfeti::parallel
