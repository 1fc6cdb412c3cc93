#include "halfeti/sph/neighbour_list.hpp"

#include <algorithm>
#include <limits>

namespace halfeti::sph {

namespace {
// Squared distance from a point to a barrier segment.
double point_segment_distance2(double px, double py, const Barrier& b) {
  const double ex = b.xb - b.xa, ey = b.yb - b.ya, len2 = ex * ex + ey * ey;
  double s = len2 > 0.0 ? ((px - b.xa) * ex + (py - b.ya) * ey) / len2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  const double dx = px - (b.xa + s * ex), dy = py - (b.ya + s * ey);
  return dx * dx + dy * dy;
}

// Counting sort of items by cell; inside a cell, by key (global id / wall index).
template <class Key>
void bin(const parallel::CellGrid& g, const double* x, const double* y, int n, Key key,
         std::vector<int>& start, std::vector<int>& items, std::vector<int>& cell_of) {
  const int nc = g.cell_count();
  start.assign(nc + 1, 0);
  cell_of.resize(n);
  for (int i = 0; i < n; ++i) {
    cell_of[i] = g.cell_of(x[i], y[i]);
    ++start[cell_of[i] + 1];
  }
  for (int c = 0; c < nc; ++c) start[c + 1] += start[c];
  items.resize(n);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int i = 0; i < n; ++i) items[fill[cell_of[i]]++] = i;
  // Usually already in key order (owned particles are kept sorted by cell and id, and a cell's ghosts all come
  // from its one owner in that order), so the sort rarely runs.
  for (int c = 0; c < nc; ++c) {
    auto b = items.begin() + start[c], e = items.begin() + start[c + 1];
    const auto less = [&](int a, int bb) { return key(a) < key(bb); };
    if (e - b > 1 && !std::is_sorted(b, e, less)) std::sort(b, e, less);
  }
}

}  // namespace

void NeighbourSearch::set_fixed_points(int set, const std::vector<double>& px, const std::vector<double>& py,
                                       const std::vector<int>& internal) {
  FixedBins& b = fixed_[set];
  b.internal = internal;
  b.x = px;
  b.y = py;
  std::vector<int> cells;
  bin(
      grid_, b.x.data(), b.y.data(), static_cast<int>(b.x.size()), [](int i) { return i; }, b.start, b.items,
      cells);
  b.near.assign(grid_.cell_count(), 0);
  for (int c : cells) {
    const int cx = c % grid_.nx, cy = c / grid_.nx;
    for (int jy = std::max(cy - 1, 0); jy <= std::min(cy + 1, grid_.ny - 1); ++jy)
      for (int jx = std::max(cx - 1, 0); jx <= std::min(cx + 1, grid_.nx - 1); ++jx)
        b.near[jy * grid_.nx + jx] = 1;
  }
}

void NeighbourSearch::set_barriers(std::vector<Barrier> barriers) {
  barriers_ = std::move(barriers);
  const int cells = grid_.cell_count();
  barrier_start_.assign(cells + 1, 0);
  barrier_items_.clear();
  const double s = kernel_.support();
  const auto for_cells = [&](const Barrier& b, auto&& fn) {
    const int x0 = grid_.ix(std::min(b.xa, b.xb) - s), x1 = grid_.ix(std::max(b.xa, b.xb) + s);
    const int y0 = grid_.iy(std::min(b.ya, b.yb) - s), y1 = grid_.iy(std::max(b.ya, b.yb) + s);
    for (int cy = y0; cy <= y1; ++cy)
      for (int cx = x0; cx <= x1; ++cx) fn(cy * grid_.nx + cx);
  };
  for (const auto& b : barriers_) for_cells(b, [&](int c) { ++barrier_start_[c + 1]; });
  for (int c = 0; c < cells; ++c) barrier_start_[c + 1] += barrier_start_[c];
  barrier_items_.resize(static_cast<std::size_t>(barrier_start_[cells]));
  std::vector<int> fill(barrier_start_.begin(), barrier_start_.end() - 1);
  for (int k = 0; k < static_cast<int>(barriers_.size()); ++k)
    for_cells(barriers_[k], [&](int c) { barrier_items_[fill[c]++] = k; });
}

bool NeighbourSearch::crosses_any(const std::vector<int>& which, double xi, double yi, double xj,
                                  double yj) const {
  for (int k : which) {
    const Barrier& b = barriers_[k];
    if (segments_cross(xi, yi, xj, yj, b.xa, b.ya, b.xb, b.yb)) return true;
  }
  return false;
}

bool NeighbourSearch::crosses_barrier(double xi, double yi, double xj, double yj) const {
  const int c = grid_.cell_of(xi, yi);
  for (int k = barrier_start_[c]; k < barrier_start_[c + 1]; ++k) {
    const Barrier& b = barriers_[barrier_items_[k]];
    if (segments_cross(xi, yi, xj, yj, b.xa, b.ya, b.xb, b.yb)) return true;
  }
  return false;
}

