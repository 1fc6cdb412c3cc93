#include "halfeti/parallel/halo_plan.hpp"

#include <algorithm>

namespace halfeti::parallel {

std::vector<int> neighbour_ranks(const CellGrid& grid, const std::vector<int>& owner, int rank) {
  std::vector<int> out;
  for (int c = 0; c < grid.cell_count(); ++c) {
    if (owner[c] != rank) continue;
    grid.for_each_neighbour(c, [&](int j) {
      if (owner[j] != rank && std::find(out.begin(), out.end(), owner[j]) == out.end())
        out.push_back(owner[j]);
    });
  }
  std::sort(out.begin(), out.end());
  return out;
}

HaloPlan::HaloPlan(MPI_Comm comm, const CellGrid& grid, const std::vector<int>& owner,
                   const std::vector<int>& cells)
    : HaloPlan(comm, grid, owner, cells, [&] {
        int rank = 0;
        MPI_Comm_rank(comm, &rank);
        return neighbour_ranks(grid, owner, rank);
      }()) {}

HaloPlan::HaloPlan(MPI_Comm comm, const CellGrid& grid, const std::vector<int>& owner,
                   const std::vector<int>& cells, const std::vector<int>& peers, Traffic* traffic) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (size == 1) return;
  single_ = false;

  // Ranks that see each cell's particles as ghosts: the owners of the 8 surrounding cells, except the cell's own
  // (each one of `peers`). Computed per occupied cell once, then applied to its particles.
  std::vector<std::vector<int>> per_peer(peers.size());
  int last_cell = -1;
  int targets[8];
  int ntargets = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int c = cells[i];
    if (c != last_cell) {
      last_cell = c;
      ntargets = 0;
      grid.for_each_neighbour(c, [&](int j) {
        const int r = owner[j];
        if (r == rank) return;
        const int k = static_cast<int>(std::lower_bound(peers.begin(), peers.end(), r) - peers.begin());
        if (std::find(targets, targets + ntargets, k) == targets + ntargets) targets[ntargets++] = k;
      });
    }
    for (int t = 0; t < ntargets; ++t) per_peer[targets[t]].push_back(static_cast<int>(i));
  }
  std::vector<int> counts(peers.size());
  for (std::size_t k = 0; k < peers.size(); ++k) {  // peers are in increasing rank
    counts[k] = static_cast<int>(per_peer[k].size());
    send_ids_.insert(send_ids_.end(), per_peer[k].begin(), per_peer[k].end());
  }
  plan_ = CommPlan::with_peers(comm, peers, counts, 0, traffic);
}

void HaloPlan::update(std::vector<double>& field, std::size_t owned, int ncomp) const {
  field.resize((owned + ghost_count()) * ncomp);
  if (single_) return;
  std::vector<double> buf(send_ids_.size() * ncomp);
  for (std::size_t k = 0; k < send_ids_.size(); ++k)
    for (int c = 0; c < ncomp; ++c)
      buf[k * ncomp + c] = field[static_cast<std::size_t>(send_ids_[k]) * ncomp + c];
  plan_.exchange(buf.data(), field.data() + owned * ncomp, ncomp, MPI_DOUBLE);
}

void HaloPlan::update(std::vector<std::int64_t>& field, std::size_t owned) const {
  field.resize(owned + ghost_count());
  if (single_) return;
  std::vector<std::int64_t> buf(send_ids_.size());
  for (std::size_t k = 0; k < send_ids_.size(); ++k) buf[k] = field[send_ids_[k]];
  plan_.exchange(buf.data(), field.data() + owned, 1, MPI_INT64_T);
}

void HaloPlan::update(std::initializer_list<std::vector<double>*> fields, std::size_t owned) const {
  const std::size_t ghosts = ghost_count(), nf = fields.size();
  for (auto* f : fields) f->resize(owned + ghosts);
  if (single_) return;
  std::vector<double> buf(send_ids_.size() * nf), recv(ghosts * nf);
  for (std::size_t k = 0; k < send_ids_.size(); ++k) {
    std::size_t c = k * nf;
    for (const auto* f : fields) buf[c++] = (*f)[send_ids_[k]];
  }
  plan_.exchange(buf.data(), recv.data(), static_cast<int>(nf), MPI_DOUBLE);
  for (std::size_t g = 0; g < ghosts; ++g) {
    std::size_t c = g * nf;
    for (auto* f : fields) (*f)[owned + g] = recv[c++];
  }
}

}  // namespace halfeti::parallel
