// The projection equations (eqs. 15-16) and the flexibility (eq. 17) derived in docs/cable.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfeti/cable/catenary.hpp"

namespace halfeti::cable {
namespace {

Eigen::Vector2d projections(double tx, double ty, double l0, double ea, double w) {
  const CatenaryProjection p = catenary_projection(tx, ty, l0, ea, w);
  return {p.horizontal, p.vertical};
}

// Central differences of (l, h) and of the complementary energy with respect to (Tx, Ty).
struct FlexibilityCase {
  double tx, ty, l0, ea, w;
  const char* regime;
};

class FlexibilityAgainstDifferences : public ::testing::TestWithParam<FlexibilityCase> {};

TEST_P(FlexibilityAgainstDifferences, MatchesCentralDifferences) {
  const FlexibilityCase c = GetParam();
  const CatenaryProjection p = catenary_projection(c.tx, c.ty, c.l0, c.ea, c.w);
  const double step = 1e-5 * c.tx;  // tx sets the length scale of the tension's turning
  Eigen::Matrix2d fd;
  fd.col(0) =
      (projections(c.tx + step, c.ty, c.l0, c.ea, c.w) - projections(c.tx - step, c.ty, c.l0, c.ea, c.w)) /
      (2 * step);
  fd.col(1) =
      (projections(c.tx, c.ty + step, c.l0, c.ea, c.w) - projections(c.tx, c.ty - step, c.l0, c.ea, c.w)) /
      (2 * step);
  const double error = (fd - p.flexibility).norm() / p.flexibility.norm();
  EXPECT_LT(error, 1e-7) << c.regime << "\nanalytic\n" << p.flexibility << "\nfd\n" << fd;
  std::printf("flexibility vs differences, %s: %.2e\n", c.regime, error);
  // Symmetric: the Hessian of the complementary energy.
  EXPECT_EQ(p.flexibility(0, 1), p.flexibility(1, 0)) << c.regime;
  // The energy's gradient is (l, h).
  auto energy = [&](double tx, double ty) {
    return catenary_projection(tx, ty, c.l0, c.ea, c.w).complementary_energy;
  };
  const Eigen::Vector2d grad((energy(c.tx + step, c.ty) - energy(c.tx - step, c.ty)) / (2 * step),
                             (energy(c.tx, c.ty + step) - energy(c.tx, c.ty - step)) / (2 * step));
  const Eigen::Vector2d lh(p.horizontal, p.vertical);
  EXPECT_LT((grad - lh).norm(), 1e-6 * std::max(lh.norm(), c.l0)) << c.regime;
  // Positive definite.
  EXPECT_GT(p.flexibility.determinant(), 0.0) << c.regime;
  EXPECT_GT(p.flexibility(0, 0), 0.0) << c.regime;
}

INSTANTIATE_TEST_SUITE_P(
    Regimes, FlexibilityAgainstDifferences,
    ::testing::Values(FlexibilityCase{10.0, 3.0, 2.0, 1e4, 1.0, "taut, rising"},
                      FlexibilityCase{1.0, -4.0, 10.0, 1e5, 1.0, "slack, lowest point inside the span"},
                      FlexibilityCase{1.0, -20.0, 10.0, 1e5, 1.0, "slack, falling all the way"},
                      FlexibilityCase{100.0, -0.3, 1.0, 1e6, 0.5, "nearly horizontal (quadrature branch)"},
                      FlexibilityCase{1e-3, 5.0, 1.0, 1e3, 2.0, "nearly vertical, taut"},
                      FlexibilityCase{1e-2, -1.0, 1.0, 1e3, 2.0, "nearly vertical, folded"},
                      FlexibilityCase{3.0, 1.0, 1.0, 1e2, 1e-9, "almost weightless"},
                      FlexibilityCase{0.05, 0.02, 1.0, 1e2, 30.0, "heavy, deep sag"}));

TEST(CatenaryProjection, WeightlessLimitIsAStraightElasticBar) {
  // w = 0: l = Tx L0 (1/EA + 1/T), h = Ty L0 (1/EA + 1/T), no division by w anywhere.
  const double tx = 3.0, ty = 4.0, l0 = 2.0, ea = 50.0;
  for (double w : {0.0, 1e-14, 1e-10}) {
    const CatenaryProjection p = catenary_projection(tx, ty, l0, ea, w);
    const double stretched = l0 * (1.0 + 5.0 / ea);
    EXPECT_NEAR(p.horizontal, stretched * 0.6, 1e-9) << "w = " << w;
    EXPECT_NEAR(p.vertical, stretched * 0.8, 1e-9) << "w = " << w;
    // f = L0/EA I + (L0/T)(I - n n^T)
    Eigen::Matrix2d expected = l0 / ea * Eigen::Matrix2d::Identity();
    const Eigen::Vector2d n(0.6, 0.8);
    expected += l0 / 5.0 * (Eigen::Matrix2d::Identity() - n * n.transpose());
    EXPECT_LT((p.flexibility - expected).norm(), 1e-9) << "w = " << w;
  }
}

TEST(CatenaryProjection, InextensibleCatenaryClosedForm) {
  // Tx = H, Ty = H sinh(a): x(L0) = (H/w)(asinh(sinh a + w L0/H) - a) + H L0/EA.
  const double h = 2.0, w = 3.0, l0 = 4.0, ea = 1e3, a = -0.7;
  const CatenaryProjection p = catenary_projection(h, h * std::sinh(a), l0, ea, w);
  const double b = std::asinh(std::sinh(a) + w * l0 / h);
  EXPECT_NEAR(p.horizontal, h / w * (b - a) + h * l0 / ea, 1e-12);
  const double ty = h * std::sinh(a);
  EXPECT_NEAR(p.vertical, h / w * (std::cosh(b) - std::cosh(a)) + l0 * (ty + 0.5 * w * l0) / ea, 1e-12);
}

TEST(CatenaryProjection, PointAtEndEqualsProjection) {
  const CatenaryProjection p = catenary_projection(2.0, -1.0, 3.0, 100.0, 1.5);
  const Eigen::Vector2d end = catenary_point(2.0, -1.0, 3.0, 100.0, 1.5);
  EXPECT_DOUBLE_EQ(end.x(), p.horizontal);
  EXPECT_DOUBLE_EQ(end.y(), p.vertical);
}

}  // namespace
}  // namespace halfeti::cable
