#include "halfeti/sph/wall_friction.hpp"

#include <algorithm>
#include <cmath>

namespace halfeti::sph {

LawOfTheWall::LawOfTheWall(double kappa, double E) : kappa_(kappa), E_(E), y_plus_c_(11.0) {
  // fixed point of y+ = ln(E y+) / kappa (a contraction there: the derivative 1 / (kappa y+) is below 1)
  for (int i = 0; i < 200; ++i) y_plus_c_ = std::log(E_ * y_plus_c_) / kappa_;
}

double LawOfTheWall::friction_velocity(double u, double y, double nu) const {
  if (u <= 0.0) return 0.0;
  const double laminar = std::sqrt(nu * u / y);  // u+ = y+: u*^2 = nu u / y
  if (y * laminar / nu <= y_plus_c_) return laminar;
  // Log law: g(s) = s ln(E y s / nu) - kappa u = 0 for s = u*; g is increasing and convex beyond the sublayer and
  // negative at the laminar value, so Newton from there steps past the root once and then falls onto it.
  double s = laminar;
  for (int i = 0; i < 50; ++i) {
    const double l = std::log(E_ * y * s / nu), g = s * l - kappa_ * u, step = g / (l + 1.0);
    s -= step;
    if (std::abs(step) <= 1e-14 * s) break;
  }
  return s;
}

void add_wall_friction(const double* x, const double* y, const double* vx, const double* vy, int n,
                       const TankWalls& tank, double dx, double nu, double* ax, double* ay) {
  static const LawOfTheWall law;  // its crossover is solved once, not every step
  const double y_min = 0.5 * dx, inv_dx = 1.0 / dx;
  // A wall's shear on particle i: the wall at distance dist, its tangential velocity component ut along (tx, ty).
  const auto shear = [&](int i, double dist, double tx, double ty) {
    if (dist >= dx) return;
    const double ut = vx[i] * tx + vy[i] * ty, speed = std::abs(ut);
    if (speed == 0.0) return;
    const double us = law.friction_velocity(speed, std::max(dist, y_min), nu);
    const double a = -us * us * inv_dx * (ut > 0.0 ? 1.0 : -1.0);
    ax[i] += a * tx;
    ay[i] += a * ty;
  };
  for (int i = 0; i < n; ++i) {
    shear(i, y[i], 1.0, 0.0);                              // floor
    shear(i, x[i], 0.0, 1.0);                              // left wall
    shear(i, tank.length - x[i], 0.0, 1.0);                // right wall
    if (tank.lid) shear(i, tank.height - y[i], 1.0, 0.0);  // lid
  }
}

}  // namespace halfeti::sph
