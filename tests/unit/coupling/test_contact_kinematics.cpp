// Contact kinematics (eq. 20), the SSOSD relocation and layer (eqs. 22-23) and the contact constraint's
// derivatives against finite differences (eq. 19).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "halfeti/core/error.hpp"
#include "halfeti/coupling/contact_constraint.hpp"
#include "halfeti/coupling/contact_kinematics.hpp"
#include "halfeti/coupling/ssosd.hpp"

namespace hc = halfeti::coupling;
using Eigen::Vector2d;

namespace {

// A 2 x 4 box standing on y = 0, surface counterclockwise without the base: up the right face, across the top
// leftwards, down the left face (as the plate mesh orders it).
hc::SurfacePolyline box() {
  hc::SurfacePolyline s;
  s.points = {{1, 0}, {1, 2}, {1, 4}, {0, 4}, {-1, 4}, {-1, 2}, {-1, 0}};
  s.nodes = {0, 1, 2, 3, 4, 5, 6};
  return s;
}

}  // namespace

TEST(ContactKinematics, ProjectionOnASegment) {
  const Vector2d f(1, 0), s(1, 2);
  const auto p = hc::project_on_segment(Vector2d(1.5, 0.5), f, s);
  EXPECT_DOUBLE_EQ(p.eta, 0.25);
  EXPECT_DOUBLE_EQ(p.gap, 0.5);  // right face: outward normal +x
  EXPECT_DOUBLE_EQ(p.normal.x(), 1.0);
  EXPECT_DOUBLE_EQ(p.normal.y(), 0.0);
  EXPECT_DOUBLE_EQ(p.length, 2.0);
  EXPECT_DOUBLE_EQ(p.distance, 0.5);
  const auto inside = hc::project_on_segment(Vector2d(0.8, 1.0), f, s);
  EXPECT_NEAR(inside.gap, -0.2, 1e-15);
  EXPECT_DOUBLE_EQ(inside.eta, 0.5);
  const auto beyond = hc::project_on_segment(Vector2d(1.3, 2.4), f, s);  // eta past S: distance to S
  EXPECT_DOUBLE_EQ(beyond.eta, 1.2);
  EXPECT_NEAR(beyond.distance, 0.5, 1e-15);
}