void NeighbourSearch::fluid_pairs(const double* x, const double* y, const std::int64_t* gid, int n_owned,
                                  int n_local, FluidPairList& out) {
  bin(
      grid_, x, y, n_local, [gid](int i) { return gid[i]; }, cell_start_, cell_items_, cell_of_);
  // Positions in binned order, so that the three cells of a row are one contiguous range.
  bx_.resize(n_local);
  by_.resize(n_local);
  for (int k = 0; k < n_local; ++k) {
    bx_[k] = x[cell_items_[k]];
    by_[k] = y[cell_items_[k]];
  }
  // The pair arrays are sized once for about 24 pairs a particle (or what the last search needed), grown when a
  // particle needs more and cut to the count at the end.
  out.start.assign(n_owned + 1, 0);
  std::size_t n_pairs = 0, room = std::max(out.j.capacity(), static_cast<std::size_t>(n_owned) * 24);
  out.resize(room);
  const double rc2 = kernel_.support() * kernel_.support();
  const bool barriers = !barriers_.empty();
  double min_r2 = std::numeric_limits<double>::infinity();
  closest_particle_ = -1;
  for (int i = 0; i < n_owned; ++i) {
    const int c = cell_of_[i], cx = c % grid_.nx, cy = c / grid_.nx;
    const double xi = x[i], yi = y[i];
    // Only a barrier within the support of particle i can cross a pair of it (the crossing point lies on the pair,
    // closer to i than the pair's length): those of its cell's list, found once per particle (most of the tank
    // has none). The 1e-9 margin keeps every barrier a rounded crossing test could see.
    near_barriers_.clear();
    if (barriers)
      for (int k = barrier_start_[c]; k < barrier_start_[c + 1]; ++k) {
        const Barrier& b = barriers_[barrier_items_[k]];
        if (point_segment_distance2(xi, yi, b) < rc2 * (1.0 + 1e-9))
          near_barriers_.push_back(barrier_items_[k]);
      }
    const bool near_barrier = !near_barriers_.empty();
    const int x_lo = std::max(cx - 1, 0), x_hi = std::min(cx + 1, grid_.nx - 1);
    // Global cell order (rows ascending, and within a row the cells ascending), then global id inside a cell.
    // Three passes: the candidates within the support are kept without a branch on the distance (in a disordered
    // flow r < 2h is unpredictable, and mispredicted branches cost more than the stores), the kept pairs are
    // tested against the near barriers, and the kernel is evaluated for the survivors in one vectorised loop. The
    // order, and so every sum over the pairs, is unchanged.
    int kept = 0;
    for (int jy = std::max(cy - 1, 0); jy <= std::min(cy + 1, grid_.ny - 1); ++jy) {
      const int k_begin = cell_start_[jy * grid_.nx + x_lo], k_end = cell_start_[jy * grid_.nx + x_hi + 1];
      if (static_cast<int>(cand_.size()) < kept + (k_end - k_begin)) {
        cand_.resize(2 * static_cast<std::size_t>(kept + (k_end - k_begin)));
        cand_r2_.resize(cand_.size());
      }
      for (int k = k_begin; k < k_end; ++k) {
        const double dx = bx_[k] - xi, dy = by_[k] - yi, r2 = dx * dx + dy * dy;
        cand_[kept] = k;
        cand_r2_[kept] = r2;
        kept += (r2 < rc2) & (cell_items_[k] != i);
      }
    }
    if (near_barrier) {  // drop the pairs that cross a barrier, keeping the order
      int left = 0;
      for (int m = 0; m < kept; ++m) {
        const int j = cell_items_[cand_[m]];
        if (crosses_any(near_barriers_, xi, yi, x[j], y[j])) continue;
        cand_[left] = cand_[m];
        cand_r2_[left++] = cand_r2_[m];
      }
      kept = left;
    }
    if (n_pairs + kept > room) {
      room = 2 * (n_pairs + kept);
      out.resize(room);
    }
    const std::size_t base = n_pairs;
    n_pairs += kept;
    int* pj = out.j.data() + base;
    double min_i = std::numeric_limits<double>::infinity();
    for (int m = 0; m < kept; ++m) {
      pj[m] = cell_items_[cand_[m]];
      min_i = std::min(min_i, cand_r2_[m]);
    }
    if (min_i < min_r2) {
      min_r2 = min_i;
      closest_particle_ = i;
    }
    eval_.batch(cand_r2_.data(), kept, out.w.data() + base, out.f.data() + base);
    out.start[i + 1] = static_cast<int>(n_pairs);
  }
  out.resize(n_pairs);
  min_distance_ = std::sqrt(min_r2);
}

void NeighbourSearch::fixed_pairs(int set, const double* x, const double* y, int n_owned,
                                  PairList& out) const {
  const FixedBins& b = fixed_[set];
  out.clear();
  out.start.assign(n_owned + 1, 0);
  const double rc2 = kernel_.support() * kernel_.support();
  for (int i = 0; i < n_owned; ++i) {
    const int cx = grid_.ix(x[i]), cy = grid_.iy(y[i]);
    if (!b.near[cy * grid_.nx + cx]) {
      out.start[i + 1] = static_cast<int>(out.size());
      continue;
    }
    for (int jy = std::max(cy - 1, 0); jy <= std::min(cy + 1, grid_.ny - 1); ++jy)
      for (int jx = std::max(cx - 1, 0); jx <= std::min(cx + 1, grid_.nx - 1); ++jx) {
        const int cc = jy * grid_.nx + jx;
        for (int k = b.start[cc]; k < b.start[cc + 1]; ++k) {
          const int j = b.items[k];
          const double dx = b.x[j] - x[i], dy = b.y[j] - y[i], r2 = dx * dx + dy * dy;
          if (r2 >= rc2 || r2 == 0.0) continue;
          if (!b.internal.empty() && b.internal[j] >= 0) {
            const Barrier& w = barriers_[b.internal[j]];
            if (!segments_cross(x[i], y[i], b.x[j], b.y[j], w.xa, w.ya, w.xb, w.yb)) continue;
          } else if (!barriers_.empty() && crosses_barrier(x[i], y[i], b.x[j], b.y[j])) {
            continue;
          }
          out.push(j, dx, dy, std::sqrt(r2), eval_);
        }
      }
    out.start[i + 1] = static_cast<int>(out.size());
  }
}

}  // namespace halfeti::sph
