// Probes: collective, same value on every rank. Sums go through parallel::ordered_sum (in global-id order) so
// that they do not depend on how particles are split over ranks; max/min reductions are exact anyway.
#include <algorithm>
#include <cmath>
#include <limits>

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
    const double dx = x[i] - px, dy = y[i] - py, r = std::hypot(dx, dy);
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
    out[f] = (scale > 0.0 && std::abs(det) > 1e-3 * scale) ? (c00 * b0 + c01 * b1 + c02 * b2) / det : b0 / m00;
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

double Fluid::min_spacing() const {
  double d = search_.min_distance();
  MPI_Allreduce(MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MIN, comm_.get());
  return d / dx_;
}

}  // namespace halfeti::sph
