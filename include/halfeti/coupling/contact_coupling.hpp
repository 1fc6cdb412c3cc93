// One coupled step of water and plate through contact (DESIGN.md "One time step", steps 3-5): the interface
// search on every rank, the gather to the structure's rank, Newton on eq. 21 with the plate, and the
// hand-back of the corrections to the owning ranks. The application drives it between the fluid's prediction
// and its finish:
//
//   fluid.compute_forces(); fluid.<predict>();                      // positions at t + dt without contact
//   coupling.step(t, dt, view_of(fluid), corrections);               // collective over `world`
//   fluid.<apply corrections>; fluid.set_barriers(coupling.outline());
//
// The plate solver lives on the root rank only (PlateSolver runs on one rank); other ranks pass nullptr.
#pragma once

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "halfeti/core/communicator.hpp"
#include "halfeti/core/nodal_element.hpp"
#include "halfeti/core/timers.hpp"
#include "halfeti/coupling/contact_constraint.hpp"
#include "halfeti/coupling/contact_kinematics.hpp"
#include "halfeti/coupling/contact_system.hpp"
#include "halfeti/coupling/interface_exchange.hpp"
#include "halfeti/coupling/interface_quasi_newton.hpp"
#include "halfeti/coupling/ssosd.hpp"
#include "halfeti/sph/neighbour_list.hpp"
#include "halfeti/sph/plate_wall.hpp"
#include "halfeti/structure/plate_solver.hpp"

