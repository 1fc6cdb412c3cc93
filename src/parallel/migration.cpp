#include "halfeti/parallel/migration.hpp"

namespace halfeti::parallel {

std::vector<int> destinations(const std::vector<int>& cells, const std::vector<int>& owner) {
  std::vector<int> dest(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) dest[i] = owner[cells[i]];
  return dest;
}

ParticleMigration::ParticleMigration(MPI_Comm comm, const std::vector<int>& destination, Traffic* traffic) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> counts(size, 0), fill(size, 0);
  for (int d : destination) ++counts[d];
  for (int r = 1; r < size; ++r) fill[r] = fill[r - 1] + counts[r - 1];
  order_.resize(destination.size());
  for (std::size_t i = 0; i < destination.size(); ++i) order_[fill[destination[i]]++] = static_cast<int>(i);
  plan_ = CommPlan::discover(comm, counts, traffic);
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
