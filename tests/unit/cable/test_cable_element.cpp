// CableElement as a NodalElement: sign convention, tangent, warm start, two-node form.
#include <gtest/gtest.h>

#include "halfeti/cable/cable_element.hpp"

namespace halfeti::cable {
namespace {

CableProperties make_cable(double l0, double ea, double w) {
  CableProperties c;
  c.unstretched_length = l0;
  c.axial_stiffness = ea;
  c.weight_per_length = w;
  return c;
}

TEST(CableElement, TautCablePullsTheNodeTowardsTheAnchor) {
  const Eigen::Vector2d anchor(0.0, 0.01);
  CableElement cable(anchor, 7, make_cable(0.1468, 91.2, 0.11772));
  EXPECT_EQ(cable.nodes(), std::vector<int>{7});
  Eigen::VectorXd f;
  Eigen::MatrixXd k;
  const Eigen::Vector2d node(0.1485, 0.08);
  cable.evaluate({node}, f, k);
  ASSERT_EQ(f.size(), 2);
  ASSERT_EQ(k.rows(), 2);
  // F_int is what the node exerts on the cable; the cable's pull on the node is -F_int.
  const Eigen::Vector2d pull = -f;
  EXPECT_GT(pull.dot(anchor - node), 0.99 * pull.norm() * (anchor - node).norm());
  EXPECT_EQ(cable.last_solution().state, CableState::kTaut);
}

TEST(CableElement, AnchoredTangentMatchesDifferencesAndWarmStartConverges) {
  const Eigen::Vector2d anchor(0.0, 0.0);
  CableElement cable(anchor, 0, make_cable(1.0, 80.0, 1.0));
  Eigen::VectorXd f, fp, fm;
  Eigen::MatrixXd k, unused;
  const Eigen::Vector2d x(0.8, 0.4);
  cable.evaluate({x}, f, k);
  const int cold_iterations = cable.last_solution().iterations;
  const double step = 1e-6;
  Eigen::Matrix2d fd;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d xp = x, xm = x;
    xp(j) += step;
    xm(j) -= step;
    cable.evaluate({xp}, fp, unused);
    cable.evaluate({xm}, fm, unused);
    fd.col(j) = (fp - fm) / (2 * step);
  }
  EXPECT_LT((fd - k).norm(), 1e-6 * k.norm());
  // From the previous state a small move takes fewer Newton steps than the cold start.
  cable.evaluate({x}, f, k);
  EXPECT_LE(cable.last_solution().iterations, std::max(cold_iterations, 2));
}

TEST(CableElement, BetweenTwoNodesBalancesItsWeight) {
  const CableProperties c = make_cable(1.0, 50.0, 2.0);
  CableElement cable(3, 5, c);
  EXPECT_EQ(cable.nodes(), (std::vector<int>{3, 5}));
  Eigen::VectorXd f;
  Eigen::MatrixXd k;
  cable.evaluate({Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.7, 0.2)}, f, k);
  ASSERT_EQ(f.size(), 4);
  // The nodes hold the cable up: their forces on it sum to its weight, upwards.
  EXPECT_NEAR(f(0) + f(2), 0.0, 1e-12);
  EXPECT_NEAR(f(1) + f(3), 2.0, 1e-12);
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  // Rigid translation changes nothing: each row of the tangent sums to zero over x and over y.
  EXPECT_LT((k.col(0) + k.col(2)).norm(), 1e-12 * k.norm());
  EXPECT_LT((k.col(1) + k.col(3)).norm(), 1e-12 * k.norm());
}

TEST(CableElement, HorizontalLoadTiltsTheSag) {
  // The tank frame's inertial load: the cable's load rotates, and the ends still balance it.
  CableProperties c = make_cable(1.0, 50.0, 2.0);
  CableElement cable(Eigen::Vector2d(0.0, 0.0), 0, c);
  cable.set_horizontal_load(-0.5);
  Eigen::VectorXd f;
  Eigen::MatrixXd k;
  cable.evaluate({Eigen::Vector2d(0.8, 0.3)}, f, k);
  const CatenarySolution& s = cable.last_solution();
  const Eigen::Vector2d sum = s.nodal_force.head<2>() + s.nodal_force.tail<2>();
  EXPECT_NEAR(sum.x(), -0.5, 1e-12);
  EXPECT_NEAR(sum.y(), -2.0, 1e-12);
  EXPECT_LT((k - k.transpose()).norm(), 1e-10 * k.norm());
}

}  // namespace
}  // namespace halfeti::cable