namespace halfeti::coupling {

// How the contact changes an invader's velocity (docs/coupling.md):
//   kAcceleration: dv = C dt / m, the constant acceleration Delta C = C / m of eq. 4 held over the step, the
//                  Newmark (beta 1/2, gamma 1) partner of the 2 / dt^2 mass participation: dv = 2 dx / dt;
//   kDisplacement: dv = dx / dt, the velocity the fluid's own drift x += dt v would need for the same dx.
//   kNormalStop:   dv = -min(0, (v - v_s) . n) n: the particle's approach to the surface (velocity v_s of its contact
//                  point) is stopped and nothing more; the relocation (contact + SSOSD, eqs. 21-22) moves it
//                  without turning into velocity (docs/coupling.md: dx / dt of an SSOSD shift reached 3 m/s).
enum class VelocityUpdate { kAcceleration, kDisplacement, kNormalStop };

struct CouplingParameters {
  ContactConstraint constraint = ContactConstraint::kTied;  // scene: coupling.constraint: tied | normal
  VelocityUpdate velocity_update = VelocityUpdate::kAcceleration;  // scene: coupling.velocity_update
  // Mass participation factor p in p m / dt^2 (scene: coupling.mass_participation): 1 = kick_drift (the fluid's
  // symplectic-Euler step: an impulse J moves a particle by dt J / m, so dv = C dt / m = dx / dt and the contact
  // is inelastic), 2 = constant_acceleration (the paper's 2/dt^2: dv = 2 dx / dt, an elastic bounce).
  double mass_participation = 1.0;
  ContactSolver solver = ContactSolver::kCondensed;  // scene: coupling.solver: condensed | saddle_point
  bool unilateral = true;  // scene: coupling.unilateral: release invaders the solve would pull (C . n < 0)
  // scene: coupling.plate_wall: the plate's faces act on the water in the SPH sums (wall ghosts, docs/coupling.md);
  // false = the paper's form, the water feels the plate through the contact of eq. 21 only.
  bool plate_wall = true;
  // scene: coupling.plate_wall_velocity: the ghosts move with the face (its mean velocity over the last step) in
  // eqs. 3 and 8; false (default): the faces' ghosts are at rest, the plate pushes the water by their positions and
  // the contact. The moving-face feedback grew into a plate-water oscillation until the interface added mass
  // (added_mass_layer, docs/coupling.md section 13); the paper scenes run with true.
  bool plate_wall_velocity = false;
  // scene: coupling.plate_wall_free_surface: a particle beside a face with the water around it gone (Marrone et al.
  // 2010's free-surface mark) is held at the atmosphere's pressure or above; it pushes the face and is pushed by
  // it, but neither pulls the other, and it does not expand as it leaves the face (docs/coupling.md, section 21);
  // true by default (as the scene's key); false: every particle's ghosts continue its pressure, tension included.
  bool plate_wall_free_surface = true;
  // scene: coupling.plate_wall_exchange (docs/coupling.md, sections 12 and 16):
  //   kExtrapolated (default): explicit; the plate gets the water's load extrapolated to mid-step, 1.5 F_n - 0.5
  //                 F_n-1, and the water the face's velocity extrapolated to mid-step, 2 v_n-1/2 - v_n-3/2;
  //   kLagged:      explicit; F_n and v_n-1/2 as computed;
  //   kImplicit:    converged within the step: the plate is solved under the water's load at the step's end,
  //                 F_n+1, which the water computes with the plate so moved (its density with the faces' motion over
  //                 the step), iterated to `implicit.tolerance` by interface quasi-Newton.
  enum class PlateWallExchange { kExtrapolated, kLagged, kImplicit };
  PlateWallExchange plate_wall_exchange = PlateWallExchange::kExtrapolated;
  bool implicit_exchange() const { return plate_wall_exchange == PlateWallExchange::kImplicit; }
  struct ImplicitExchange {
    int max_iterations =
        20;  // scene: coupling.implicit.max_iterations, evaluations of the water's load a step
    double tolerance =
        1e-3;  // scene: coupling.implicit.tolerance, ||F_out - F_in|| / ||F_out|| over the surface
    InterfaceQuasiNewtonOptions accelerator;  // scene: coupling.implicit.{acceleration, relaxation}
  } implicit;
  // scene: coupling.added_mass: the water's mass the plate's faces carry in the plate's step, normal to the face,
  // on the step's change of velocity (docs/coupling.md, sections 13 and 15):
  //   kAcoustic: rho0 c0 dt per face area, the water a pressure wave reaches within the step: the face's change of
  //              normal velocity dv meets the water's acoustic impedance, dp = rho0 c0 dv (a piston's response in a
  //              compressible fluid), within the implicit step instead of one step later through the ghosts;
  //   kLayer:    rho0 * added_mass_layer * dx (the former, chosen depth);
  //   kNone:     the plate-water exchange fully explicit.
  enum class AddedMass { kAcoustic, kLayer, kNone };
  AddedMass added_mass_kind = AddedMass::kAcoustic;
  double added_mass_layer = 0.25;  // scene: coupling.added_mass_layer, in particle spacings (kLayer)
  double density = 1000.0;         // kg/m^3, the water's rho0, set by the application
  double sound_speed = 0.0;        // m/s, the water's c0, set by the application
  double spacing = 0.0;            // m, the water's dx, set by the application
  // kg/m^2 per face area over a step of dt.
  double added_mass_per_area(double dt) const {
    switch (added_mass_kind) {
      case AddedMass::kAcoustic:
        return density * sound_speed * dt;
      case AddedMass::kLayer:
        return density * added_mass_layer * spacing;
      case AddedMass::kNone:
        break;
    }
    return 0.0;
  }
  SsosdParameters ssosd;           // scene: coupling.ssosd.{enabled,layer_ratio,velocity_floor}
  double inside_tolerance = 1e-6;  // m, > 0: an invader ending deeper than this past the surface is an error
  std::string options_prefix = "structure_contact_";  // PETSc options prefix of the contact KSP
  bool trace = false;  // not a scene key: `halfeti run --trace coupling` (a line per invader on stderr)
};

void validate(const CouplingParameters& p);  // UserError naming coupling.<key>

struct CouplingStepReport {
  int invaders = 0;           // particles in the contact solve this step (all ranks)
  int newton_iterations = 0;  // of the coupled Newton (or of the plate alone when there were no invaders)
  double layer = 0.0;         // m, SSOSD layer thickness L used (eq. 23), 0 without SSOSD
  double u_max = 0.0;         // m/s, max particle speed (all ranks) that set L
  double force_x = 0.0,
         force_y = 0.0;    // N/m, total contact force on the particles (the plate gets the opposite)
  double max_force = 0.0;  // N/m, largest |C| of one invader
  int released = 0;        // invaders released by the unilateral active set (they keep their predicted state)
};

// The converged exchange's verdict on one evaluation of the water's load (every rank the same).
struct ExchangeIterate {
  int iteration = 0;       // 0 for the step's first evaluation
  double residual = 0.0;   // ||F_out - F_in|| / ||F_out|| over the surface points
  bool converged = false;  // residual <= implicit.tolerance
  bool accepted =
      false;  // the step is taken with this iterate (converged, or the best of a stalled iteration)
};

// The water's force on the plate over the last step, by where and how it acts (docs/coupling.md, section 15): the
// plate-wall ghosts' load (what the plate is handed at the step's start, before any extrapolation), split into the
// parts that push into a face and those that pull it outwards (suction: the ghosts continue a particle's pressure,
// so water in tension beside a face pulls it), and the contact's (eq. 21). Faces by the plate at rest: its top
// (corners included) and the two sides. The work terms are the water's work on the plate since the start,
// sum over steps of F . (x_n+1 - x_n) at the surface points: the plate-wall load as applied (extrapolated or not),
// the interface added mass's spring (section 13) and the contact. Every rank holds the same numbers.
struct PlateLoadBreakdown {
  enum Face { kRight = 0, kTop = 1, kLeft = 2 };
  double wall_push[3][2] = {}, wall_suction[3][2] = {};               // N/m, [face][x, y]
  double contact[3][2] = {};                                          // N/m, [face][x, y]
  double work_wall = 0.0, work_added_mass = 0.0, work_contact = 0.0;  // J/m since the start
};

// The water's plate-wall force on one surface point over a step, as a nodal element of the plate: a dead load plus
// the interface added mass M_a = m_a n n^T (docs/coupling.md, section 13), carried as a spring K = M_a / dt^2 about
// the place the point would reach at its last step's velocity, x_n + (x_n - x_n-1). The force is then
// -M_a (x - 2 x_n + x_n-1) / dt^2, minus the added mass times the point's acceleration over the step: smooth motion
// meets the water's load alone and a sudden change of velocity meets the layer's inertia within the plate's
// implicit step, not one step later through the water.
class SurfacePointLoad : public NodalElement {
 public:
  explicit SurfacePointLoad(int node) : node_(node) {}
  // At the start of a step: the water's load on the point from the step's start (N/m), the point's place then, its
  // added mass (kg/m, m_a n n^T times its share of the face). The load used, once a previous load exists:
  // kStart F_n, kMidStep 1.5 F_n - 0.5 F_n-1, kStepEnd 2 F_n - F_n-1 (the converged exchange's first iterate).
  enum class Guess { kStart, kMidStep, kStepEnd };
  void start_step(const Eigen::Vector2d& load, const Eigen::Vector2d& place,
                  const Eigen::Matrix2d& added_mass, Guess guess);
  void set_force(const Eigen::Vector2d& force) { force_ = force; }  // an iterate of the converged exchange
  void set_time_step(double dt) { stiffness_ = added_mass_ / (dt * dt); }
  const Eigen::Vector2d& force() const { return force_; }
  // The force the point gets at place x over the step: the water's load and the added mass's spring.
  Eigen::Vector2d spring_force(const Eigen::Vector2d& x) const { return -stiffness_ * (x - rest_); }
  // A restart's state: what start_step() carries from one step to the next (5 doubles).
  void save_state(std::vector<double>& state) const;
  const double* restore_state(const double* state);
  std::vector<int> nodes() const override { return {node_}; }
  void evaluate(const std::vector<Eigen::Vector2d>& x, Eigen::VectorXd& f, Eigen::MatrixXd& k) override {
    f = stiffness_ * (x[0] - rest_) -
        force_;  // external: enters the residual with the sign opposite to F_int
    k = stiffness_;
  }