TEST(ContactKinematics, TopFaceNormalPointsUp) {
  const auto p = hc::project_on_segment(Vector2d(0.5, 4.1), Vector2d(1, 4), Vector2d(0, 4));
  EXPECT_DOUBLE_EQ(p.normal.y(), 1.0);
  EXPECT_NEAR(p.gap, 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(p.eta, 0.5);
}

TEST(ContactKinematics, ClosestSegmentAroundTheBox) {
  const auto s = box();
  auto c = hc::closest_segment(s, Vector2d(1.2, 3.0));  // right face, upper segment
  EXPECT_EQ(c.segment, 1);
  EXPECT_NEAR(c.projection.gap, 0.2, 1e-15);
  c = hc::closest_segment(s, Vector2d(-1.1, 0.5));  // left face, lower segment (downwards: F = (-1,2))
  EXPECT_EQ(c.segment, 5);
  EXPECT_NEAR(c.projection.gap, 0.1, 1e-15);
  EXPECT_NEAR(c.projection.eta, 0.75, 1e-15);
  c = hc::closest_segment(s, Vector2d(0.9, 1.0));  // just inside the right face
  EXPECT_EQ(c.segment, 0);
  EXPECT_NEAR(c.projection.gap, -0.1, 1e-15);
}

TEST(ContactKinematics, CornersPickTheNearestFaceInsideAndTheFrontFaceOutside) {
  const auto s = box();
  // Inside the top right corner, nearer the top face than the right face: pushed out through the top.
  auto c = hc::closest_segment(s, Vector2d(0.9, 3.95));
  EXPECT_EQ(c.segment, 2);
  EXPECT_NEAR(c.projection.gap, -0.05, 1e-15);
  // Nearer the right face.
  c = hc::closest_segment(s, Vector2d(0.97, 3.9));
  EXPECT_EQ(c.segment, 1);
  EXPECT_NEAR(c.projection.gap, -0.03, 1e-15);
  // Outside the corner, in the wedge: both segments are closest at the vertex; the one the particle is most
  // in front of wins, and its eta leaves [0, 1] (kept unclamped so the tangential position is not moved).
  c = hc::closest_segment(s, Vector2d(1.3, 4.1));
  EXPECT_EQ(c.segment, 1);
  EXPECT_NEAR(c.projection.gap, 0.3, 1e-15);
  EXPECT_GT(c.projection.eta, 1.0);
  c = hc::closest_segment(s, Vector2d(1.1, 4.3));
  EXPECT_EQ(c.segment, 2);
  EXPECT_NEAR(c.projection.gap, 0.3, 1e-15);
  EXPECT_LT(c.projection.eta, 0.0);
}

TEST(Ssosd, RelocationLimitsAndMonotonicity) {
  const double layer = 2e-4;
  EXPECT_DOUBLE_EQ(hc::modified_overlap(0.0, layer), 0.0);  // nothing at the layer's edge
  EXPECT_DOUBLE_EQ(hc::relocated_gap(layer, layer), layer);
  EXPECT_NEAR(hc::relocated_gap(0.0, layer), layer / std::exp(1.0), 1e-18);
  EXPECT_GT(hc::relocated_gap(-50 * layer, layer), 0.0);  // never past the surface
  EXPECT_LT(hc::relocated_gap(-50 * layer, layer), 1e-20);
  double previous = -1.0;
  for (int k = -400; k <= 100; ++k) {
    const double g = k * layer / 100.0;
    const double moved = hc::relocated_gap(g, layer);
    EXPECT_GT(moved, previous) << g;  // monotone: the order of particles along the normal is kept
    EXPECT_GE(moved, g);              // pushed outwards only
    EXPECT_GT(moved, 0.0);
    EXPECT_LE(moved, layer);
    // Consistent with eq. 22 on the overlap o = L - g: new gap = g + o'.
    EXPECT_NEAR(moved, g + hc::modified_overlap(layer - g, layer), 1e-15 * layer * 50);
    previous = moved;
  }
  // Small penetration into the layer: o' = o^2 / (2 L) + O(o^3), second order: the layer is soft at its edge.
  const double o = 1e-3 * layer;
  EXPECT_NEAR(hc::modified_overlap(o, layer), o * o / (2 * layer), 1e-3 * o * o / layer);
  // Without a layer: plain contact, onto the surface.
  EXPECT_EQ(hc::relocated_gap(-1e-5, 0.0), 0.0);
  EXPECT_TRUE(hc::is_invader(-1e-12, 0.0));
  EXPECT_FALSE(hc::is_invader(0.0, 0.0));
  EXPECT_TRUE(hc::is_invader(0.5 * layer, layer));
  EXPECT_FALSE(hc::is_invader(layer, layer));
}

TEST(Ssosd, LayerThicknessFollowsEq23) {
  hc::SsosdParameters p;
  const double dt = 1.6e-5;
  p.layer_ratio = 20.0;
  EXPECT_DOUBLE_EQ(hc::layer_thickness(p, 0.6, dt), 20.0 * 0.6 * dt);
  const double l = hc::layer_thickness(p, 0.6, dt);
  EXPECT_GE(l / (0.6 * dt), 5.0);
  EXPECT_LE(l / (0.6 * dt), 50.0);
  // Still water: the floor keeps a layer.
  EXPECT_DOUBLE_EQ(hc::layer_thickness(p, 0.0, dt), 20.0 * p.velocity_floor * dt);
  p.enabled = false;
  EXPECT_EQ(hc::layer_thickness(p, 0.6, dt), 0.0);
  p.layer_ratio = 4.0;
  EXPECT_THROW(hc::validate(p), halfeti::UserError);
  p.layer_ratio = 51.0;
  EXPECT_THROW(hc::validate(p), halfeti::UserError);
  p.layer_ratio = 5.0;
  p.velocity_floor = 0.0;
  EXPECT_THROW(hc::validate(p), halfeti::UserError);
  p.velocity_floor = 0.05;
  EXPECT_NO_THROW(hc::validate(p));
}

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

hc::ConstraintTerms at(hc::ContactConstraint form, const Vec6& q, double eta, double target,
                       const Vector2d& lam) {
  return hc::evaluate_constraint(form, q.segment<2>(0), q.segment<2>(2), q.segment<2>(4), eta, target, lam);
}

// dc/dq and d2(lambda . c)/dq2 against central differences of c and of gradient^T lambda.
void check_against_differences(hc::ContactConstraint form, double target) {
  Vec6 q;
  q << 0.31, 0.52, 0.2, -0.1, 0.45, 1.3;  // particle, F, S: a tilted segment
  const Vector2d lambda(3.7, -1.9);
  const double eta = 0.37;
  const auto terms = at(form, q, eta, target, lambda);
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Vec6 qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    const auto tp = at(form, qp, eta, target, lambda), tm = at(form, qm, eta, target, lambda);
    for (int k = 0; k < terms.rows; ++k)
      EXPECT_NEAR(terms.gradient(k, j), (tp.value(k) - tm.value(k)) / (2 * h), 1e-8)
          << "row " << k << " q " << j;
    const Vec6 dforce = (hc::contact_forces(tp, lambda) - hc::contact_forces(tm, lambda)) / (2 * h);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(terms.hessian(i, j), dforce(i), 1e-7) << i << "," << j;
  }
  EXPECT_NEAR((terms.hessian - terms.hessian.transpose()).norm(), 0.0, 1e-12);
  // Action and reaction: the forces on particle, F and S sum to zero.
  const Vec6 f = hc::contact_forces(terms, lambda);
  EXPECT_NEAR((f.segment<2>(0) + f.segment<2>(2) + f.segment<2>(4)).norm(), 0.0, 1e-14);
}

}  // namespace

