// The Q9 integrator: internal force against finite differences of the energy, tangent against finite
// differences of the internal force (every material, hypothesis and integration), and the patch test on
// distorted elements.
#include <gtest/gtest.h>

#include <random>

#include "halfeti/structure/q9_element.hpp"

namespace hs = halfeti::structure;

namespace {

// A distorted reference element (straight-sided quadrilateral, midside and centre nodes moved off their
// places).
hs::Q9Coordinates distorted_reference() {
  hs::Q9Coordinates x;
  const Eigen::Vector2d corner[4] = {{0.0, 0.0}, {2.0e-3, 0.2e-3}, {1.8e-3, 1.5e-3}, {-0.2e-3, 1.2e-3}};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double s = 0.5 * i, t = 0.5 * j;  // bilinear map of the corners
      x.row(i + 3 * j) = ((1 - s) * (1 - t) * corner[0] + s * (1 - t) * corner[1] + s * t * corner[2] +
                          (1 - s) * t * corner[3])
                             .transpose();
    }
  x(4, 0) += 0.1e-3;
  x(4, 1) -= 0.05e-3;
  x(1, 1) += 0.05e-3;
  return x;
}

// A large, non-affine deformation of the element.
hs::Q9Coordinates deformed(const hs::Q9Coordinates& x0) {
  hs::Q9Coordinates x = x0;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-0.1e-3, 0.1e-3);
  for (int a = 0; a < hs::kQ9Nodes; ++a) {
    const double px = x0(a, 0), py = x0(a, 1);
    x(a, 0) = 1.1 * px + 0.3 * py + d(rng);
    x(a, 1) = -0.1 * px + 0.9 * py + d(rng);
  }
  return x;
}

struct Case {
  hs::MaterialModel model;
  hs::PlaneHypothesis hypothesis;
  bool reduced;
};

class Q9Integrator : public ::testing::TestWithParam<Case> {};

TEST_P(Q9Integrator, ForceIsEnergyDerivativeAndTangentIsForceDerivative) {
  const auto [model, hyp, reduced] = GetParam();
  auto m = hs::make_material(model, 10e6, 0.49);
  hs::HyperelasticQ9 q9(*m, {hyp, reduced});
  const auto x0 = distorted_reference();
  const auto g = hs::HyperelasticQ9::reference_geometry(x0);
  const hs::Q9Coordinates x = deformed(x0) - x0;  // nodal displacements
  hs::Q9Vector f;
  hs::Q9Matrix k;
  q9.internal_force_and_tangent(g, x, f, k);
  hs::Q9Vector f_only;
  q9.internal_force(g, x, f_only);
  EXPECT_NEAR((f - f_only).norm(), 0.0, 1e-12 * f.norm());

  const double h = 1e-9;  // m (elements are mm in size)
  for (int dof = 0; dof < hs::kQ9Dofs; ++dof) {
    hs::Q9Coordinates xp = x, xm = x;
    xp(dof / 2, dof % 2) += h;
    xm(dof / 2, dof % 2) -= h;
    const double de = (q9.energy(g, xp) - q9.energy(g, xm)) / (2 * h);
    EXPECT_NEAR(de, f(dof), 1e-6 * f.norm()) << "dof " << dof;
    hs::Q9Vector fp, fm;
    q9.internal_force(g, xp, fp);
    q9.internal_force(g, xm, fm);
    const hs::Q9Vector column = (fp - fm) / (2 * h);
    EXPECT_NEAR((column - k.col(dof)).norm(), 0.0, 1e-6 * k.norm()) << "column " << dof;
  }
  EXPECT_NEAR((k - k.transpose()).norm(), 0.0, 1e-10 * k.norm());
}

INSTANTIATE_TEST_SUITE_P(
    AllVariants, Q9Integrator,
    ::testing::Values(Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStrain, true},
                      Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStrain, false},
                      Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStress, false},
                      Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStrain, true},
                      Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStrain, false},
                      Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStress, false}));