 private:
  int node_;
  Eigen::Vector2d force_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d added_mass_ = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d stiffness_ = Eigen::Matrix2d::Zero();
  Eigen::Vector2d rest_ = Eigen::Vector2d::Zero();      // the spring's rest place
  Eigen::Vector2d previous_ = Eigen::Vector2d::Zero();  // the water's load of the step before
  Eigen::Vector2d place_ = Eigen::Vector2d::Zero();     // the point's place at the start of the step before
  bool has_previous_ = false;
};

class ContactCoupling {
 public:
  // Collective over world. solver: non-null on `root` only (it must outlive this object).
  ContactCoupling(MPI_Comm world, structure::PlateSolver* solver, const CouplingParameters& params,
                  int root = 0);
  ContactCoupling(const ContactCoupling&) = delete;
  ContactCoupling& operator=(const ContactCoupling&) = delete;

  // Collective. Advances the plate from t to t + dt with the contact of the particles' predicted positions
  // (at t + dt) and fills `out` with the corrections of this rank's owned particles. Same report on every
  // rank. NumericalError on every rank together when the solve fails (with time, place and cause).
  const CouplingStepReport& step(double t, double dt, const InterfaceParticles& particles, Corrections& out);

  // The plate's current outer surface as segments, on every rank (for Fluid::set_barriers: no SPH interaction
  // across the plate).
  std::vector<sph::Barrier> outline() const;
  // The same surface with its points' velocities and accelerations (for Fluid::set_plate_outline).
  sph::PlateOutline plate_outline() const;
  // Collective. The fluid's plate-wall loads of this rank (Fluid::plate_wall_loads()), applied to the plate over
  // the next step() of length dt: gathered to the root, summed per surface point in (gid, point) order
  // (rank-independent).
  void set_fluid_loads(const std::vector<sph::PlateWallLoad>& local, double dt);
  // Collective, with plate_wall_exchange: implicit: the water's plate-wall loads computed after a step() with the
  // plate as that step left it (F_out). Compares them with the loads the step was solved under (F_in); if they
  // differ by more than the tolerance, sets the next iterate's loads for a repeat of the step (after the caller has
  // put the plate, the cables, the water and this object back with restore_state(), which leaves these loads).
  // An iteration that stalls (3 evaluations without a new best) or reaches max_iterations ends with its best
  // iterate, evaluated once more if it was not the last; `accepted` says the step is taken as it stands.
  ExchangeIterate converge_exchange(const std::vector<sph::PlateWallLoad>& local);
  double fluid_load_x() const { return fluid_load_[0]; }  // N/m, total on the plate, every rank
  double fluid_load_y() const { return fluid_load_[1]; }
  const SurfacePolyline& surface() const { return surface_; }
  // Collective: re-reads the plate's surface (points, velocities, accelerations) after the plate moved outside a
  // step, as its static start moves it; the surface is otherwise read when this object is built and after a step.
  void refresh_surface() { broadcast_surface(); }

