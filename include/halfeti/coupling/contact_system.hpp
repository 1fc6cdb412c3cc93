// The saddle-point system of eq. 21 on the structure's rank, solved by Newton together with the plate:
//
//   [ K_eff + H_UU   H_Uy        -A_U^T ] [dU ]   [ r_s + A_U^T lambda              ]
//   [ H_yU           M_p + H_yy  -A_y^T ] [dy ] = [ A_y^T lambda - M_p (y - y_pred) ]
//   [ -A_U           -A_y         0     ] [dl ]   [ c(y, U)                         ]
//
// U: plate displacements (K_eff, r_s from PlateSolver::add_newton_system: Newmark-effective solid + cables),
// y: invader positions, M_p = m 2/dt^2 (constant-acceleration mass participation), lambda: contact forces on
// the invaders, c: the constraint of contact_constraint.hpp, A = dc/d(U, y), H = -d2(lambda . c). Two ways to
// solve it (ContactSolver):
//   kCondensed (default): each invader's (dy, dl) block couples only to its segment's 4 plate dofs, so it is
//     eliminated exactly (a dense 4 x 4 Schur update per invader) and the plate's own Newton system and KSP
//     ("-structure_" options) solve what remains; dy and dl follow by back-substitution. Same answer,
//     fastest.
//   kSaddlePoint: the whole system as one sequential AIJ matrix, fields ordered [plate dofs | invader dofs |
//     multipliers], KSP prefix "structure_contact_" (default preonly + LU with MUMPS; PCFIELDSPLIT
//     selectable, with the splits "primal" and "contact"). See docs/coupling.md for the measured costs.
#pragma once

#include <petscksp.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "halfeti/core/petsc_owner.hpp"
#include "halfeti/core/timers.hpp"
#include "halfeti/coupling/contact_constraint.hpp"
#include "halfeti/coupling/contact_kinematics.hpp"
#include "halfeti/structure/plate_solver.hpp"

namespace halfeti::coupling {

// One invader as the system sees it: predicted position, mass, and what the search froze for the step.
struct ContactInvader {
  Eigen::Vector2d predicted = Eigen::Vector2d::Zero();  // m, fluid's position at t + dt without contact
  double mass = 0.0;                                    // kg/m
  int segment = -1;                                     // index into mesh().surface
  double eta = 0.0;                                     // eq. 20 at the search (kTied keeps it)
  double target_gap = 0.0;                              // m, g* (0, or eq. 22's relocated gap)
};

struct ContactSolveReport {
  int iterations = 0;                    // Newton iterations (linear solves)
  std::vector<double> residual_history;  // ||force rows||_2 [N/m] at each assembly
  std::vector<double> gap_history;       // ||c||_inf [m] at each assembly
  double solve_seconds = 0.0;            // KSP time in this call
};

enum class ContactSolver { kCondensed, kSaddlePoint };

class ContactSystem {
 public:
  // solver: the plate, on this rank (the structure's communicator has one rank in this version).
  // participation: the invader's mass participation is participation * m / dt^2 (1: the fluid's kick-drift
  // step, where an impulse J moves the particle by dt J / m; 2: the paper's constant acceleration over the step).
  ContactSystem(structure::PlateSolver& solver, ContactConstraint form,
                std::string options_prefix = "structure_contact_",
                ContactSolver method = ContactSolver::kCondensed, double participation = 1.0);
  ContactSystem(const ContactSystem&) = delete;
  ContactSystem& operator=(const ContactSystem&) = delete;

  // Newton on eq. 21 between solver.begin_step()/begin_static() and solver.end_step(). dt sets the mass
  // participation (participation * m / dt^2). `when` names the time in error messages. NumericalError on non-convergence.
  ContactSolveReport solve(const std::vector<ContactInvader>& invaders, double dt, double when);

  // After solve(): final invader positions, contact forces on them (N/m), and the contact forces on the
  // plate's dofs (2 per node, clamped nodes included: there they are reactions carried by the clamp).
  const std::vector<Eigen::Vector2d>& positions() const { return y_; }
  const std::vector<Eigen::Vector2d>& forces() const { return force_; }
  const Eigen::VectorXd& structure_forces() const { return structure_force_; }

  // The current surface of the plate as a polyline (node positions at the current iterate).
  static SurfacePolyline surface(const structure::PlateSolver& solver);

  PhaseTimers& timers() { return timers_; }
  const PhaseTimers& timers() const { return timers_; }

 private:
  // One invader's share of the Newton system at the current iterate.
  struct LocalContact {
    PetscInt q[6];  // rows of (y, F, S) in the saddle-point numbering; -1 for clamped plate dofs
    ConstraintTerms terms;
    double participation = 0.0;       // participation * m / dt^2
    Eigen::Matrix<double, 6, 1> rhs;  // A^T lambda, minus the particle's inertia on its rows
  };
  LocalContact local_contact(int i, const ContactInvader& inv, double dt);

  void build(const std::vector<ContactInvader>& invaders);
  // Assembles the Jacobian and right-hand side at the current iterate; returns (force norm, gap inf-norm).
  std::pair<double, double> assemble(const std::vector<ContactInvader>& invaders, double dt);
  void solve_linear(double when);
  // The condensed path: assemble into the plate's own system, solve it, back-substitute
  // (contact_condensed.cpp).
  std::pair<double, double> assemble_condensed(const std::vector<ContactInvader>& invaders, double dt);
  double solve_condensed(double when);  // applies the increments; returns the increment inf-norm

  structure::PlateSolver& solver_;
  ContactConstraint form_;
  std::string prefix_;
  ContactSolver method_;
  double participation_ = 1.0;
  // Condensed path: per invader B^-1 C and B^-1 b_z of its eliminated (dy, dl) block (contact_condensed.cpp).
  struct Eliminated {
    Eigen::Matrix4d binv_c = Eigen::Matrix4d::Zero();
    Eigen::Vector4d binv_b = Eigen::Vector4d::Zero();
  };
  std::vector<Eliminated> eliminated_;
  std::vector<PetscInt> local_q_;  // the 4 plate dofs of each invader's segment (-1: clamped)
  int n_struct_ = 0, n_inv_ = 0, rows_per_ = 1;
  OwnedMat matrix_;
  OwnedVec rhs_, solution_;
  OwnedKsp ksp_;
  std::vector<Eigen::Vector2d> y_, lambda_, force_;
  Eigen::VectorXd structure_force_;
  PhaseTimers timers_;
};

}  // namespace halfeti::coupling
