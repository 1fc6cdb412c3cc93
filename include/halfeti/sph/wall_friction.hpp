// Friction of the tank's walls on the water that slides along them: a smooth-wall law of the wall (a wall
// function), for flows whose boundary layer the particles do not resolve (the dam break's surge front).
//
// The particles next to a wall slide freely over it in the paper's scheme (Monaghan & Kos repulsion and mirrored
// ghosts). With `fluid.wall_friction: log_law` the first layer of particles (centres within dx of a wall) also
// feels the wall's shear stress tau_w = rho u*^2, spread over the layer's thickness dx:
//   a = -(u*^2 / dx) u_t / |u_t|,
// where u_t is the particle's velocity along the wall (the walls are at rest in the tank's frame) and u* the
// friction velocity of the law of the wall at the particle's distance y from it (Pope, Turbulent Flows, 2000,
// sections 7.1.3-7.1.4): the viscous sublayer u+ = y+ below y+_c and the log law u+ = ln(E y+) / kappa above,
// kappa = 0.41, E = 9.8 (hydraulically smooth wall), u+ = u_t / u*, y+ = y u* / nu; y+_c = 11.53 is where the two
// meet, so that u* is continuous. No constant is fitted to a flow. y is taken no closer than dx/2, the wall
// repulsion's range (a particle stands for the dx x dx cell around it).
#pragma once

namespace halfeti::sph {

class LawOfTheWall {
 public:
  // kappa: von Karman constant; E: smooth-wall constant of the log law (B = ln(E) / kappa = 5.57)
  explicit LawOfTheWall(double kappa = 0.41, double E = 9.8);
  // y+ where u+ = y+ meets u+ = ln(E y+) / kappa
  double crossover() const { return y_plus_c_; }
  // Friction velocity u* [m/s] of a flow of speed u >= 0 at distance y > 0 from the wall, kinematic viscosity nu.
  double friction_velocity(double u, double y, double nu) const;

 private:
  double kappa_, E_, y_plus_c_;
};

// The walls of the tank [0, length] x [0, height] (the top only with a lid).
struct TankWalls {
  double length = 0.0, height = 0.0;
  bool lid = false;
};

// Adds the wall friction to the accelerations (ax, ay) of particles 0..n-1 (eq. 4's momentum balance, with the
// wall's shear as an external force on the first layer). Each particle's term is its own: no sums across particles.
void add_wall_friction(const double* x, const double* y, const double* vx, const double* vy, int n,
                       const TankWalls& tank, double dx, double nu, double* ax, double* ay);

}  // namespace halfeti::sph