TEST(ContactConstraint, NormalFormMatchesFiniteDifferences) {
  check_against_differences(hc::ContactConstraint::kNormal, 0.0);
  check_against_differences(hc::ContactConstraint::kNormal, 0.05);
}

TEST(ContactConstraint, TiedFormMatchesFiniteDifferences) {
  check_against_differences(hc::ContactConstraint::kTied, 0.0);
  check_against_differences(hc::ContactConstraint::kTied, 0.05);
}

TEST(ContactConstraint, TiedWithZeroTargetIsTheContactPointItself) {
  const Vector2d f(0, 0), s(0, 2), xp(0.1, 0.5);
  const auto t = hc::evaluate_constraint(hc::ContactConstraint::kTied, xp, f, s, 0.25, 0.0, Vector2d::Zero());
  EXPECT_NEAR(t.value.x(), 0.1, 1e-15);  // overlap vector O of eq. 19: particle minus contact point
  EXPECT_NEAR(t.value.y(), 0.0, 1e-15);
  const auto n =
      hc::evaluate_constraint(hc::ContactConstraint::kNormal, xp, f, s, 0.0, 0.0, Vector2d::Zero());
  EXPECT_NEAR(n.value(0), 0.1, 1e-15);  // segment (0,0)->(0,2) faces +x: the particle is 0.1 in front of it
}

TEST(ContactKinematics, FastSearchEqualsTheFullScanWithinReach) {
  // A wavy 41-point polyline (runs of 8 segments); random points: within reach the fast search returns
  // exactly the full scan's contact point, beyond it nothing.
  hc::SurfacePolyline s;
  for (int k = 0; k <= 40; ++k)
    s.points.emplace_back(0.1 * std::sin(0.2 * k), 0.05 * k), s.nodes.push_back(k);
  for (int k = 39; k >= 0; --k)
    s.points.emplace_back(-0.1 + 0.1 * std::sin(0.2 * k), 0.05 * k), s.nodes.push_back(k);
  const double reach = 0.03;
  const hc::SurfaceSearch search(s, reach);
  std::srand(7);
  int within = 0;
  for (int n = 0; n < 20000; ++n) {
    const Vector2d x(-0.3 + 0.6 * std::rand() / RAND_MAX, -0.1 + 2.2 * std::rand() / RAND_MAX);
    const auto full = hc::closest_segment(s, x);
    const auto fast = search.closest_within_reach(x);
    if (full.projection.distance <= reach) {
      ++within;
      ASSERT_EQ(fast.segment, full.segment) << x.transpose();
      EXPECT_EQ(fast.projection.gap, full.projection.gap);
      EXPECT_EQ(fast.projection.eta, full.projection.eta);
    } else {
      EXPECT_EQ(fast.segment, -1);
    }
  }
  EXPECT_GT(within, 500);
}
