// Newmark's family of time integrators (Newmark 1959) for M a + F(u) = R: the plate's time step, in one place.
//
//   u_n+1 = u_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_n+1)
//   v_n+1 = v_n + dt ((1 - gamma) a_n + gamma a_n+1)
//
// solved for the displacement: a_n+1 is the function acceleration() of the unknown u_n+1, whose derivative
// mass_coefficient() = 1 / (beta dt^2) multiplies M in the Newton matrix. beta = 1/4, gamma = 1/2 is the
// trapezoidal rule (energy-conserving for linear systems, second order); gamma > 1/2 damps the high frequencies
// (first order); unconditional stability needs beta >= (gamma + 1/2)^2 / 4.
#pragma once

#include <Eigen/Dense>

namespace halfeti::structure {

struct NewmarkParameters {
  double beta = 0.25;  // (0, 0.5]; 1/4 with gamma 1/2 is the trapezoidal rule (energy-conserving, 2nd order)
  double gamma = 0.5;  // [0.5, 1]; > 0.5 adds numerical damping
};

// UserError naming structure.newmark.* when a parameter is out of range or the pair is only conditionally stable.
void validate(const NewmarkParameters& p);

class Newmark {
 public:
  explicit Newmark(const NewmarkParameters& p) : beta_(p.beta), gamma_(p.gamma) {}
  // d a_n+1 / d u_n+1.
  double mass_coefficient(double dt) const { return 1.0 / (beta_ * dt * dt); }
  // a_n+1 of the displacement u (the step from (u_n, v_n, a_n) over dt).
  void acceleration(const Eigen::VectorXd& u, const Eigen::VectorXd& u_n, const Eigen::VectorXd& v_n,
                    const Eigen::VectorXd& a_n, double dt, Eigen::VectorXd& a) const {
    a = (u - u_n - dt * v_n - dt * dt * (0.5 - beta_) * a_n) / (beta_ * dt * dt);
  }
  // v_n+1 once a_n+1 is known.
  void velocity(const Eigen::VectorXd& v_n, const Eigen::VectorXd& a_n, const Eigen::VectorXd& a, double dt,
                Eigen::VectorXd& v) const {
    v = v_n + dt * ((1.0 - gamma_) * a_n + gamma_ * a);
  }

 private:
  double beta_, gamma_;
};

}  // namespace halfeti::structure
