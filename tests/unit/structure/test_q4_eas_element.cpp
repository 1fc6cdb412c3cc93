// The Q4 enhanced-strain integrator (Q1/E4, Simo & Armero 1992): condensed internal force against finite
// differences of the condensed energy, consistent condensed tangent against finite differences of the condensed
// force (the local solve of the enhanced parameters inside every evaluation), both materials and hypotheses, on
// a distorted element under a strong non-affine deformation; closed-form kernel = general path; patch test and
// rigid rotation.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "halfeti/structure/q4_eas_element.hpp"

namespace hs = halfeti::structure;

namespace {

hs::Q4Coordinates distorted_reference() {
  hs::Q4Coordinates x;  // tensor order: (-1,-1), (1,-1), (-1,1), (1,1)
  x << 0.0, 0.0, 2.0e-3, 0.2e-3, -0.2e-3, 1.2e-3, 1.8e-3, 1.5e-3;
  return x;
}

// A large non-affine deformation (stretch, shear, rotation and random nodal moves of 5 % of the size).
hs::Q4Coordinates displacement_of(const hs::Q4Coordinates& x0) {
  hs::Q4Coordinates u;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-0.1e-3, 0.1e-3);
  for (int a = 0; a < hs::kQ4Nodes; ++a) {
    const double px = x0(a, 0), py = x0(a, 1);
    u(a, 0) = 0.1 * px + 0.3 * py + d(rng);
    u(a, 1) = -0.1 * px - 0.1 * py + d(rng);
  }
  return u;
}

struct Case {
  hs::MaterialModel model;
  hs::PlaneHypothesis hypothesis;
  bool closed_form;
};

class Q4EasIntegrator : public ::testing::TestWithParam<Case> {};

