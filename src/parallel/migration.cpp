#include "halfeti/parallel/migration.hpp"

#include "halfeti/parallel/exchange.hpp"

namespace halfeti::parallel {

std::vector<int> destinations(const std::vector<int>& cells, const std::vector<int>& owner) {
  std::vector<int> dest(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) dest[i] = owner[cells[i]];
  return dest;
}

ParticleMigration::ParticleMigration(MPI_Comm comm, const std::vector<int>& destination) : comm_(comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  send_counts_.assign(size, 0);
  send_displs_.assign(size, 0);
  recv_counts_.assign(size, 0);
  recv_displs_.assign(size, 0);
  int leaving = 0;
  for (int d : destination) {
    ++send_counts_[d];
    leaving += d != rank;
  }
  int any = leaving > 0 ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, comm);
  anything_moves_ = any != 0;
  for (int r = 1; r < size; ++r) send_displs_[r] = send_displs_[r - 1] + send_counts_[r - 1];
  order_.resize(destination.size());
  std::vector<int> fill(send_displs_);
  for (std::size_t i = 0; i < destination.size(); ++i) order_[fill[destination[i]]++] = static_cast<int>(i);
  MPI_Alltoall(send_counts_.data(), 1, MPI_INT, recv_counts_.data(), 1, MPI_INT, comm);
  for (int r = 0; r < size; ++r) {
    recv_displs_[r] = recv_total_;
    recv_total_ += recv_counts_[r];
  }
}

void ParticleMigration::move(const void* send, void* recv, int ncomp, MPI_Datatype type, std::size_t) const {
  exchange_items(comm_, send_counts_, send_displs_, recv_counts_, recv_displs_, ncomp, send, recv, type);
}

void ParticleMigration::apply(std::vector<double>& field, int ncomp) const {
  std::vector<double> buf(order_.size() * ncomp), out(static_cast<std::size_t>(recv_total_) * ncomp);
  for (std::size_t k = 0; k < order_.size(); ++k)
    for (int c = 0; c < ncomp; ++c) buf[k * ncomp + c] = field[static_cast<std::size_t>(order_[k]) * ncomp + c];
  move(buf.data(), out.data(), ncomp, MPI_DOUBLE, sizeof(double));
  field.swap(out);
}

void ParticleMigration::apply(std::vector<std::int64_t>& field) const {
  std::vector<std::int64_t> buf(order_.size()), out(recv_total_);
  for (std::size_t k = 0; k < order_.size(); ++k) buf[k] = field[order_[k]];
  move(buf.data(), out.data(), 1, MPI_INT64_T, sizeof(std::int64_t));
  field.swap(out);
}

}  // namespace halfeti::parallel