// The closed-form Neo-Hookean plane-strain kernel (the default path) against the general material path, at a
// strong deformation and at a vibration-size one (strains ~1e-6, where round-off of the stress matters): force
// and tangent agree to round-off, and the component-major tangent is the interleaved one reordered.
TEST(Q9, ClosedFormNeoHookeanEqualsGeneralPath) {
  auto m = hs::make_material(hs::MaterialModel::kNeoHookean, 10e6, 0.49);
  const auto x0 = distorted_reference();
  const auto g = hs::HyperelasticQ9::reference_geometry(x0);
  const hs::Q9Coordinates large = deformed(x0) - x0;
  for (bool reduced : {true, false})
    for (double scale : {1.0, 1e-5}) {
      const hs::Q9Coordinates u = scale * large;
      hs::HyperelasticQ9 fast(*m, {hs::PlaneHypothesis::kPlaneStrain, reduced, true});
      hs::HyperelasticQ9 general(*m, {hs::PlaneHypothesis::kPlaneStrain, reduced, false});
      hs::Q9Vector f_fast, f_general;
      hs::Q9Matrix k_fast, k_general, k_component_major;
      fast.internal_force_and_tangent(g, u, f_fast, k_fast);
      general.internal_force_and_tangent(g, u, f_general, k_general);
      EXPECT_LE((f_fast - f_general).norm(), 1e-12 * f_general.norm())
          << "reduced " << reduced << " scale " << scale;
      EXPECT_LE((k_fast - k_general).norm(), 1e-12 * k_general.norm())
          << "reduced " << reduced << " scale " << scale;
      hs::Q9Vector f_only;
      fast.internal_force(g, u, f_only);
      EXPECT_EQ((f_only - f_fast).norm(), 0.0);
      fast.internal_force_and_tangent_component_major(g, u, f_only, k_component_major);
      for (int a = 0; a < hs::kQ9Nodes; ++a)
        for (int b = 0; b < hs::kQ9Nodes; ++b)
          for (int i = 0; i < 2; ++i)
            for (int k = 0; k < 2; ++k)
              EXPECT_EQ(k_component_major(9 * i + a, 9 * k + b), k_fast(2 * a + i, 2 * b + k));
    }
}

TEST(Q9, MassIntegratesDensityTimesArea) {
  const auto x0 = distorted_reference();
  const auto g = hs::HyperelasticQ9::reference_geometry(x0);
  EXPECT_NEAR(hs::HyperelasticQ9::scalar_mass(g, 1150.0).sum(), 1150.0 * g.area, 1e-12 * 1150.0 * g.area);
}

TEST(Q9, RigidRotationIsStressFree) {
  const double youngs_modulus = 10e6;  // Pa
  auto m = hs::make_material(hs::MaterialModel::kNeoHookean, youngs_modulus, 0.45);
  hs::HyperelasticQ9 q9(*m, {});
  const auto x0 = distorted_reference();
  const auto g = hs::HyperelasticQ9::reference_geometry(x0);
  Eigen::Matrix2d r;
  const double th = 1.0;  // rad: large rotations must cost no energy (frame invariance)
  r << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);
  const hs::Q9Coordinates x = ((x0 * r.transpose()).rowwise() + Eigen::RowVector2d(0.01, -0.02)) - x0;
  hs::Q9Vector f;
  q9.internal_force(g, x, f);
  EXPECT_NEAR(q9.energy(g, x), 0.0, 1e-15);
  // Round-off only: the force scale is E times the element's side (10 MPa x 2 mm = 2e4 N/m), and the motion (a
  // 22 mm translation of a 2 mm element) loses about a digit in the displacement gradient; 1e-12 of the scale
  // (~5000 machine epsilons) holds under every optimisation level (1.05e-9 N/m measured at -O1, below 1e-9 at -O3).
  const double force_scale = youngs_modulus * 2.0e-3;  // the element's side: 2 mm
  EXPECT_NEAR(f.norm(), 0.0, 1e-12 * force_scale);
}

