// Parameters of the fluid part as plain structs (the application maps scene keys onto them). SI units.
#pragma once

#include <string>
#include <vector>

#include "halfeti/sph/kernel.hpp"

namespace halfeti::sph {

// Continuation of the pressure onto the wall ghosts (see FluidParams::wall_ghost_pressure).
enum class WallGhostPressure { kTaylor, kBodyForce };

enum class Scheme { kDeltaSph, kStandard };  // standard = no density diffusion (delta term off)

// Shear of the tank's walls on the water beside them: none (free slip, as the paper's walls) or the smooth-wall
// law of the wall on the first particle layer (wall_friction.hpp).
enum class WallFriction { kNone, kLogLaw };

// A rectangle filled with still water on a square lattice of spacing dx; its top is the free surface used for the
// hydrostatic initial density. `surface_amplitude` != 0 shapes the top as y1 + A cos(pi (x - x0_tank) / L)
// (the first sloshing mode of the tank).
struct WaterBlock {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  double surface_amplitude = 0.0;
};

// A rectangle the water leaves empty (where the plate stands): lattice points inside it are not laid.
struct Exclusion {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

// A rigid internal wall: a line of repulsive particles between two end points that pushes on both sides; fluid
// pairs across it do not interact. Water-block lattice points closer than dx/2 to it are left out.
struct InternalWall {
  double xa = 0.0, ya = 0.0, xb = 0.0, yb = 0.0;
};

struct FluidParams {
  // Geometry: tank [0, tank_length] x [0, tank_height]; walls at x = 0, x = L, y = 0 and optionally y = H.
  double tank_length = 0.30;
  double tank_height = 0.40;
  bool lid = false;
  std::vector<WaterBlock> water;
  std::vector<InternalWall> internal_walls;
  std::vector<Exclusion> exclusions;

  // Discretisation
  double spacing = 0.0015;  // dx [m]
  double h_over_dx = 1.33;  // h = 1.33 dx, support 2h
  KernelKind kernel = KernelKind::kCubicSpline;
  double wall_spacing_ratio = 0.5;  // boundary particle spacing / dx

  // Fluid
  double density = 1000.0;                // rho0 [kg/m^3]
  double sound_speed = 0.0;               // c0 [m/s]; 0 = eq. 10 from depth and the peak body force
  double max_density_variation = 0.01;    // drho/rho0 for eq. 10 and the health warning
  double gravity = 9.81;                  // [m/s^2], acts towards -y
  double peak_ground_acceleration = 0.0;  // [m/s^2], only for the automatic c0

  // delta-SPH
  Scheme scheme = Scheme::kDeltaSph;
  double delta = 0.1;   // density diffusion (eq. 3)
  double alpha = 0.02;  // artificial viscosity (eq. 4, 8)
  // Laminar viscous term (Morris et al. 1997 in Lo & Shao's 2003 form, docs/sph.md "Laminar viscosity"): nu
  // [m^2/s] of a Newtonian fluid, the same at every dx (eq. 8's viscosity scales with h); 0 = off
  double laminar_viscosity = 0.0;
  double xsph = 0.05;              // XSPH epsilon (eq. 11); 0 turns it off
  bool tensile_correction = true;  // Monaghan (2000)
  double tensile_epsilon_negative = 0.2;
  double tensile_epsilon_positive = 0.01;
  // Every particle the water has left (the smallest eigenvalue of its moment matrix over the water at most
  // kFreeSurfaceEigenvalue, Marrone et al. 2010) is raised to rho0 when below it, the atmosphere's pressure, at
  // each force evaluation (docs/sph.md, "Separated particles"); off: it keeps the tension it left the water with.
  bool free_surface_floor = false;

  // Walls (Monaghan & Kos 1999 plus the wall's pressure, see docs/sph.md)
  double wall_repulsion = 0.01;  // A = wall_repulsion * c0^2 / h
  bool wall_pressure = true;     // wall ghosts: pressure and velocity of the fluid behind the wall
  bool wall_no_slip = false;     // viscous term sees the walls as no-slip (default free slip)
  WallFriction wall_friction =
      WallFriction::kNone;              // the walls' shear on the first layer (wall_friction.hpp)
  double kinematic_viscosity = 1.0e-6;  // nu [m^2/s] of the law of the wall (water at 20 C)
  // How the wall ghosts' pressure is continued from the particle that sees them (docs/sph.md "Walls"):
  // kTaylor: p_g = p_i + rho_i (b.n)(n.r_gi) + (grad p_i.t)(t.r_gi), the wall condition across the wall and the
  // particle's own pressure gradient (eqs. 6, 9) along it; kBodyForce: p_g = p_i + rho_i b.r_gi (Adami et al.
  // 2012), which holds up films on vertical walls (kept for comparison).
  WallGhostPressure wall_ghost_pressure = WallGhostPressure::kTaylor;

  // Time step
  double cfl = 0.2;
  double max_dt = 1.0e-3;  // [s]
  double min_dt = 1.0e-9;  // [s]; below it the run stops (health)

  // Distribution
  double rebalance_threshold = 1.15;  // rebalance when max/target particles per rank exceeds it
  double first_rank_share = 1.0;      // rank 0's particles / another rank's (it also solves the plate)
  int rebalance_interval = 50;        // steps between imbalance checks

  // Health
  bool density_variation_fatal = false;
  double spacing_collapse_fraction = 0.2;  // warn when a pair comes closer than this * dx
};

}  // namespace halfeti::sph
