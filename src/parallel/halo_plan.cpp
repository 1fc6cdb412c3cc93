#include "halfeti/parallel/halo_plan.hpp"

#include "halfeti/parallel/exchange.hpp"

#include <algorithm>

namespace halfeti::parallel {

HaloPlan::HaloPlan(MPI_Comm comm, const CellGrid& grid, const std::vector<int>& owner,
                   const std::vector<int>& cells)
    : comm_(comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  send_counts_.assign(size, 0);
  send_displs_.assign(size, 0);
  recv_counts_.assign(size, 0);
  recv_displs_.assign(size, 0);
  if (size == 1) return;

  // Ranks that see each cell's particles as ghosts: the owners of the 8 surrounding cells, except the cell's own.
  // Computed per occupied cell once, then applied to its particles.
  std::vector<std::vector<int>> per_rank(size);
  int last_cell = -1;
  int targets[8];
  int ntargets = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int c = cells[i];
    if (c != last_cell) {
      last_cell = c;
      ntargets = 0;
      const int ix = c % grid.nx, iy = c / grid.nx;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int jx = ix + dx, jy = iy + dy;
          if (jx < 0 || jy < 0 || jx >= grid.nx || jy >= grid.ny) continue;
          const int r = owner[jy * grid.nx + jx];
          if (r == rank || std::find(targets, targets + ntargets, r) != targets + ntargets) continue;
          targets[ntargets++] = r;
        }
    }
    for (int t = 0; t < ntargets; ++t) per_rank[targets[t]].push_back(static_cast<int>(i));
  }
  for (int r = 0; r < size; ++r) {
    send_counts_[r] = static_cast<int>(per_rank[r].size());
    send_displs_[r] = static_cast<int>(send_ids_.size());
    send_ids_.insert(send_ids_.end(), per_rank[r].begin(), per_rank[r].end());
  }
  MPI_Alltoall(send_counts_.data(), 1, MPI_INT, recv_counts_.data(), 1, MPI_INT, comm);
  for (int r = 0; r < size; ++r) {
    recv_displs_[r] = recv_total_;
    recv_total_ += recv_counts_[r];
  }
}

void HaloPlan::exchange(const void* send, void* recv, int ncomp, MPI_Datatype type) const {
  exchange_items(comm_, send_counts_, send_displs_, recv_counts_, recv_displs_, ncomp, send, recv, type);
}

void HaloPlan::update(std::vector<double>& field, std::size_t owned, int ncomp) const {
  field.resize((owned + ghost_count()) * ncomp);
  if (comm_ == MPI_COMM_NULL || send_counts_.size() <= 1) return;
  std::vector<double> buf(send_ids_.size() * ncomp);
  for (std::size_t k = 0; k < send_ids_.size(); ++k)
    for (int c = 0; c < ncomp; ++c) buf[k * ncomp + c] = field[static_cast<std::size_t>(send_ids_[k]) * ncomp + c];
  exchange(buf.data(), field.data() + owned * ncomp, ncomp, MPI_DOUBLE);
}

void HaloPlan::update(std::vector<std::int64_t>& field, std::size_t owned) const {
  field.resize(owned + ghost_count());
  if (comm_ == MPI_COMM_NULL || send_counts_.size() <= 1) return;
  std::vector<std::int64_t> buf(send_ids_.size());
  for (std::size_t k = 0; k < send_ids_.size(); ++k) buf[k] = field[send_ids_[k]];
  exchange(buf.data(), field.data() + owned, 1, MPI_INT64_T);
}

}  // namespace halfeti::parallel