// Patch test: four distorted Q9 elements sharing an interior node; an affine motion of all nodes gives a
// constant F, so the interior nodes must be in equilibrium, and Newton from a perturbed interior must return
// to it.
TEST(Q9, PatchTestOnDistortedMesh) {
  for (auto model : {hs::MaterialModel::kNeoHookean, hs::MaterialModel::kStVenantKirchhoff}) {
    for (bool reduced : {true, false}) {
      auto m = hs::make_material(model, 10e6, 0.49);
      hs::HyperelasticQ9 q9(*m, {hs::PlaneHypothesis::kPlaneStrain, reduced});
      // 5 x 5 node grid, 2 x 2 elements, interior nodes jittered.
      std::vector<Eigen::Vector2d> nodes;
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> d(-0.15e-3, 0.15e-3);
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
          Eigen::Vector2d p(1e-3 * i, 1e-3 * j);
          if (i > 0 && i < 4 && j > 0 && j < 4) p += Eigen::Vector2d(d(rng), d(rng));
          nodes.push_back(p);
        }
      std::vector<std::array<int, 9>> elements;
      for (int ey = 0; ey < 2; ++ey)
        for (int ex = 0; ex < 2; ++ex) {
          std::array<int, 9> e;
          for (int b = 0; b < 3; ++b)
            for (int a = 0; a < 3; ++a) e[a + 3 * b] = (2 * ex + a) + 5 * (2 * ey + b);
          elements.push_back(e);
        }
      std::vector<hs::Q9Geometry> geo;
      for (const auto& e : elements) {
        hs::Q9Coordinates x;
        for (int a = 0; a < 9; ++a) x.row(a) = nodes[e[a]].transpose();
        geo.push_back(hs::HyperelasticQ9::reference_geometry(x));
      }
      Eigen::Matrix2d affine;
      affine << 1.2, 0.1, -0.05, 0.85;
      std::vector<Eigen::Vector2d> x(nodes.size());
      for (std::size_t n = 0; n < nodes.size(); ++n) x[n] = affine * nodes[n];
      std::vector<bool> interior(nodes.size());
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) interior[i + 5 * j] = i > 0 && i < 4 && j > 0 && j < 4;

      auto assemble = [&](Eigen::VectorXd& r, Eigen::MatrixXd& k) {
        r = Eigen::VectorXd::Zero(2 * nodes.size());
        k = Eigen::MatrixXd::Zero(2 * nodes.size(), 2 * nodes.size());
        for (std::size_t e = 0; e < elements.size(); ++e) {
          hs::Q9Coordinates xe;
          for (int a = 0; a < 9; ++a) xe.row(a) = (x[elements[e][a]] - nodes[elements[e][a]]).transpose();
          hs::Q9Vector f;
          hs::Q9Matrix ke;
          q9.internal_force_and_tangent(geo[e], xe, f, ke);
          for (int a = 0; a < 9; ++a) {
            r.segment<2>(2 * elements[e][a]) += f.segment<2>(2 * a);
            for (int b = 0; b < 9; ++b)
              k.block<2, 2>(2 * elements[e][a], 2 * elements[e][b]) += ke.block<2, 2>(2 * a, 2 * b);
          }
        }
        for (std::size_t n = 0; n < nodes.size(); ++n)
          if (!interior[n]) {
            r.segment<2>(2 * n).setZero();
            k.middleRows<2>(2 * n).setZero();
            k.middleCols<2>(2 * n).setZero();
            k.block<2, 2>(2 * n, 2 * n).setIdentity();
          }
      };
      Eigen::VectorXd r;
      Eigen::MatrixXd k;
      assemble(r, k);
      EXPECT_LT(r.norm(), 1e-8) << "interior force of an affine motion";  // N/m; stresses are ~1e6 Pa

      const std::vector<Eigen::Vector2d> exact = x;
      for (std::size_t n = 0; n < nodes.size(); ++n)
        if (interior[n]) x[n] += Eigen::Vector2d(d(rng), d(rng)) * 0.5;
      for (int it = 0; it < 20; ++it) {
        assemble(r, k);
        if (r.norm() < 1e-9) break;
        const Eigen::VectorXd du = k.ldlt().solve(-r);
        for (std::size_t n = 0; n < nodes.size(); ++n) x[n] += du.segment<2>(2 * n);
      }
      for (std::size_t n = 0; n < nodes.size(); ++n) EXPECT_NEAR((x[n] - exact[n]).norm(), 0.0, 1e-12);
    }
  }
}

TEST(Q9, ShapeFunctionsPartitionUnity) {
  Eigen::Matrix<double, 9, 1> n;
  Eigen::Matrix<double, 9, 2> dn;
  hs::q9_shape(0.3, -0.7, n, dn);
  EXPECT_NEAR(n.sum(), 1.0, 1e-14);
  EXPECT_NEAR(dn.col(0).sum(), 0.0, 1e-14);
  EXPECT_NEAR(dn.col(1).sum(), 0.0, 1e-14);
}

}  // namespace
