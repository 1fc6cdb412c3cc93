#include "halfeti/parallel/migration.hpp"

#include "halfeti/core/error.hpp"

namespace halfeti::parallel {

std::vector<int> destinations(const std::vector<int>& cells, const std::vector<int>& owner) {
  std::vector<int> dest(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) dest[i] = owner[cells[i]];
  return dest;
}

namespace {
// Particle indices grouped by destination rank in increasing order, each group in the particles' order; and
// the count for each rank.
std::vector<int> group_by_destination(const std::vector<int>& destination, int size,
                                      std::vector<int>& counts) {
  std::vector<int> fill(size, 0), order(destination.size());
  counts.assign(size, 0);
  for (int d : destination) ++counts[d];
  for (int r = 1; r < size; ++r) fill[r] = fill[r - 1] + counts[r - 1];
  for (std::size_t i = 0; i < destination.size(); ++i) order[fill[destination[i]]++] = static_cast<int>(i);
  return order;
}
}  // namespace

ParticleMigration::ParticleMigration(MPI_Comm comm, const std::vector<int>& destination, Traffic* traffic) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> counts;
  order_ = group_by_destination(destination, size, counts);
  plan_ = CommPlan::discover(comm, counts, traffic);
}

ParticleMigration::ParticleMigration(MPI_Comm comm, const std::vector<int>& destination,
                                     const std::vector<int>& peers, Traffic* traffic) {
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  std::vector<int> counts;
  order_ = group_by_destination(destination, size, counts);
  std::vector<int> to_peers(peers.size());
  std::size_t placed = static_cast<std::size_t>(counts[rank]);
  for (std::size_t k = 0; k < peers.size(); ++k) {
    to_peers[k] = counts[peers[k]];
    placed += static_cast<std::size_t>(to_peers[k]);
  }
  HALFETI_CHECK(placed == destination.size(), "a particle's destination is neither this rank nor a peer");
  plan_ = CommPlan::with_peers(comm, peers, to_peers, counts[rank], traffic);
}

void ParticleMigration::apply(std::vector<double>& field, int ncomp) const {
  std::vector<double> buf(order_.size() * ncomp), out(new_count() * ncomp);
  for (std::size_t k = 0; k < order_.size(); ++k)
    for (int c = 0; c < ncomp; ++c)
      buf[k * ncomp + c] = field[static_cast<std::size_t>(order_[k]) * ncomp + c];
  plan_.exchange(buf.data(), out.data(), ncomp, MPI_DOUBLE);
  field.swap(out);
}

void ParticleMigration::apply(std::vector<std::int64_t>& field) const {
  std::vector<std::int64_t> buf(order_.size()), out(new_count());
  for (std::size_t k = 0; k < order_.size(); ++k) buf[k] = field[order_[k]];
  plan_.exchange(buf.data(), out.data(), 1, MPI_INT64_T);
  field.swap(out);
}

}  // namespace halfeti::parallel