  const CouplingStepReport& last_step() const { return last_; }
  const PlateLoadBreakdown& load_breakdown() const { return breakdown_; }
  const ContactSolveReport& last_solve() const { return last_solve_; }  // root only (empty elsewhere)
  PhaseTimers timers() const;  // search, gather, assembly, solve, handback (assembly/solve: root only)
  const CouplingParameters& parameters() const { return params_; }

  // A restart's state: what a step carries to the next (the surface's extrapolated motion, the surface loads'
  // previous values, the work sums and their last nodal forces). save_state() is rank 0's copy; restore_state()
  // is collective, after the plate's state is restored (it re-reads the surface from the plate).
  std::vector<double> save_state() const;
  void restore_state(const std::vector<double>& state);

 private:
  void broadcast_surface();
  // Root: the loads of every rank's particles summed per surface point in (gid, point) order; with `breakdown`, the
  // push / suction split of each face into breakdown_.
  std::vector<Eigen::Vector2d> gather_point_loads(const std::vector<sph::PlateWallLoad>& local,
                                                  bool breakdown);
  std::vector<Eigen::Vector2d> surface_normals() const;  // outward, per surface point
  // The face (PlateLoadBreakdown::Face) of surface point k and of segment s = (k, k + 1), from the corners at rest.
  int point_face(int k) const {
    return k < corners_[0] ? first_face_ : k > corners_[1] ? second_face_ : PlateLoadBreakdown::kTop;
  }
  int segment_face(int s) const {
    return s < corners_[0] ? first_face_ : s >= corners_[1] ? second_face_ : PlateLoadBreakdown::kTop;
  }
  // Root: the structure's part of step(); returns the corrections in gathered order.
  std::vector<InvaderCorrection> solve_on_root(double t, double dt, double layer,
                                               const std::vector<Invader>& inv);

  Communicator comm_;
  int rank_ = 0, root_ = 0;
  std::vector<std::unique_ptr<SurfacePointLoad>>
      loads_;  // root: one per surface point (clamped ones ignored)
  double fluid_load_[2] = {0.0, 0.0};
  // The outline's corners at rest (sph::outline_corners) and which tank face its first and second faces are: the
  // first runs up the tank's right face on a standing plate, down its left face on a hanging one.
  int corners_[2] = {-1, -1};
  int first_face_ = PlateLoadBreakdown::kTop, second_face_ = PlateLoadBreakdown::kTop;
  PlateLoadBreakdown breakdown_;
  // Root: each part's force (wall, added mass, contact) per plate node at the step's end, and at the last step's.
  std::vector<Eigen::Vector2d> nodal_force_[3], previous_force_[3];
  std::vector<double> surface_motion_;  // every rank: vx, vy, ax, ay per surface point
  std::vector<double> mean_velocity_;   // every rank: vx, vy per surface point over the last step
  InterfaceQuasiNewton accelerator_{
      InterfaceQuasiNewtonOptions{}};  // root: the converged exchange's iterations
  int exchange_iteration_ = 0, best_iteration_ = 0;
  double best_residual_ = 0.0;
  Eigen::VectorXd best_input_;
  bool returning_to_best_ = false;
  double thickness_ = 0.0;  // m, the plate's: bounds how deep inside an invader can be found
  structure::PlateSolver* solver_;
  CouplingParameters params_;
  std::unique_ptr<ContactSystem> system_;
  SurfacePolyline surface_;
  CouplingStepReport last_;
  ContactSolveReport last_solve_;
  PhaseTimers timers_;
};

}  // namespace halfeti::coupling
