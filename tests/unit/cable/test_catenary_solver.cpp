// Newton on the projection equations: tangent, limits, a published example, and a sweep of geometries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "halfeti/cable/catenary.hpp"
#include "halfeti/core/error.hpp"

namespace halfeti::cable {
namespace {

CableProperties make_cable(double l0, double ea, double w) {
  CableProperties c;
  c.unstretched_length = l0;
  c.axial_stiffness = ea;
  c.weight_per_length = w;
  return c;
}

// Force the nodes exert on the cable, the quantity whose derivative `tangent` is.
Eigen::Vector4d internal_force(const Eigen::Vector4d& x, const CableProperties& c) {
  return -solve_catenary(x.head<2>(), x.tail<2>(), c).nodal_force;
}

double tangent_error(const Eigen::Vector4d& x, const CableProperties& c) {
  const CatenarySolution s = solve_catenary(x.head<2>(), x.tail<2>(), c);
  const double step = 1e-6 * s.chord;
  Eigen::Matrix4d fd;
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector4d plus = x, minus = x;
    plus(j) += step;
    minus(j) -= step;
    fd.col(j) = (internal_force(plus, c) - internal_force(minus, c)) / (2 * step);
  }
  return (fd - s.tangent).norm() / s.tangent.norm();
}

TEST(CatenarySolver, TangentMatchesCentralDifferences) {
  struct Case {
    Eigen::Vector4d x;
    CableProperties c;
    const char* regime;
  };
  const Case cases[] = {
      {{0.0, 0.0, 1.0, 0.5}, make_cable(1.0, 100.0, 1.0), "taut"},
      {{0.0, 0.0, 0.8, 0.3}, make_cable(1.0, 100.0, 1.0), "slack"},
      {{0.0, 0.0, 0.3, 0.1}, make_cable(1.0, 1e4, 1.0), "deep slack"},
      {{1.0, 2.0, 0.2, 2.7}, make_cable(1.0, 100.0, 1.0), "chord pointing left"},
      {{0.0, 1.0, 1e-3, 0.0}, make_cable(0.95, 100.0, 1.0), "nearly vertical, end 2 below"},
      {{0.0, 0.0, 2.0, -0.1}, make_cable(2.0, 1e5, 0.01), "nearly horizontal, light"},
      {{0.0, 0.01, 0.1485, 0.08}, make_cable(0.1468, 91.2, 0.11772), "paper set-up, 135 kPa"},
  };
  double worst = 0.0;
  for (const Case& k : cases) {
    const double error = tangent_error(k.x, k.c);
    worst = std::max(worst, error);
    EXPECT_LT(error, 1e-6) << k.regime;
  }
  std::printf("4x4 tangent against central differences: worst relative error %.2e\n", worst);
}

TEST(CatenarySolver, TangentIsSymmetricAndFlexibilityInvertsIt) {
  const CatenarySolution s = solve_catenary({0.0, 0.0}, {0.7, -0.2}, make_cable(1.0, 50.0, 2.0));
  EXPECT_LT((s.tangent - s.tangent.transpose()).norm(), 1e-14 * s.tangent.norm());
  EXPECT_LT((s.flexibility * s.stiffness - Eigen::Matrix2d::Identity()).norm(), 1e-12);
  EXPECT_EQ(s.flexibility(0, 1), s.flexibility(1, 0));
}

TEST(CatenarySolver, EndForcesBalanceTheCableWeight) {
  const CableProperties c = make_cable(1.3, 40.0, 2.5);
  const CatenarySolution s = solve_catenary({0.2, 0.1}, {1.1, 0.6}, c);
  const Eigen::Vector2d sum = s.nodal_force.head<2>() + s.nodal_force.tail<2>();
  EXPECT_NEAR(sum.x(), 0.0, 1e-12);
  EXPECT_NEAR(sum.y(), -c.weight_per_length * c.unstretched_length, 1e-12);
  // End tensions are eq. 14 at s0 = 0 and s0 = L0.
  EXPECT_NEAR(s.tension_start, s.nodal_force.head<2>().norm(), 1e-12);
  EXPECT_NEAR(s.tension_end, s.nodal_force.tail<2>().norm(), 1e-12);
  // The curve through the solved tension ends at end 2.
  const Eigen::Vector2d end = catenary_point(s.end_tension.x(), s.end_tension.y(), 1.3, 40.0, 2.5);
  EXPECT_NEAR(end.x(), 0.9, 1e-13);
  EXPECT_NEAR(end.y(), 0.5, 1e-13);
}

TEST(CatenarySolver, WeightlessLimit) {
  // Taut weightless spring: axial stiffness EA/L0 along the chord, T/chord across it (the stretched length).
  const double l0 = 1.0, ea = 200.0;
  const Eigen::Vector2d a(0.0, 0.0), b(0.63, 0.84);
  const double chord = b.norm();
  const double tension = ea * (chord - l0) / l0;
  const Eigen::Vector2d n = b / chord;
  const Eigen::Matrix2d expected =
      ea / l0 * n * n.transpose() + tension / chord * (Eigen::Matrix2d::Identity() - n * n.transpose());
  for (double w : {0.0, 1e-12, 1e-8}) {
    const CatenarySolution s = solve_catenary(a, b, make_cable(l0, ea, w));
    EXPECT_EQ(s.state, CableState::kTaut);
    EXPECT_NEAR(s.tension_start, tension, 1e-6 * tension) << "w = " << w;
    EXPECT_LT((s.stiffness - expected).norm(), 1e-6 * expected.norm()) << "w = " << w;
  }
  // Weightless and slack: carries nothing.
  const CatenarySolution slack = solve_catenary(a, {0.5, 0.5}, make_cable(l0, ea, 0.0));
  EXPECT_FALSE(slack.carries_load);
  EXPECT_EQ(slack.state, CableState::kSlack);
  EXPECT_EQ(slack.nodal_force.norm(), 0.0);
  EXPECT_EQ(slack.tangent.norm(), 0.0);
  // Almost weightless and slack: a light catenary, force of the order of its weight.
  const CatenarySolution light = solve_catenary(a, {0.5, 0.5}, make_cable(l0, ea, 1e-9));
  EXPECT_TRUE(light.carries_load);
  EXPECT_LT(light.tension_end, 1e-8);
  EXPECT_GT(light.tension_end, 0.0);
}

TEST(CatenarySolver, TautCablePullsTheEndsTogether) {
  const CatenarySolution s = solve_catenary({0.0, 0.0}, {1.0, 0.4}, make_cable(1.0, 100.0, 0.1));
  const Eigen::Vector2d towards_end1(-1.0, -0.4);
  EXPECT_GT(s.nodal_force.tail<2>().dot(towards_end1), 0.0);
  EXPECT_GT(s.nodal_force.head<2>().dot(-towards_end1), 0.0);
}

TEST(CatenarySolver, ChordPointingLeftMirrorsChordPointingRight) {
  const CableProperties c = make_cable(1.2, 30.0, 1.5);
  const CatenarySolution right = solve_catenary({0.0, 0.0}, {0.9, 0.3}, c);
  const CatenarySolution left = solve_catenary({0.0, 0.0}, {-0.9, 0.3}, c);
  EXPECT_NEAR(left.end_tension.x(), -right.end_tension.x(), 1e-12);
  EXPECT_NEAR(left.end_tension.y(), right.end_tension.y(), 1e-12);
  EXPECT_NEAR(left.stiffness(0, 1), -right.stiffness(0, 1), 1e-9);
  EXPECT_NEAR(left.sag, right.sag, 1e-14);
}

TEST(CatenarySolver, VerticalCable) {
  const double l0 = 0.9, ea = 100.0, w = 2.0;
  // Taut, hanging: Ty = EA (h - L0)/L0 - w L0/2 (eq. 16 with Tx = 0).
  const CatenarySolution s = solve_catenary({0.0, 0.0}, {0.0, 1.0}, make_cable(l0, ea, w));
  EXPECT_DOUBLE_EQ(s.end_tension.x(), 0.0);
  EXPECT_NEAR(s.end_tension.y(), ea * (1.0 - l0) / l0 - 0.5 * w * l0, 1e-12);
  // Lateral stiffness of the vertical string equals the limit of nearly vertical ones.
  const double dx = 1e-7;
  const CatenarySolution tilted = solve_catenary({0.0, 0.0}, {dx, 1.0}, make_cable(l0, ea, w));
  EXPECT_NEAR(tilted.end_tension.x() / dx, s.stiffness(0, 0), 1e-5 * s.stiffness(0, 0));
  // Folded: the end 2 directly above end 1 at less than L0 apart; no lateral stiffness.
  const CatenarySolution folded = solve_catenary({0.0, 0.0}, {0.0, 0.5}, make_cable(l0, ea, w));
  EXPECT_EQ(folded.state, CableState::kSlack);
  EXPECT_EQ(folded.stiffness(0, 0), 0.0);
  EXPECT_TRUE(std::isinf(folded.flexibility(0, 0)));
  EXPECT_EQ(folded.flexibility(0, 1), 0.0);
  EXPECT_GT(folded.stiffness(1, 1), 0.0);
  EXPECT_NEAR(folded.nodal_force(1) + folded.nodal_force(3), -w * l0, 1e-12);
  EXPECT_GT(folded.sag, 0.0);
}

// NREL MoorPy, tests/test_catenary.py (also in WISDEM/WEIS): fully suspended lines (seabed far below,
// CB = -372.7 and -1245), anchor at the origin, fairlead at (x, z); expected forces of the line on the anchor
// (fAH, fAV) and on the fairlead (fBH, fBV), solved there to Tol = 1e-4 and compared at rtol = 1e-5.
TEST(CatenarySolver, ReproducesMoorPyCatenaryTestCases) {
  struct Case {
    double x, z, l0, ea, w, fah, fav, fbh, fbv;
  };
  const Case cases[] = {
      {400.0, 200.0, 500.0, 7.51e12, 200.0, 43694.580989249596, -22365.599350216216, -43694.580989249596,
       -77634.40064978378},
      {89.9, 59.2, 130.0, 751000000.0, 881.05, 31373.229006023103, -26650.341270116318, -31373.229006023103,
       -87886.15872988368},
      // A buoyant line (negative submerged weight) floating up.
      {37.96888656874307, 20.49078283711694, 100.0, 751000000.0, -881.0549577007893, 6428.437434537766,
       53178.729367882406, -6428.437434537766, 34926.76640219652},
  };
  for (const Case& k : cases) {
    const CatenarySolution s = solve_catenary({0.0, 0.0}, {k.x, k.z}, make_cable(k.l0, k.ea, k.w));
    const Eigen::Vector4d expected(k.fah, k.fav, k.fbh, k.fbv);
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(s.nodal_force(i), expected(i), 1e-5 * std::fabs(expected(i)))
          << "x = " << k.x << ", i = " << i;
  }
}

TEST(CatenarySolver, RandomGeometriesFromDeepSlackToTautAllConverge) {
  std::mt19937_64 rng(20260121);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = 5000;
  int slack = 0, taut = 0, near_vertical = 0, worst_iterations = 0;
  double worst_residual = 0.0;
  double worst_tangent = 0.0;
  int tangent_checks = 0;
  Eigen::Vector2d previous(1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const double l0 = std::pow(10.0, -2.0 + 4.0 * unit(rng));
    const double w = std::pow(10.0, -6.0 + 8.0 * unit(rng)) * (unit(rng) < 0.1 ? -1.0 : 1.0);
    const double ea = std::fabs(w) * l0 * std::pow(10.0, -1.0 + 8.0 * unit(rng));
    // chord / L0: half from 0.01 to 1 (slack, log-uniform), half from 0.95 to 1.6 (around taut)
    const double ratio = (i % 2 == 0) ? std::pow(10.0, -2.0 + 2.0 * unit(rng)) : 0.95 + 0.65 * unit(rng);
    double angle = 2.0 * M_PI * unit(rng);
    if (i % 5 == 0) {  // nearly vertical, up or down
      angle =
          (unit(rng) < 0.5 ? 0.5 : 1.5) * M_PI + (unit(rng) - 0.5) * std::pow(10.0, -1.0 - 8.0 * unit(rng));
      ++near_vertical;
    }
    const Eigen::Vector2d end1(unit(rng), unit(rng));
    const Eigen::Vector2d end2 = end1 + ratio * l0 * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const CableProperties c = make_cable(l0, ea, w);
    // Every third case starts from the previous case's tension, as a badly warm-started element would.
    const Eigen::Vector2d stale = previous;
    CatenarySolution s;
    ASSERT_NO_THROW(s = solve_catenary(end1, end2, c, i % 3 == 0 ? &stale : nullptr)) << "case " << i;
    previous = s.end_tension;
    (s.state == CableState::kSlack ? slack : taut)++;
    worst_iterations = std::max(worst_iterations, s.iterations);
    const Eigen::Vector2d span = end2 - end1;
    // Projection residual, mirrored into the frame where Tx >= 0 and the load points down.
    const Eigen::Vector2d mirror(s.end_tension.x() < 0.0 ? -1.0 : 1.0, w < 0.0 ? -1.0 : 1.0);
    const Eigen::Vector2d reached = mirror.cwiseProduct(
        catenary_point(mirror.x() * s.end_tension.x(), mirror.y() * s.end_tension.y(), l0, ea, std::fabs(w)));
    const double residual = (reached - span).norm() / std::max(span.norm(), l0);
    worst_residual = std::max(worst_residual, residual);
    ASSERT_LT(residual, 1e-9) << "case " << i << " span " << span.transpose() << " L0 " << l0 << " EA " << ea
                              << " w " << w;
    ASSERT_TRUE(s.tangent.allFinite()) << "case " << i;
    if ((i % 5 == 1 || i % 5 == 2) &&
        ratio > 0.05) {  // tangent against differences, away from the vertical fold
      const Eigen::Vector4d x(end1.x(), end1.y(), end2.x(), end2.y());
      const double error = tangent_error(x, c);
      worst_tangent = std::max(worst_tangent, error);
      ++tangent_checks;
      EXPECT_LT(error, 1e-4) << "case " << i;
    }
    ASSERT_GE(s.tension_end, 0.0);
  }
  RecordProperty("worst_residual", std::to_string(worst_residual));
  std::printf(
      "sweep: %d slack, %d taut (%d nearly vertical); worst relative residual %.2e, max %d iterations, "
      "worst tangent difference %.2e over %d\n",
      slack, taut, near_vertical, worst_residual, worst_iterations, worst_tangent, tangent_checks);
  EXPECT_GT(slack, n / 2);
  EXPECT_GT(taut, n / 5);
}

TEST(UnstretchedLength, InvertsTheEndTension) {
  const Eigen::Vector2d a(0.0, 0.0), b(1.0, 0.3);
  const double ea = 500.0, w = 2.0;
  for (double tension : {1.9, 10.0, 300.0}) {
    const double l0 = unstretched_length_for_end_tension(a, b, ea, w, tension);
    const CatenarySolution s = solve_catenary(a, b, make_cable(l0, ea, w));
    EXPECT_NEAR(s.tension_end, tension, 1e-10 * tension) << "T = " << tension;
  }
  // A heavy cable's end tension never falls below a positive minimum (1.8466 N here): less is a user error.
  EXPECT_THROW(unstretched_length_for_end_tension(a, b, ea, w, 1.84), UserError);
  EXPECT_THROW(unstretched_length_for_end_tension(a, b, ea, w, -1.0), UserError);
}

// The drawn shape: it starts and ends at the cable's ends, carries the end tensions of eq. 14, and its polyline is
// as long as the stretched cable, the integral of 1 + T / EA over s0 (within the polyline's O(1/n^2) chord error:
// 1e-3 at 64 segments). A slack heavy cable, a taut one, and one under a sideways load (the solver's rotated frame).
TEST(CatenaryCurve, EndsAtTheEndsWithTheEndTensionsAndTheStretchedLength) {
  struct Case {
    Eigen::Vector2d a, b;
    double l0, ea, w, side;
  };
  for (const Case& c : {Case{{0.0, 0.0}, {1.0, 0.2}, 1.3, 50.0, 2.0, 0.0},
                        Case{{0.0, 0.0}, {-0.8, 0.5}, 0.9, 400.0, 1.0, 0.0},
                        Case{{0.2, 0.1}, {0.9, 0.4}, 1.0, 80.0, 1.5, 0.7}}) {
    CableProperties cable = make_cable(c.l0, c.ea, c.w);
    cable.horizontal_load = c.side;
    const CatenarySolution s = solve_catenary(c.a, c.b, cable);
    const int n = 64;
    const auto curve = catenary_curve(c.a, c.b, cable, s, n);
    ASSERT_EQ(curve.size(), static_cast<std::size_t>(n + 1));
    EXPECT_LT((curve.front().position - c.a).norm(), 1e-12);
    EXPECT_LT((curve.back().position - c.b).norm(), 1e-9 * s.chord) << "l0 = " << c.l0;
    EXPECT_NEAR(curve.front().tension, s.tension_start, 1e-12 * s.tension_start);
    EXPECT_NEAR(curve.back().tension, s.tension_end, 1e-9 * s.tension_end);
    double polyline = 0.0, stretched = 0.0;
    for (int k = 0; k < n; ++k) {
      polyline += (curve[k + 1].position - curve[k].position).norm();
      stretched += c.l0 / n * (1.0 + 0.5 * (curve[k].tension + curve[k + 1].tension) / c.ea);
    }
    EXPECT_NEAR(polyline, stretched, 1e-3 * stretched) << "l0 = " << c.l0;
  }
}

TEST(CatenarySolver, FailsLoudlyOnBadInput) {
  EXPECT_THROW(solve_catenary({0.0, 0.0}, {1.0, 0.0}, make_cable(0.0, 1.0, 1.0)), InternalError);
  EXPECT_THROW(solve_catenary({0.0, 0.0}, {NAN, 0.0}, make_cable(1.0, 1.0, 1.0)), InternalError);
}

}  // namespace
}  // namespace halfeti::cable
