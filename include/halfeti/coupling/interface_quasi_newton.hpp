// The converged plate-water exchange's accelerator: a fixed point x = H(x) of the interface load (H: the plate
// solved under load x, then the water's load on the plate so moved), solved by interface quasi-Newton with an
// inverse Jacobian from least squares (IQN-ILS: Degroote, Bruggeman, Haelterman & Vierendeels 2009, Computers &
// Structures 87, 793-801), or by constant under-relaxation. Chosen because it needs nothing but H's input and output
// (the water's solver gives no Jacobian), converges where plain iteration diverges under a strong added-mass effect,
// and for a linear H of n unknowns ends in at most n + 1 evaluations (docs/coupling.md, section 16).
//
//   InterfaceQuasiNewton qn(options);
//   x = guess; qn.start();
//   for (;;) { y = H(x); if (qn.residual_ratio(x, y) <= tol) break; x = qn.next(x, y); }
//
// Pure linear algebra on one rank (the plate's): the caller broadcasts the verdict.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace halfeti::coupling {

enum class InterfaceAcceleration { kIqnIls, kRelaxation };

struct InterfaceQuasiNewtonOptions {
  InterfaceAcceleration method = InterfaceAcceleration::kIqnIls;
  // The first iteration's (IQN-ILS) or every iteration's (constant) under-relaxation, (0, 1].
  double relaxation = 1.0;
};

class InterfaceQuasiNewton {
 public:
  explicit InterfaceQuasiNewton(const InterfaceQuasiNewtonOptions& options) : options_(options) {}
  // Forgets the iterations of the last time step (each step builds its own Jacobian: IQN-ILS without reuse).
  void start();
  // ||H(x) - x|| / ||H(x)|| (0 when both are zero): the convergence measure.
  static double residual_ratio(const Eigen::VectorXd& x, const Eigen::VectorXd& hx);
  // The next input from this input x and its output H(x).
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& hx);
  int columns() const { return static_cast<int>(residuals_.size()) - 1; }  // secant pairs in the last update

 private:
  InterfaceQuasiNewtonOptions options_;
  std::vector<Eigen::VectorXd> residuals_,
      outputs_;  // r_i = H(x_i) - x_i and H(x_i) of this step's iterations
};

}  // namespace halfeti::coupling
