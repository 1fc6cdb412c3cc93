// Probes: collective, same value on every rank. Sums go through parallel::ordered_sum (in global-id order) so
// that they do not depend on how particles are split over ranks; max/min reductions are exact anyway.
#include <algorithm>
#include <cmath>
#include <limits>

#include "halfeti/core/error.hpp"
#include "halfeti/parallel/ordered_reduce.hpp"
#include "halfeti/sph/equation_of_state.hpp"
#include "halfeti/sph/fluid.hpp"

namespace halfeti::sph {

namespace {
// First-order (MLS) kernel interpolation at a point: with b = (1, x_i - x, y_i - y), solves
// [sum V W b b^T] c = sum V W b f for f = p, u, v and returns c_0 of each: exact for linear fields even where the
// kernel is cut by a wall or the surface. Falls back to the Shepard value sum V W f / sum V W when the moment
// matrix is singular (too few particles). All sums in global-id order.
std::array<double, 3> interpolate(MPI_Comm comm, const Kernel& k, double px, double py, int n,
                                  const std::vector<std::int64_t>& gid, const std::vector<double>& x,
                                  const std::vector<double>& y, const std::vector<double>& vx,
                                  const std::vector<double>& vy, const std::vector<double>& rho,
                                  const std::vector<double>& mass, double rho0, double c0) {
  std::vector<std::int64_t> g;
  std::vector<double> v;
  const double rc = k.support();
  for (int i = 0; i < n; ++i) {
    const double dx = x[i] - px, dy = y[i] - py;
    if (std::abs(dx) >= rc || std::abs(dy) >= rc) continue;  // out of reach, before the square root
    const double r = std::hypot(dx, dy);
    if (r >= rc) continue;
    const double vw = mass[i] / rho[i] * k.value(r);
    const double f[3] = {pressure_from_density(rho[i], rho0, c0), vx[i], vy[i]};
    g.push_back(gid[i]);
    // moments 1, dx, dy, dx dx, dx dy, dy dy, then (1, dx, dy) * f for each field
    v.insert(v.end(), {vw, vw * dx, vw * dy, vw * dx * dx, vw * dx * dy, vw * dy * dy});
    for (double fi : f) v.insert(v.end(), {vw * fi, vw * dx * fi, vw * dy * fi});
  }
  const auto s = parallel::ordered_sum(comm, g, v, 15);
  std::array<double, 3> out{0.0, 0.0, 0.0};
  if (s[0] <= 0.0) return out;
  const double m00 = s[0], m01 = s[1], m02 = s[2], m11 = s[3], m12 = s[4], m22 = s[5];
  // Cofactors of the symmetric 3x3 moment matrix (first row of its inverse is all that c_0 needs).
  const double c00 = m11 * m22 - m12 * m12, c01 = -(m01 * m22 - m12 * m02), c02 = m01 * m12 - m11 * m02;
  const double det = m00 * c00 + m01 * c01 + m02 * c02;
  const double scale = m00 * m11 * m22;
  for (int f = 0; f < 3; ++f) {
    const double b0 = s[6 + 3 * f], b1 = s[7 + 3 * f], b2 = s[8 + 3 * f];
    out[f] =
        (scale > 0.0 && std::abs(det) > 1e-3 * scale) ? (c00 * b0 + c01 * b1 + c02 * b2) / det : b0 / m00;
  }
  return out;
}
}  // namespace

double Fluid::pressure_at(double px, double py) const {
  return interpolate(comm_.get(), kernel_, px, py, n_owned_, gid_, x_, y_, vx_, vy_, rho_, mass_,
                     params_.density, c0_)[0];
}

std::array<double, 2> Fluid::velocity_at(double px, double py) const {
  const auto s = interpolate(comm_.get(), kernel_, px, py, n_owned_, gid_, x_, y_, vx_, vy_, rho_, mass_,
                             params_.density, c0_);
  return {s[1], s[2]};
}

double Fluid::free_surface_elevation(double px) const {
  // Highest fluid particle centre in the column |x_i - x| <= dx, plus half a spacing (the top of its cell).
  double top = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n_owned_; ++i)
    if (std::abs(x_[i] - px) <= dx_) top = std::max(top, y_[i]);
  MPI_Allreduce(MPI_IN_PLACE, &top, 1, MPI_DOUBLE, MPI_MAX, comm_.get());
  return std::isfinite(top) ? top + 0.5 * dx_ : 0.0;
}

