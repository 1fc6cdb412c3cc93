// The converged exchange's accelerator on fixed points with known answers.
#include <gtest/gtest.h>

#include "halfeti/coupling/interface_quasi_newton.hpp"

namespace {

using halfeti::coupling::InterfaceAcceleration;
using halfeti::coupling::InterfaceQuasiNewton;

// H(x) = A x + b with A's eigenvalues -1.8 ... -0.2 (the added-mass effect of a light structure: the plain
// iteration x = H(x) overshoots and, with |lambda| > 1, diverges); fixed point x* = (I - A)^-1 b.
struct LinearMap {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  explicit LinearMap(int n) : A(n, n), b(n) {
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) Q(i, j) = std::cos(0.7 * (i + 1) * (j + 2)) + (i == j ? 2.0 : 0.0);
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Q);
    const Eigen::MatrixXd orth = qr.householderQ();
    Eigen::VectorXd lambda(n);
    for (int i = 0; i < n; ++i) lambda(i) = -0.2 - 1.6 * i / (n - 1);
    A = orth * lambda.asDiagonal() * orth.transpose();
    for (int i = 0; i < n; ++i) b(i) = 1.0 + 0.5 * i;
  }
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const { return A * x + b; }
  Eigen::VectorXd solution() const {
    return (Eigen::MatrixXd::Identity(b.size(), b.size()) - A).partialPivLu().solve(b);
  }
};

int iterations_to(InterfaceQuasiNewton& qn, const LinearMap& H, double tol, int max, Eigen::VectorXd& x) {
  x = Eigen::VectorXd::Zero(H.b.size());
  qn.start();
  for (int k = 1; k <= max; ++k) {
    const Eigen::VectorXd y = H(x);
    if (InterfaceQuasiNewton::residual_ratio(x, y) <= tol) return k;
    x = qn.next(x, y);
  }
  return max + 1;
}

TEST(InterfaceQuasiNewton, LinearMapConvergesWithinUnknownsPlusTwoEvaluations) {
  // For a linear map the secant model is exact once it spans the space: n + 1 inputs give the answer, and one more
  // evaluation confirms it (the residual to round-off).
  const int n = 6;
  const LinearMap H(n);
  InterfaceQuasiNewton qn({InterfaceAcceleration::kIqnIls, 0.5});
  Eigen::VectorXd x;
  const int evaluations = iterations_to(qn, H, 1e-10, 50, x);
  EXPECT_LE(evaluations, n + 2);
  EXPECT_LT((x - H.solution()).norm() / H.solution().norm(), 1e-9);
}

TEST(InterfaceQuasiNewton, PlainIterationDivergesWhereQuasiNewtonConverges) {
  // The same map without the quasi-Newton update: the eigenvalue -1.8 makes every plain step grow the error.
  const LinearMap H(6);
  InterfaceQuasiNewton plain({InterfaceAcceleration::kRelaxation, 1.0});
  Eigen::VectorXd x;
  EXPECT_GT(iterations_to(plain, H, 1e-6, 60, x), 60);
  // Under-relaxed by 0.5 the plain iteration contracts every mode (|1 - 0.5 (1 - lambda)| < 1 for lambda in
  // [-1.8, -0.2]: at most 0.4), and converges, but takes several times IQN-ILS's evaluations.
  InterfaceQuasiNewton relaxed({InterfaceAcceleration::kRelaxation, 0.5});
  const int slow = iterations_to(relaxed, H, 1e-6, 200, x);
  EXPECT_LT(slow, 200);
  EXPECT_LT((x - H.solution()).norm() / H.solution().norm(), 1e-5);
  InterfaceQuasiNewton qn({InterfaceAcceleration::kIqnIls, 0.5});
  EXPECT_LT(iterations_to(qn, H, 1e-6, 200, x), slow);
}

TEST(InterfaceQuasiNewton, WeakCouplingConvergesInTwoOrThreeEvaluations) {
  // The water's within-step response to the plate is weak at WCSPH time steps (docs/coupling.md, section 16: the
  // loop gain ~ 1e-2): H = 0.02 A / 1.8 + b. Plain iteration gains two digits a pass; IQN-ILS needs no more passes.
  LinearMap H(6);
  H.A *= 0.02 / 1.8;
  InterfaceQuasiNewton qn({InterfaceAcceleration::kIqnIls, 1.0});
  Eigen::VectorXd x;
  EXPECT_LE(iterations_to(qn, H, 1e-6, 20, x), 4);
}

TEST(InterfaceQuasiNewton, ResidualRatioOfZeroOutputIsTheResidual) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3);
  EXPECT_EQ(InterfaceQuasiNewton::residual_ratio(zero, zero), 0.0);
  Eigen::VectorXd x = zero;
  x(1) = 2.0;
  EXPECT_DOUBLE_EQ(InterfaceQuasiNewton::residual_ratio(x, zero), 2.0);
}

}  // namespace