// Tolerances: central differences with h = 1e-9 m on 2 mm elements have a truncation error ~ (h/size)^2 ~ 1e-12
// and a round-off error ~ 1e-16 |f| / h * size ~ 1e-10 of the entries; 1e-6 of the norms leaves a wide margin,
// while leaving out the condensation term K_ua K_aa^-1 K_au fails by orders of magnitude (measured: 5-14 % of
// the norm of K at this deformation; with it 2e-11 to 1e-10).
TEST_P(Q4EasIntegrator, CondensedForceIsEnergyDerivativeAndTangentIsForceDerivative) {
  const auto [model, hyp, closed_form] = GetParam();
  auto m = hs::make_material(model, 10e6, 0.49);
  hs::HyperelasticQ4Eas q4(*m, {hyp, closed_form});
  const auto x0 = distorted_reference();
  const auto g = hs::HyperelasticQ4Eas::reference_geometry(x0);
  const hs::Q4Coordinates u = displacement_of(x0);
  hs::EasParameters alpha = hs::EasParameters::Zero();
  hs::Q4Vector f;
  hs::Q4Matrix k;
  q4.internal_force_and_tangent(g, u, alpha, f, k);
  EXPECT_GT(q4.last_local_iterations(), 0);
  EXPECT_GT(alpha.norm(), 1e-6 * g.size) << "the enhanced modes must be active under this deformation";
  const hs::EasParameters solved = alpha;
  hs::Q4Vector f_only;
  hs::EasParameters alpha_only = hs::EasParameters::Zero();
  q4.internal_force(g, u, alpha_only, f_only);
  EXPECT_LE((f - f_only).norm(), 1e-12 * f.norm());

  const double h = 1e-9;
  double worst_force = 0.0, worst_tangent = 0.0;
  for (int dof = 0; dof < hs::kQ4Dofs; ++dof) {
    hs::Q4Coordinates up = u, um = u;
    up(dof / 2, dof % 2) += h;
    um(dof / 2, dof % 2) -= h;
    const double de = (q4.energy(g, up, solved) - q4.energy(g, um, solved)) / (2 * h);
    EXPECT_NEAR(de, f(dof), 1e-6 * f.norm()) << "dof " << dof;
    hs::Q4Vector fp, fm;
    hs::EasParameters ap = solved, am = solved;
    q4.internal_force(g, up, ap, fp);
    q4.internal_force(g, um, am, fm);
    const hs::Q4Vector column = (fp - fm) / (2 * h);
    EXPECT_LE((column - k.col(dof)).norm(), 1e-6 * k.norm()) << "column " << dof;
    worst_force = std::max(worst_force, std::abs(de - f(dof)) / f.norm());
    worst_tangent = std::max(worst_tangent, (column - k.col(dof)).norm() / k.norm());
  }
  std::printf(
      "%s %s %s: |f - dE/du| / |f| <= %.1e, |K - df/du| / |K| <= %.1e (columns), %d local iterations from "
      "0\n",
      hs::to_string(model).c_str(), hs::to_string(hyp).c_str(), closed_form ? "closed form" : "general",
      worst_force, worst_tangent, q4.last_local_iterations());
  EXPECT_LE((k - k.transpose()).norm(), 1e-10 * k.norm());

  // d alpha / du by finite differences of the solved alpha.
  hs::Q4Matrix cm;
  hs::EasUpdate update;
  hs::EasParameters a0 = hs::EasParameters::Zero();
  q4.internal_force_and_tangent_component_major(g, u, a0, f, cm, &update);
  for (int dof = 0; dof < hs::kQ4Dofs; ++dof) {
    const int node = dof % hs::kQ4Nodes, comp = dof / hs::kQ4Nodes;  // component-major column
    hs::Q4Coordinates up = u, um = u;
    up(node, comp) += h;
    um(node, comp) -= h;
    hs::EasParameters ap = solved, am = solved;
    hs::Q4Vector scratch;
    q4.internal_force(g, up, ap, scratch);
    q4.internal_force(g, um, am, scratch);
    EXPECT_LE(((ap - am) / (2 * h) - update.col(dof)).norm(), 1e-6 * update.norm()) << "column " << dof;
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllVariants, Q4EasIntegrator,
    ::testing::Values(Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStrain, true},
                      Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStrain, false},
                      Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStress, false},
                      Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStrain, false},
                      Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStress, false}));

// The closed-form Neo-Hookean kernel against the general material path, strong and vibration-size (1e-5 of it).
TEST(Q4Eas, ClosedFormNeoHookeanEqualsGeneralPath) {
  auto m = hs::make_material(hs::MaterialModel::kNeoHookean, 10e6, 0.45);
  const auto x0 = distorted_reference();
  const auto g = hs::HyperelasticQ4Eas::reference_geometry(x0);
  for (double scale : {1.0, 1e-5}) {
    const hs::Q4Coordinates u = scale * displacement_of(x0);
    hs::HyperelasticQ4Eas fast(*m, {hs::PlaneHypothesis::kPlaneStrain, true});
    hs::HyperelasticQ4Eas general(*m, {hs::PlaneHypothesis::kPlaneStrain, false});
    hs::EasParameters a1 = hs::EasParameters::Zero(), a2 = hs::EasParameters::Zero();
    hs::Q4Vector f1, f2;
    hs::Q4Matrix k1, k2;
    fast.internal_force_and_tangent(g, u, a1, f1, k1);
    general.internal_force_and_tangent(g, u, a2, f2, k2);
    EXPECT_LE((f1 - f2).norm(), 1e-10 * f2.norm()) << "scale " << scale;
    EXPECT_LE((k1 - k2).norm(), 1e-10 * k2.norm()) << "scale " << scale;
    EXPECT_LE((a1 - a2).norm(), 1e-8 * a2.norm()) << "scale " << scale;
  }
}