double Fluid::surface_level(double px) const {
  // The bulk's free surface at x, robust to splashes: the water's kernel-interpolated volume fraction
  // c(y) = sum V_j W(|(x, y) - r_j|) (the tank's walls and floor as mirrors, so that c = 1 in the bulk next to them)
  // sampled upward from the floor every dx / 8; the level is the first place it falls below 1/2 (linearly
  // interpolated): a flat surface's, there, is its top particles' centres plus dx / 2, as the elevation probe's.
  // A jet or spray above the bulk, separated from it by a gap, is not counted. The particles within one support of
  // the vertical line are gathered on every rank and summed in global-id order (the same value on any ranks).
  const double rc = kernel_.support(), L = params_.tank_length;
  std::vector<double> mine;  // gid, x, y, volume
  for (int i = 0; i < n_owned_; ++i)
    if (std::abs(x_[i] - px) < rc || std::abs(-x_[i] - px) < rc || std::abs(2.0 * L - x_[i] - px) < rc)
      mine.insert(mine.end(), {static_cast<double>(gid_[i]), x_[i], y_[i], mass_[i] / rho_[i]});
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(size_), offsets(size_, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_.get());
  for (int r = 1; r < size_; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(offsets[size_ - 1] + counts[size_ - 1]);
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 comm_.get());
  const std::size_t n = all.size() / 4;
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return all[4 * a] < all[4 * b]; });
  // Each particle and its mirrors in the side walls and the floor.
  std::vector<double> sx, sy, sv;
  for (std::size_t k : order) {
    const double x = all[4 * k + 1], y = all[4 * k + 2], v = all[4 * k + 3];
    for (double mx : {x, -x, 2.0 * L - x})
      if (std::abs(mx - px) < rc)
        for (double my : {y, -y}) {
          sx.push_back(mx);
          sy.push_back(my);
          sv.push_back(v);
        }
  }
  const auto fraction = [&](double y) {
    double c = 0.0;
    for (std::size_t k = 0; k < sx.size(); ++k) {
      if (std::abs(sy[k] - y) >= rc) continue;  // out of reach: skipped before the square root (the same sum)
      const double r = std::hypot(sx[k] - px, sy[k] - y);
      if (r < rc) c += sv[k] * kernel_.value(r);
    }
    return c;
  };
  const double step = dx_ / 8.0;
  double y = 0.0, c = fraction(0.0);
  if (c < 0.5) return 0.0;  // no water at the floor here
  for (;;) {
    const double y2 = y + step, c2 = fraction(y2);
    if (c2 < 0.5) return y + step * (c - 0.5) / (c - c2);
    if (y2 > params_.tank_height + rc) return params_.tank_height;  // a column up to the open top
    y = y2;
    c = c2;
  }
}

double Fluid::front_position(double y_max) const {
  double front = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n_owned_; ++i)
    if (y_[i] <= y_max) front = std::max(front, x_[i]);
  MPI_Allreduce(MPI_IN_PLACE, &front, 1, MPI_DOUBLE, MPI_MAX, comm_.get());
  return front + 0.5 * dx_;
}

double Fluid::total_mass() const {
  std::vector<std::int64_t> g(gid_.begin(), gid_.begin() + n_owned_);
  std::vector<double> m(mass_.begin(), mass_.begin() + n_owned_);
  return parallel::ordered_sum(comm_.get(), g, m, 1)[0];
}

double Fluid::kinetic_energy() const {
  std::vector<std::int64_t> g(gid_.begin(), gid_.begin() + n_owned_);
  std::vector<double> e(n_owned_);
  for (int i = 0; i < n_owned_; ++i) e[i] = 0.5 * mass_[i] * (vx_[i] * vx_[i] + vy_[i] * vy_[i]);
  return parallel::ordered_sum(comm_.get(), g, e, 1)[0];
}

double Fluid::max_density_variation() const {
  double v = 0.0;
  for (int i = 0; i < n_owned_; ++i) v = std::max(v, std::abs(rho_[i] - params_.density) / params_.density);
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_DOUBLE, MPI_MAX, comm_.get());
  return v;
}

double Fluid::plate_free_surface_count() const {
  long long n = static_cast<long long>(plate_wall_.free_surface_count());
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LONG_LONG, MPI_SUM, comm_.get());
  return static_cast<double>(n);
}

double Fluid::floored_count() const {
  long long n = static_cast<long long>(floored_.size());
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LONG_LONG, MPI_SUM, comm_.get());
  return static_cast<double>(n);
}

double Fluid::min_spacing() const {
  double d = search_.min_distance();
  MPI_Allreduce(MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MIN, comm_.get());
  return d / dx_;
}

double Fluid::surface_mode(int n, int samples) const {
  if (n < 1 || samples < 2 * n)
    HALFETI_USER_ERROR("surface mode " << n << " with " << samples
                                       << " samples: needs n >= 1 and at least 2 n samples");
  const double L = params_.tank_length;
  double a = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double x = (k + 0.5) * L / samples;
    a += surface_level(x) * std::cos(n * M_PI * x / L);
  }
  return 2.0 * a / samples;
}

}  // namespace halfeti::sph
