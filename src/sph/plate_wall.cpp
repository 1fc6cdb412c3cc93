// The plate's surface as a moving wall in the SPH sums (docs/coupling.md, section 12, "The plate in the SPH sums").
#include "halfeti/sph/plate_wall.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

#include "halfeti/core/error.hpp"
#include "halfeti/sph/neighbour_list.hpp"
#include "halfeti/sph/walls.hpp"

namespace halfeti::sph {

namespace {
// Index of the first point (from the start, or from the end when backwards) where the polyline turns by more
// than 45 degrees: the top corners of the plate's outline.
int corner(const PlateOutline& o, bool backwards) {
  const int n = static_cast<int>(o.size());
  for (int step = 1; step + 1 < n; ++step) {
    const int k = backwards ? n - 1 - step : step;
    const int a = backwards ? k + 1 : k - 1, b = backwards ? k - 1 : k + 1;
    const double ax = o.x[k] - o.x[a], ay = o.y[k] - o.y[a], bx = o.x[b] - o.x[k], by = o.y[b] - o.y[k];
    if (ax * bx + ay * by < std::sqrt(0.5) * std::hypot(ax, ay) * std::hypot(bx, by)) return k;
  }
  return -1;
}
}  // namespace

std::pair<int, int> outline_corners(const PlateOutline& o) {
  return {corner(o, false), corner(o, true)};
}

void PlateWall::offset_outline(const PlateOutline& o, double dx) {
  const int n = static_cast<int>(o.size());
  point_.resize(n);
  for (int k = 0; k < n; ++k) point_[k] = k;
  outline_ = o;
  // The corners: found on the first outline (the plate at rest, its top turning by 90 degrees) and kept, since
  // the surface's topology never changes (a strongly bent plate can turn by more than 45 degrees elsewhere).
  if (n != corner_points_) {
    std::tie(corner_right_, corner_left_) = outline_corners(o);
    corner_points_ = n;
    HALFETI_CHECK(corner_right_ > 0 && corner_left_ > corner_right_ && corner_right_ == n - 1 - corner_left_,
                  "the plate's outline must run up one face, across the top and down the other with as many "
                  "points on each face (corners at "
                      << corner_right_ << " and " << corner_left_ << " of " << n << ")");
  }
  right_end_ = corner_right_;
  left_start_ = corner_left_;
  const int c1 = right_end_, c2 = left_start_;
  if (offsets_.right == 0.0 && offsets_.left == 0.0 && offsets_.top == 0.0) return;
  // Outward unit normal of segment s (the tangent turned clockwise).
  auto normal = [&](int s) {
    const double tx = o.x[s + 1] - o.x[s], ty = o.y[s + 1] - o.y[s], l = std::hypot(tx, ty);
    return std::pair{ty / l, -tx / l};
  };
  // The faces move along their normals (a point's: the mean of its face's segments beside it).
  auto face_shift = [&](int k, int first_seg, int last_seg, double offset) {
    double nx = 0.0, ny = 0.0;
    for (int s : {k - 1, k})
      if (s >= first_seg && s <= last_seg) {
        const auto [sx, sy] = normal(s);
        nx += sx;
        ny += sy;
      }
    const double l = std::hypot(nx, ny);
    return std::pair{offset * nx / l, offset * ny / l};
  };
  for (int k = 0; k < n; ++k) {
    if (k > c1 && k < c2) continue;  // the top's inner points follow the corners (below)
    const auto [mx, my] =
        k <= c1 ? face_shift(k, 0, c1 - 1, offsets_.right) : face_shift(k, c2, n - 2, offsets_.left);
    outline_.x[k] = o.x[k] + mx;
    outline_.y[k] = o.y[k] + my;
  }
  // The top moves along the faces: each corner slides down its face by -offset (dropping the face points it
  // passes, as many on both faces so that they keep pairing up), or up along its last segment's direction.
  int drop = 0;
  double corner_x[2], corner_y[2];
  for (int side = 0; side < 2; ++side) {
    const int c = side == 0 ? c1 : c2, step = side == 0 ? -1 : 1;  // step: from the corner down the face
    double remaining = -offsets_.top, x = outline_.x[c], y = outline_.y[c];
    int k = c, passed = 0;
    if (remaining < 0.0) {  // raised top: extend the last segment
      const double tx = x - outline_.x[c + step], ty = y - outline_.y[c + step], l = std::hypot(tx, ty);
      x -= remaining * tx / l;
      y -= remaining * ty / l;
    }
    while (remaining > 0.0) {
      const int next = k + step;
      const double l = std::hypot(outline_.x[next] - x, outline_.y[next] - y);
      if (l > remaining + 0.05 * dx) {  // stop on this segment, leaving it at least dx/20 long
        x += remaining / l * (outline_.x[next] - x);
        y += remaining / l * (outline_.y[next] - y);
        break;
      }
      remaining -= l;
      x = outline_.x[next];
      y = outline_.y[next];
      k = next;
      ++passed;
      HALFETI_CHECK(passed + 2 < c1, "the plate is shorter than its lattice offset " << offsets_.top << " m");
    }
    drop = std::max(drop, passed);
    corner_x[side] = x;
    corner_y[side] = y;
  }
  // The top's points between the corners move with them, in proportion.
  const double sx0 = corner_x[0] - o.x[c1], sy0 = corner_y[0] - o.y[c1];
  const double sx1 = corner_x[1] - o.x[c2], sy1 = corner_y[1] - o.y[c2];
  for (int k = c1; k <= c2; ++k) {
    const double f = static_cast<double>(k - c1) / (c2 - c1);
    outline_.x[k] = o.x[k] + (1.0 - f) * sx0 + f * sx1;
    outline_.y[k] = o.y[k] + (1.0 - f) * sy0 + f * sy1;
  }
  if (drop == 0) return;
  PlateOutline cut;
  point_.clear();
  for (int k = 0; k < n; ++k) {
    if ((k >= c1 - drop && k < c1) || (k > c2 && k <= c2 + drop)) continue;
    for (auto [to, from] : {std::pair{&cut.x, &outline_.x},
                            {&cut.y, &outline_.y},
                            {&cut.vx, &outline_.vx},
                            {&cut.vy, &outline_.vy},
                            {&cut.ax, &outline_.ax},
                            {&cut.ay, &outline_.ay}})
      to->push_back((*from)[k]);
    point_.push_back(k);
  }
  outline_ = std::move(cut);
  right_end_ -= drop;
  left_start_ -= drop;
}

void PlateWall::set_wall_velocity(const PlateOutline& motion) {
  HALFETI_CHECK(static_cast<int>(motion.size()) == corner_points_,
                "the plate's motion has " << motion.size() << " points, its outline " << corner_points_);
  for (std::size_t j = 0; j < outline_.size(); ++j) {
    outline_.vx[j] = motion.vx[static_cast<std::size_t>(point_[j])];
    outline_.vy[j] = motion.vy[static_cast<std::size_t>(point_[j])];
  }
}

std::vector<Barrier> PlateWall::midline() const {
  std::vector<Barrier> out;
  for (int q = 0; q < fibres_; ++q) out.push_back({mid_x_[q], mid_y_[q], mid_x_[q + 1], mid_y_[q + 1]});
  return out;
}

void PlateWall::set_outline(const PlateOutline& true_outline, double dx, double support) {
  outline_ = PlateOutline{};
  if (true_outline.size() >= 2) offset_outline(true_outline, dx);
  const PlateOutline& o = outline_;
  support_ = support;
  gx_.clear();
  gy_.clear();
  gvol_.clear();
  gregion_.clear();
  gfibre_.clear();
  row_start_.clear();
  mid_x_.clear();
  mid_y_.clear();
  mid_box_.clear();
  fibres_ = 0;
  const int n = static_cast<int>(o.size());
  if (n < 2) return;
  fibres_ = right_end_;
  for (int k = 0; k <= fibres_; ++k) {  // the mid-line: the mean of the faces' paired points, base to top
    mid_x_.push_back(0.5 * (o.x[k] + o.x[n - 1 - k]));
    mid_y_.push_back(0.5 * (o.y[k] + o.y[n - 1 - k]));
  }
  for (int q = 0; q < fibres_; ++q)  // each mid-line segment's box (x0, y0, x1, y1)
    mid_box_.insert(mid_box_.end(), {std::min(mid_x_[q], mid_x_[q + 1]), std::min(mid_y_[q], mid_y_[q + 1]),
                                     std::max(mid_x_[q], mid_x_[q + 1]), std::max(mid_y_[q], mid_y_[q + 1])});
  // Arc length of every face point from its top corner, down each face.
  arc_.assign(n, 0.0);
  for (int k = right_end_ - 1; k >= 0; --k)
    arc_[k] = arc_[k + 1] + std::hypot(o.x[k + 1] - o.x[k], o.y[k + 1] - o.y[k]);
  for (int k = left_start_ + 1; k < n; ++k)
    arc_[k] = arc_[k - 1] + std::hypot(o.x[k] - o.x[k - 1], o.y[k] - o.y[k - 1]);
  double shortest = std::numeric_limits<double>::max();
  for (int k = 0; k < right_end_; ++k) shortest = std::min(shortest, arc_[k] - arc_[k + 1]);
  for (int k = left_start_; k + 1 < n; ++k) shortest = std::min(shortest, arc_[k + 1] - arc_[k]);
  // The point at arc length s down a face: its position, the outward normal and the right face's segment there.
  auto at = [&](bool right, double s, double& px, double& py, double& nx, double& ny, int& seg) {
    int k = right ? right_end_ - 1 : left_start_;  // segment k: points k, k + 1 of the outline
    if (right)
      while (k > 0 && arc_[k] < s) --k;
    else
      while (k + 2 < n && arc_[k + 1] < s) ++k;
    const double x0 = o.x[k], y0 = o.y[k], x1 = o.x[k + 1], y1 = o.y[k + 1], l = std::hypot(x1 - x0, y1 - y0);
    const double e = right ? (arc_[k] - s) / l : (s - arc_[k]) / l;  // along the outline's direction
    px = x0 + e * (x1 - x0);
    py = y0 + e * (y1 - y0);
    nx = (y1 - y0) / l;  // outward: the outline's tangent turned clockwise
    ny = -(x1 - x0) / l;
    seg = right ? k : n - 2 - k;
  };
  // Rows down the plate from the top corners, as the water lattice's rows: body ghosts across the thickness and band
  // ghosts (m + 1/2) dx beyond each face, each standing for one lattice cell. Each face is cut into the same number
  // of rows, about one spacing tall (the faces' mean length over dx), so that the rows reach the foot of both faces
  // however the plate bends (rows a fixed dx apart left a bent plate's foot without ghosts: docs/coupling.md,
  // section 17).
  const int bands = static_cast<int>(std::ceil(support / dx - 0.5)) + 1;
  const int rows = std::max(1, static_cast<int>(std::lround(0.5 * (arc_[0] + arc_[n - 1]) / dx)));
  row_height_[0] = arc_[0] / rows;      // the right face's
  row_height_[1] = arc_[n - 1] / rows;  // the left face's
  for (int j = 0; j < rows; ++j) {
    row_start_.push_back(static_cast<int>(gx_.size()));
    double rx, ry, nrx, nry, lx, ly, nlx, nly;
    int seg, unused;
    at(true, (j + 0.5) * row_height_[0], rx, ry, nrx, nry, seg);
    at(false, (j + 0.5) * row_height_[1], lx, ly, nlx, nly, unused);
    auto add = [&](double gx, double gy, double vol, Region region) {
      gx_.push_back(gx);
      gy_.push_back(gy);
      gvol_.push_back(vol);
      gregion_.push_back(region);
      gfibre_.push_back(seg);
    };
    const double width = std::hypot(rx - lx, ry - ly);
    const int nb = std::max(1, static_cast<int>(std::lround(width / dx)));
    const double height = 0.5 * (row_height_[0] + row_height_[1]);
    for (int m = 0; m < nb; ++m) {  // the solid, across its thickness
      const double f = (m + 0.5) / nb;
      add(lx + f * (rx - lx), ly + f * (ry - ly), width / nb * height, kBody);
    }
    for (int m = 0; m < bands; ++m) {  // the water lattice continued beyond each face
      add(rx + (m + 0.5) * dx * nrx, ry + (m + 0.5) * dx * nry, dx * row_height_[0], kRightBand);
      add(lx + (m + 0.5) * dx * nlx, ly + (m + 0.5) * dx * nly, dx * row_height_[1], kLeftBand);
    }
  }
  row_start_.push_back(static_cast<int>(gx_.size()));
  // Runs of 8 consecutive segments with their boxes, for the closest-point search.
  run_start_.clear();
  run_box_.clear();
  for (int s0 = 0; s0 < n - 1; s0 += 8) {
    const int s1 = std::min(s0 + 8, n - 1);
    run_start_.push_back(s0);
    double bx0 = o.x[s0], by0 = o.y[s0], bx1 = o.x[s0], by1 = o.y[s0];
    for (int k = s0; k <= s1; ++k) {
      bx0 = std::min(bx0, o.x[k]);
      bx1 = std::max(bx1, o.x[k]);
      by0 = std::min(by0, o.y[k]);
      by1 = std::max(by1, o.y[k]);
    }
    run_box_.insert(run_box_.end(), {bx0, by0, bx1, by1});
    box_ = s0 == 0 ? std::array<double, 4>{bx0, by0, bx1, by1}
                   : std::array<double, 4>{std::min(box_[0], bx0), std::min(box_[1], by0),
                                           std::max(box_[2], bx1), std::max(box_[3], by1)};
  }
  run_start_.push_back(n - 1);
  dx_ = dx;
  row_window_ = static_cast<int>(std::ceil(support / std::min(row_height_[0], row_height_[1]))) + 1;
  // Segments a particle's support can reach on either side of its own (segments are at least `shortest` long).
  fibre_window_ = static_cast<int>(std::ceil(support / shortest)) + 2;
}

bool PlateWall::hidden(double xi, double yi, double xg, double yg, int fibre) const {
  // The mid-line segments near the ghost's fibre (a segment between points within the support cannot reach
  // further along the plate than the fibre window); one whose box misses the pair's box cannot cross it, and the
  // box test skips most of the window.
  const int lo = std::max(0, fibre - fibre_window_), hi = std::min(fibres_, fibre + fibre_window_);
  const double x0 = std::min(xi, xg), x1 = std::max(xi, xg), y0 = std::min(yi, yg), y1 = std::max(yi, yg);
  for (int q = lo; q < hi; ++q) {
    const double* b = &mid_box_[4 * q];
    if (b[0] > x1 || b[2] < x0 || b[1] > y1 || b[3] < y0) continue;
    if (segments_cross(xi, yi, xg, yg, mid_x_[q], mid_y_[q], mid_x_[q + 1], mid_y_[q + 1])) return true;
  }
  return false;
}

void PlateWall::closest_point(double xi, double yi, double reach, int& best, double& best_d, double& best_g,
                              double& best_eta) const {
  // Closest point of the outline (eq. 20's projection, clamped); at a convex corner the tie goes to the face the
  // particle stands more clearly in front of (as the contact search). Runs whose box is farther than the best so
  // far (or than the reach) cannot hold it: skipping them gives the full scan's answer, ties included.
  const auto& o = outline_;
  // (Compared as squared distances: one square root at the end.)
  best = -1;
  double best_d2 = std::numeric_limits<double>::max();
  best_g = best_eta = 0.0;
  const double reach2 = reach * reach;
  for (std::size_t run = 0; run + 1 < run_start_.size(); ++run) {
    const double bx = std::max({run_box_[4 * run] - xi, 0.0, xi - run_box_[4 * run + 2]});
    const double by = std::max({run_box_[4 * run + 1] - yi, 0.0, yi - run_box_[4 * run + 3]});
    const double box_d2 = bx * bx + by * by;
    if (box_d2 >= reach2 || box_d2 > best_d2) continue;
    for (int s = run_start_[run]; s < run_start_[run + 1]; ++s) {
      const double dxs = o.x[s + 1] - o.x[s], dys = o.y[s + 1] - o.y[s], l2 = dxs * dxs + dys * dys;
      const double rx = xi - o.x[s], ry = yi - o.y[s];
      const double eta = std::clamp((rx * dxs + ry * dys) / l2, 0.0, 1.0);
      const double ux = rx - eta * dxs, uy = ry - eta * dys, d2 = ux * ux + uy * uy;
      const double g = (rx * dys - ry * dxs) / std::sqrt(l2);
      if (d2 < best_d2 || (d2 == best_d2 && g > best_g)) {
        best = s;
        best_d2 = d2;
        best_g = g;
        best_eta = eta;
      }
    }
  }
  best_d = best < 0 ? std::numeric_limits<double>::max() : std::sqrt(best_d2);
}

double PlateWall::normal_velocity(std::size_t a, const double* vx, const double* vy) const {
  // (u_i - u_w) . n with the wall's velocity at the particle's closest point
  const int i = particle_[a], s = seg_[a];
  const double eta = eta_[a];
  const double uwx = (1.0 - eta) * outline_.vx[s] + eta * outline_.vx[s + 1];
  const double uwy = (1.0 - eta) * outline_.vy[s] + eta * outline_.vy[s + 1];
  return (vx[i] - uwx) * nx_[a] + (vy[i] - uwy) * ny_[a];
}

void PlateWall::find_pairs(const double* x, const double* y, int n, const Kernel& kernel) {
  particle_.clear();
  start_.clear();
  ghost_.clear();
  ex_.clear();
  ey_.clear();
  f_.clear();
  nx_.clear();
  ny_.clear();
  eta_.clear();
  distance_.clear();
  px_.clear();
  py_.clear();
  seg_.clear();
  free_surface_.clear();
  start_.push_back(0);
  if (empty()) return;
  const auto& o = outline_;
  const double x0 = box_[0], y0 = box_[1], x1 = box_[2], y1 = box_[3];
  const double r = support_, r2max = r * r;
  const KernelEvaluator ke(kernel);
  for (int i = 0; i < n; ++i) {
    const double xi = x[i], yi = y[i];
    if (xi < x0 - r || xi > x1 + r || yi < y0 - r || yi > y1 + r) continue;
    int best;
    double best_d, best_g, best_eta;
    closest_point(xi, yi, r, best, best_d, best_g, best_eta);
    // Particles inside the plate are the contact's (eqs. 19-23), not the wall's. One on the surface is water: the
    // contact puts the particles it pushes out exactly there (docs/coupling.md, section 15), and without the
    // ghosts their half-empty support would push them straight back in.
    if (best < 0 || best_d >= r || best_g < 0.0) continue;
    const double cx = o.x[best] + best_eta * (o.x[best + 1] - o.x[best]);
    const double cy = o.y[best] + best_eta * (o.y[best + 1] - o.y[best]);
    // The particle's row: the arc length of its closest point below the top corners (0 on the top).
    const double tx = o.x[best + 1] - o.x[best], ty = o.y[best + 1] - o.y[best],
                 l = std::sqrt(tx * tx + ty * ty);
    // The wall normal at the particle: from its closest point to it (a face's normal in front of a face, radial
    // round a corner, so that it turns continuously); on the surface itself, the segment's outward normal.
    const bool on_surface = best_d <= 1e-9 * dx_;
    const double arc = best < right_end_     ? arc_[best] - best_eta * l
                       : best >= left_start_ ? arc_[best] + best_eta * l
                                             : 0.0;
    const double row_height = best < right_end_ ? row_height_[0] : row_height_[1];
    const int row = static_cast<int>(arc / row_height), rows = static_cast<int>(row_start_.size()) - 1;
    const std::size_t before = ghost_.size();
    const int lo = std::clamp(row - row_window_, 0, rows), hi = std::clamp(row + row_window_ + 1, 0, rows);
    for (int g = row_start_[lo]; g < row_start_[hi]; ++g) {
      const double ex = gx_[g] - xi, ey = gy_[g] - yi, rr2 = ex * ex + ey * ey;
      if (rr2 >= r2max || rr2 == 0.0) continue;
      // Band ghosts stand for water only where the plate hides the real water (the mid-line barrier's rule).
      if (gregion_[g] != kBody && !hidden(xi, yi, gx_[g], gy_[g], gfibre_[g])) continue;
      double w, f;
      ke(std::sqrt(rr2), w, f);
      ghost_.push_back(g);
      ex_.push_back(ex);
      ey_.push_back(ey);
      f_.push_back(f);
    }
    if (ghost_.size() == before) continue;
    particle_.push_back(i);
    start_.push_back(static_cast<int>(ghost_.size()));
    nx_.push_back(on_surface ? ty / l : (xi - cx) / best_d);
    ny_.push_back(on_surface ? -tx / l : (yi - cy) / best_d);
    seg_.push_back(best);
    eta_.push_back(best_eta);
    distance_.push_back(best_d);
    px_.push_back(xi);
    py_.push_back(yi);
  }
}

void PlateWall::set_free_surface(std::vector<unsigned char> marks) {
  HALFETI_CHECK(marks.size() == particle_.size(),
                "PlateWall::set_free_surface: one mark per particle with ghosts");
  free_surface_ = std::move(marks);
}

std::size_t PlateWall::free_surface_count() const {
  return static_cast<std::size_t>(std::count(free_surface_.begin(), free_surface_.end(), 1));
}

void PlateWall::momentum(const double* vx, const double* vy, const double* rho, const double* p,
                         const double* mass, const std::int64_t* gid, const PlateWallConstants& k, double* ax,
                         double* ay) {
  loads_.clear();
  const double viscosity = k.alpha * k.h * k.c0 * k.rho0;  // eq. 4
  const double eta2 = 0.01 * k.h * k.h;
  for (std::size_t a = 0; a < particle_.size(); ++a) {
    const int i = particle_[a], s = seg_[a];
    const double rhoi = rho[i], pi = p[i], inv_rhoi = 1.0 / rhoi, nx = nx_[a], ny = ny_[a], eta = eta_[a];
    // eq. 8 with the ghosts' velocity mirrored about the wall at the particle's closest point:
    // u_g - u_i = -2 ((u_i - u_w).n) n
    const double un = normal_velocity(a, vx, vy);
    const bool free_surface = marked(a);
    double sx = 0.0, sy = 0.0;
    for (int q = start_[a]; q < start_[a + 1]; ++q) {
      const int g = ghost_[q];
      const double ex = ex_[q], ey = ey_[q], f = f_[q];
      // Adami et al. (2012): pressure continued from the particle with the body force, not clamped at zero (as
      // the tank walls, docs/sph.md: a clamp tears particles in tension off the wall)
      double psum = pi + pi + rhoi * (k.body_x * ex + k.body_y * ey);
      // A particle at a free surface beside a face: pushes it, never pulls it (the gap behind it is the air's)
      if (free_surface) psum = std::max(psum, 0.0);
      // eq. 4 pressure term: -(1/rho_i) (p_i + p_g) V_g grad_i W, grad_i W = -F e
      double scalar = psum * gvol_[g] * f * inv_rhoi;
      const double du_dot_e = -2.0 * un * (nx * ex + ny * ey);
      scalar -= viscosity * du_dot_e / (ex * ex + ey * ey + eta2) * gvol_[g] * f * inv_rhoi;
      sx += scalar * ex;
      sy += scalar * ey;
      if (k.laminar_nu > 0.0) {
        // the laminar term (fluid_rates.cpp) with the same mirrored ghost velocity, u_i - u_g = 2 un n, and
        // m_g = rho_i V_g: 2 nu V_g F r^2 / (r^2 + eta^2) (u_i - u_g) (F < 0); the plate takes its reaction below
        const double r2 = ex * ex + ey * ey, lam = 2.0 * k.laminar_nu * gvol_[g] * f * r2 / (r2 + eta2);
        sx += 2.0 * lam * un * nx;
        sy += 2.0 * lam * un * ny;
      }
    }
    // The face's repulsion, as the tank walls' (fluid_rates.cpp) over a continuous wall (the Monaghan & Kos profile
    // along a wall sums to one): so that water reaching the plate's foot meets the same corner as at the tank's
    // corners. Without it the contact put every particle that reached a face exactly on it, and at the foot, where
    // the floor's repulsion holds the height, particles landed on one point and never parted (docs/coupling.md,
    // section 18). Within one spacing of a tank wall the push has no part into that wall (the rigid wall takes it,
    // as it takes the contact's corrections, Fluid::apply_corrections): in a gap narrower than a spacing, under a
    // hanging gate's free end, the two repulsions would otherwise squeeze a particle through the floor.
    const double push = monaghan_kos_repulsion(std::max(distance_[a], 1e-12 * k.dx), 0.0, 1.0, k.wall_range,
                                               k.wall_amplitude);
    double push_x = push * nx, push_y = push * ny;
    drop_part_into_walls(px_[a], py_[a], k.dx, k.tank_length, k.tank_height, k.lid, push_x, push_y);
    sx += push_x;
    sy += push_y;
    ax[i] += sx;
    ay[i] += sy;
    // The plate gets the opposite force at the particle's closest point, shared by the segment's two points as a
    // contact force (eq. 19's (1 - eta), eta).
    const double fx = -mass[i] * sx, fy = -mass[i] * sy;
    loads_.push_back({gid[i], point_[s], (1.0 - eta) * fx, (1.0 - eta) * fy});
    loads_.push_back({gid[i], point_[s + 1], eta * fx, eta * fy});
  }
}

void PlateWall::continuity(const double* vx, const double* vy, const double* rho, double* drho) const {
  for (std::size_t a = 0; a < particle_.size(); ++a) {
    const int i = particle_[a];
    const double nx = nx_[a], ny = ny_[a], un = normal_velocity(a, vx, vy);
    double d = 0.0;
    for (int q = start_[a]; q < start_[a + 1]; ++q) {
      const double n_dot_grad = -f_[q] * (nx * ex_[q] + ny * ey_[q]);
      d += 2.0 * rho[i] * gvol_[ghost_[q]] * un * n_dot_grad;  // eq. 3 first term over the ghosts
    }
    // A particle at a free surface leaving the face opens a gap (the air's), it does not expand
    if (marked(a)) d = std::max(d, 0.0);
    drho[i] += d;
  }
}

}  // namespace halfeti::sph
