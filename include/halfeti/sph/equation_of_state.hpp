// Linear equation of state of the weakly compressible fluid (eq. 9) and the sound speed choice (eq. 10).
#pragma once

#include <algorithm>
#include <cmath>

namespace halfeti::sph {

// p = c0^2 (rho - rho0)  (eq. 9)
inline double pressure_from_density(double rho, double rho0, double c0) {
  return c0 * c0 * (rho - rho0);
}
inline double density_from_pressure(double p, double rho0, double c0) {
  return rho0 + p / (c0 * c0);
}

// Eq. 10 (Morris et al. 1997) with the viscous term dropped (inviscid with artificial viscosity):
// c0^2 = max(u_b^2, F l) / (drho / rho0), where u_b is the bulk velocity, F the body force and l the length scale.
inline double sound_speed_eq10(double bulk_velocity, double body_force, double length, double max_variation) {
  return std::sqrt(std::max(bulk_velocity * bulk_velocity, body_force * length) / max_variation);
}

}  // namespace halfeti::sph
