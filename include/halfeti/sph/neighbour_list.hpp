// Neighbour pairs of the owned fluid particles, in canonical order (global cell order, then global id) so that
// every per-particle sum is done in the same order whatever the rank count. Rebuilt every step from the particles
// binned in the cell grid (owned + ghosts). The water's own pairs (FluidPairList) store j, W and F = W'(r)/r, so
// that grad_i W_ij = -F r_ji with r_ji = r_j - r_i taken from the positions; the pairs with the walls' fixed points
// (PairList) store r_ji too (|r_ji|^2 is recomputed from r_ji: cheaper than storing it).
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "halfeti/parallel/cell_grid.hpp"
#include "halfeti/sph/kernel.hpp"

namespace halfeti::sph {

// A segment that neighbour pairs may not cross (internal walls, later the structure's surface).
struct Barrier {
  double xa, ya, xb, yb;
};

// Whether segment p1-p2 properly crosses segment q1-q2 (touching at an end point does not count).
inline bool segments_cross(double p1x, double p1y, double p2x, double p2y, double q1x, double q1y, double q2x,
                           double q2y) {
  auto orient = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  const double d1 = orient(q1x, q1y, q2x, q2y, p1x, p1y), d2 = orient(q1x, q1y, q2x, q2y, p2x, p2y);
  const double d3 = orient(p1x, p1y, p2x, p2y, q1x, q1y), d4 = orient(p1x, p1y, p2x, p2y, q2x, q2y);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// The segments of a polyline given by its points (x0, y0, x1, y1, ...), e.g. the structure's surface.
inline std::vector<Barrier> barriers_from_polyline(const std::vector<double>& xy) {
  std::vector<Barrier> out;
  for (std::size_t k = 0; k + 3 < xy.size(); k += 2) out.push_back({xy[k], xy[k + 1], xy[k + 2], xy[k + 3]});
  return out;
}

// Leaves new elements of a std::vector uninitialised on resize (the pair search writes every one it adds, and
// zero-filling them first would cost a pass of stores per particle).
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using PairArray = std::vector<T, UninitialisedAllocator<T>>;

// Pairs of the owned particles with fixed points (wall particles, wall ghosts): j indexes the fixed points, and
// each pair stores the separation r_j - r_i.
struct PairList {
  std::vector<int> start;  // pairs of owned particle i are [start[i], start[i+1])
  PairArray<int> j;
  PairArray<double> ex, ey, w, f;
  void clear() {
    j.clear();
    ex.clear();
    ey.clear();
    w.clear();
    f.clear();
  }
  void push(int jj, double dx, double dy, double rr, const KernelEvaluator& k) {
    double ww, ff;
    k(rr, ww, ff);
    j.push_back(jj);
    ex.push_back(dx);
    ey.push_back(dy);
    w.push_back(ww);
    f.push_back(ff);
  }
  std::size_t size() const { return j.size(); }
  // No pairs for n particles (e.g. a scene without walls).
  static PairList none(int n) {
    PairList p;
    p.start.assign(n + 1, 0);
    return p;
  }
};

// The water's own pairs: j indexes the local particles (owned and halo). The separation r_ji = r_j - r_i is not
// stored: a sum over the pairs takes it from the positions, x[j] - x[i], which do not move between the search and
// the step's last sum over its pairs, so it is the value the search measured, bit for bit. Storing it cost 16 of
// the 36 bytes of a pair, written by the search and read by the step's three sums (the renormalised gradient,
// momentum, continuity): without it the water's step is 3-8 % shorter and needs a third less memory (docs/sph.md,
// "Speed").
struct FluidPairList {
  std::vector<int> start;  // pairs of owned particle i are [start[i], start[i+1])
  PairArray<int> j;
  PairArray<double> w, f;
  // n pairs; new ones are left for the caller to write (no zero fill).
  void resize(std::size_t n) {
    j.resize(n);
    w.resize(n);
    f.resize(n);
  }
  std::size_t size() const { return j.size(); }
};

// Drives a per-pair functor over the neighbours of particle i: fn(j, pair index). Physics never walks cells.
template <class Pairs, class Fn>
inline void for_each_neighbour(const Pairs& pairs, int i, Fn&& fn) {
  for (int k = pairs.start[i]; k < pairs.start[i + 1]; ++k) fn(pairs.j[k], k);
}

class NeighbourSearch {
 public:
  NeighbourSearch(const parallel::CellGrid& grid, const Kernel& kernel)
      : grid_(grid), kernel_(kernel), eval_(kernel) {}

  // Binds fixed points (set 0: wall particles, set 1: wall ghosts), searched by wall_pairs(); their index order
  // is canonical.
  // For set 1, `internal[g]` >= 0 names the barrier a ghost stands behind: it is seen only across that barrier;
  // other fixed points are never seen across a barrier.
  void set_fixed_points(int set, const std::vector<double>& px, const std::vector<double>& py,
                        const std::vector<int>& internal = {});
  // Barriers are indexed by cell: a pair can only cross a barrier that comes within one support of particle i,
  // so each cell lists the barriers whose box, grown by the support, overlaps it (the plate's outline changes
  // every step; indexing it costs far less than testing every pair against every segment).
  void set_barriers(std::vector<Barrier> barriers);
  const std::vector<Barrier>& barriers() const { return barriers_; }

  // Fluid pairs for owned particles [0, n_owned) among all local particles [0, n_local).
  void fluid_pairs(const double* x, const double* y, const std::int64_t* gid, int n_owned, int n_local,
                   FluidPairList& out);
  // Fixed points of a set within the support of each owned particle (pairs across barriers are dropped).
  void fixed_pairs(int set, const double* x, const double* y, int n_owned, PairList& out) const;

  // Minimum pair distance found by the last fluid_pairs() (for the spacing-collapse monitor), and the first owned
  // particle with a neighbour at that distance (-1 if it found no pair).
  double min_distance() const { return min_distance_; }
  int closest_particle() const { return closest_particle_; }

 private:
  bool crosses_barrier(double xi, double yi, double xj, double yj) const;
  bool crosses_any(const std::vector<int>& which, double xi, double yi, double xj, double yj) const;

  parallel::CellGrid grid_;
  Kernel kernel_;
  KernelEvaluator eval_;
  std::vector<int> cell_start_, cell_items_, cell_of_;  // local particles binned by cell, then gid
  std::vector<double> bx_, by_;                         // their positions in binned order
  struct FixedBins {
    std::vector<int> start, items;
    std::vector<double> x, y;
    std::vector<char> near;  // cell has fixed points in its 3x3 neighbourhood
    std::vector<int> internal;
  };
  FixedBins fixed_[2];
  std::vector<int> barrier_start_, barrier_items_;  // per cell: indices into barriers_ (CSR)
  std::vector<int> near_barriers_;  // scratch of fluid_pairs: the barriers within the support of one particle
  std::vector<int> cand_;           // scratch of fluid_pairs: one particle's candidates within the support
  std::vector<double> cand_r2_;     // and their squared distances
  std::vector<Barrier> barriers_;
  double min_distance_ = 0.0;
  int closest_particle_ = -1;
};

}  // namespace halfeti::sph