// Patch test: an affine motion (strong: 20 % stretch, 30 % shear) of a distorted 2 x 2 patch. Every element has
// a homogeneous F with alpha = 0 (the modes integrate to zero), so the interior node is in equilibrium.
TEST(Q4Eas, PatchTestAffineMotionOfDistortedPatch) {
  auto m = hs::make_material(hs::MaterialModel::kNeoHookean, 10e6, 0.49);
  hs::HyperelasticQ4Eas q4(*m, {hs::PlaneHypothesis::kPlaneStrain, true});
  // 3 x 3 nodes, the interior one moved off centre, the edge midpoints moved too.
  Eigen::Vector2d nodes[9];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) nodes[i + 3 * j] = Eigen::Vector2d(1.5e-3 * i, 1.3e-3 * j);
  nodes[4] += Eigen::Vector2d(0.4e-3, -0.3e-3);
  nodes[1] += Eigen::Vector2d(0.2e-3, 0.1e-3);
  nodes[5] += Eigen::Vector2d(-0.1e-3, 0.25e-3);
  Eigen::Matrix2d a;
  a << 0.2, 0.3, -0.1, -0.15;
  const Eigen::Vector2d c(1e-4, -2e-4);
  Eigen::Vector2d interior = Eigen::Vector2d::Zero();
  double scale = 0.0;
  for (int ey = 0; ey < 2; ++ey)
    for (int ex = 0; ex < 2; ++ex) {
      const int ids[4] = {ex + 3 * ey, ex + 1 + 3 * ey, ex + 3 * (ey + 1), ex + 1 + 3 * (ey + 1)};
      hs::Q4Coordinates x, u;
      for (int k = 0; k < 4; ++k) {
        x.row(k) = nodes[ids[k]].transpose();
        u.row(k) = (a * nodes[ids[k]] + c).transpose();
      }
      const auto g = hs::HyperelasticQ4Eas::reference_geometry(x);
      hs::EasParameters alpha =
          hs::EasParameters::Constant(1e-5);  // a wrong start: the local solve returns 0
      hs::Q4Vector f;
      q4.internal_force(g, u, alpha, f);
      EXPECT_LE(alpha.norm(), 1e-12 * g.size);
      scale = std::max(scale, f.norm());
      for (int k = 0; k < 4; ++k)
        if (ids[k] == 4) interior += f.segment<2>(2 * k);
    }
  EXPECT_GT(scale, 0.0);
  // Round-off of the sum of four element forces: 1e-12 relative.
  EXPECT_LE(interior.norm(), 1e-12 * scale);
}

// A rigid rotation (60 degrees) plus translation is stress-free: zero force, zero energy, alpha stays zero.
TEST(Q4Eas, RigidRotationIsStressFree) {
  for (auto model : {hs::MaterialModel::kNeoHookean, hs::MaterialModel::kStVenantKirchhoff}) {
    auto m = hs::make_material(model, 10e6, 0.45);
    hs::HyperelasticQ4Eas q4(*m, {hs::PlaneHypothesis::kPlaneStrain, true});
    const auto x0 = distorted_reference();
    const auto g = hs::HyperelasticQ4Eas::reference_geometry(x0);
    const double t = M_PI / 3;
    Eigen::Matrix2d r;
    r << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
    hs::Q4Coordinates u;
    for (int a = 0; a < 4; ++a)
      u.row(a) = ((r - Eigen::Matrix2d::Identity()) * x0.row(a).transpose()).transpose();
    u.col(0).array() += 3e-3;
    hs::EasParameters alpha = hs::EasParameters::Zero();
    hs::Q4Vector f;
    hs::Q4Matrix k;
    q4.internal_force_and_tangent(g, u, alpha, f, k);
    // Forces of a 1 % strain would be ~ E 1e-2 size = 200 N/m: round-off of R^T R - I gives ~1e-16 of E size.
    EXPECT_LE(f.norm(), 1e-7) << hs::to_string(model);
    EXPECT_LE(alpha.norm(), 1e-14);
    EXPECT_LE(std::abs(q4.energy(g, u, alpha)), 1e-15);
  }
}

}  // namespace
