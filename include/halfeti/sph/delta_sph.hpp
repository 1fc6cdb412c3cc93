// The delta-SPH right-hand sides (section 2.1): renormalised density gradient (eqs. 6-7), continuity with density
// diffusion (eqs. 3, 5), momentum with artificial viscosity (eqs. 4, 8), Monaghan's (2000) tensile correction,
// the wall forces and XSPH (eq. 11). Pure loops over the pair lists; each owned particle's sum is independent
// of the others and runs in the pair list's canonical order.
#pragma once

#include <vector>

#include "halfeti/sph/neighbour_list.hpp"
#include "halfeti/sph/params.hpp"
#include "halfeti/sph/walls.hpp"

namespace halfeti::sph {

// Read-only view of the local particles (owned first, then ghosts).
struct ParticleView {
  const double *x, *y, *vx, *vy, *rho, *mass, *p;
  const double* volume;  // m / rho, precomputed once per step for owned and ghosts
  int n_owned, n_local;
};

// Determinant below which L_i (eq. 7) is not inverted and the plain SPH gradient is used (isolated particles,
// sprays, thin films: the moment matrix there is near singular).
inline constexpr double kRenormalisationMinDet = 1.0e-3;

// Renormalised density gradient <grad rho>^L_i of owned particles (eqs. 6-7); out has 2 entries per particle.
void density_gradient(const ParticleView& pv, const FluidPairList& pairs, std::vector<double>& grad_rho);

// The smallest eigenvalue of owned particle i's moment matrix B_i = sum_j V_j grad_i W_ij (x) r_ji over the water
// and the tank walls' ghosts (the inverse of eq. 7's L_i with the walls, as Marrone et al. 2010 count their fixed
// ghosts; the plate's ghosts are not in it): about 1 inside the water and beside a tank wall, about 0.5 at a free
// surface, near 0 for a particle with neither water nor a tank wall around it. Marrone et al. (2010, J. Sci.
// Comput. 45) take lambda <= kFreeSurfaceEigenvalue as the mark of a free-surface particle.
double moment_min_eigenvalue(const ParticleView& pv, const FluidPairList& pairs, const PairList& ghost_pairs,
                             const WallGhosts& ghosts, int i);
inline constexpr double kFreeSurfaceEigenvalue = 0.2;

struct Rates {
  std::vector<double> drho, ax, ay, xsph_x, xsph_y;
  double max_mu = 0.0;     // max_ij h |u_ji . r_ji| / (r^2 + eta^2), for the time step
  double max_accel = 0.0;  // max_i |a_i|
};

struct RateConstants {
  double rho0, c0, h, dx, delta, alpha, xsph;
  double laminar_nu;  // nu of the laminar viscous term (Morris et al. 1997); 0 = off
  bool tensile;
  double eps_neg, eps_pos, w_dx;  // tensile correction: epsilons and W(dx)
  double wall_amplitude;          // Monaghan & Kos A = wall_repulsion c0^2 / h
  double wall_range;              // distance over which the repulsion acts (the initial wall gap, dx / 2)
  bool wall_pressure;
  bool wall_no_slip;      // ghost velocity reversed instead of mirrored in the viscous term
  double body_x, body_y;  // inertial (-a_g) and gravity body force
};

// Momentum (eqs. 4, 8 + tensile correction + walls + body force) of the owned particles. grad_rho: the owned
// particles' renormalised density gradient (eqs. 6-7), from which the wall ghosts' pressure is continued along
// the wall (FluidParams::wall_ghost_pressure = kTaylor); empty: continued with the body force (kBodyForce).
void momentum_rates(const ParticleView& pv, const FluidPairList& pairs, const PairList& wall_pairs,
                    const WallParticles& walls, const PairList& ghost_pairs, const WallGhosts& ghosts,
                    const std::vector<double>& grad_rho, const RateConstants& k, Rates& out);

// Continuity with density diffusion (eqs. 3, 5) and the XSPH velocity (eq. 11). Called with the kicked
// velocities (symplectic Euler: the density sees the new velocity, which keeps the acoustic modes stable).
// grad_rho covers owned and ghost particles (halo-updated); empty for the standard scheme.
void continuity_rates(const ParticleView& pv, const FluidPairList& pairs, const PairList& ghost_pairs,
                      const WallGhosts& ghosts, const std::vector<double>& grad_rho, const RateConstants& k,
                      Rates& out);

}  // namespace halfeti::sph
