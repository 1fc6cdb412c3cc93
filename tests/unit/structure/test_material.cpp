// Materials at a point: stress against finite differences of the energy, tangent against finite differences
// of the stress, and the small-strain limit against linear elasticity.
#include <gtest/gtest.h>

#include "halfeti/core/error.hpp"
#include "halfeti/structure/material.hpp"

namespace hs = halfeti::structure;

namespace {

// Green-Lagrange strain of a deformation large enough to make the nonlinear terms matter (stretches of
// 0.7-1.3, shear 0.25).
Eigen::Matrix2d sample_strain() {
  Eigen::Matrix2d h;
  h << 0.25, 0.25, -0.15, -0.2;
  return hs::green_lagrange(h);
}

// E perturbed by h in Voigt strain component k (engineering shear: dE_v(2) = 2 dE12).
Eigen::Matrix2d perturb(Eigen::Matrix2d e, int k, double h) {
  if (k == 0) e(0, 0) += h;
  if (k == 1) e(1, 1) += h;
  if (k == 2) e(0, 1) += 0.5 * h, e(1, 0) += 0.5 * h;
  return e;
}

struct Case {
  hs::MaterialModel model;
  hs::PlaneHypothesis hypothesis;
  hs::EnergyPart part;
};

class MaterialPoint : public ::testing::TestWithParam<Case> {};

TEST_P(MaterialPoint, StressIsEnergyDerivative) {
  const auto [model, hyp, part] = GetParam();
  auto m = hs::make_material(model, 10e6, 0.45);
  const Eigen::Matrix2d c = sample_strain();  // E
  const auto r = hs::plane_response(*m, c, hyp, part);
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    const double fd = (hs::plane_response(*m, perturb(c, k, h), hyp, part).energy -
                       hs::plane_response(*m, perturb(c, k, -h), hyp, part).energy) /
                      (2 * h);
    EXPECT_NEAR(fd, r.stress(k), 1e-6 * r.stress.norm() + 1e-3) << "component " << k;
  }
}

TEST_P(MaterialPoint, TangentIsStressDerivative) {
  const auto [model, hyp, part] = GetParam();
  auto m = hs::make_material(model, 10e6, 0.45);
  const Eigen::Matrix2d c = sample_strain();  // E
  const auto r = hs::plane_response(*m, c, hyp, part);
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d fd = (hs::plane_response(*m, perturb(c, k, h), hyp, part).stress -
                                hs::plane_response(*m, perturb(c, k, -h), hyp, part).stress) /
                               (2 * h);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(fd(i), r.tangent(i, k), 1e-6 * r.tangent.norm()) << "D(" << i << "," << k << ")";
  }
  EXPECT_NEAR((r.tangent - r.tangent.transpose()).norm(), 0.0, 1e-12 * r.tangent.norm());
}

INSTANTIATE_TEST_SUITE_P(
    AllMaterials, MaterialPoint,
    ::testing::Values(
        Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStrain, hs::EnergyPart::kAll},
        Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStrain, hs::EnergyPart::kShear},
        Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStrain, hs::EnergyPart::kBulk},
        Case{hs::MaterialModel::kNeoHookean, hs::PlaneHypothesis::kPlaneStress, hs::EnergyPart::kAll},
        Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStrain, hs::EnergyPart::kAll},
        Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStrain, hs::EnergyPart::kBulk},
        Case{hs::MaterialModel::kStVenantKirchhoff, hs::PlaneHypothesis::kPlaneStress,
             hs::EnergyPart::kAll}));

TEST(Material, SmallStrainLimitIsLinearElasticity) {
  const double e = 10e6, nu = 0.3;
  for (auto model : {hs::MaterialModel::kNeoHookean, hs::MaterialModel::kStVenantKirchhoff}) {
    auto m = hs::make_material(model, e, nu);
    const auto strain = hs::plane_response(*m, Eigen::Matrix2d::Zero(), hs::PlaneHypothesis::kPlaneStrain);
    const double f = e / ((1 + nu) * (1 - 2 * nu));
    EXPECT_NEAR(strain.tangent(0, 0), f * (1 - nu), 1e-6 * e);
    EXPECT_NEAR(strain.tangent(0, 1), f * nu, 1e-6 * e);
    EXPECT_NEAR(strain.tangent(2, 2), e / (2 * (1 + nu)), 1e-6 * e);
    EXPECT_NEAR(strain.stress.norm(), 0.0, 1e-9 * e);
    const auto stress = hs::plane_response(*m, Eigen::Matrix2d::Zero(), hs::PlaneHypothesis::kPlaneStress);
    EXPECT_NEAR(stress.tangent(0, 0), e / (1 - nu * nu), 1e-6 * e);
    EXPECT_NEAR(stress.tangent(0, 1), nu * e / (1 - nu * nu), 1e-6 * e);
    EXPECT_NEAR(stress.s33, 0.0, 1e-6);
  }
}

TEST(Material, PlaneStressThinsUnderUniaxialTension) {
  auto m = hs::make_material(hs::MaterialModel::kNeoHookean, 10e6, 0.45);
  Eigen::Matrix2d e = Eigen::Matrix2d::Zero();
  e(0, 0) = 0.5 * (1.2 * 1.2 - 1.0);
  const auto r = hs::plane_response(*m, e, hs::PlaneHypothesis::kPlaneStress);
  EXPECT_LT(r.c33, 1.0);
  EXPECT_NEAR(r.s33, 0.0, 1e-4);
}

// At the strains of a vibrating plate the stress must keep its digits: compare with the linear limit.
TEST(Material, SmallStrainStressKeepsItsDigits) {
  auto m = hs::make_material(hs::MaterialModel::kNeoHookean, 10e6, 0.45);
  Eigen::Matrix2d e;
  e << 1e-7, 3e-8, 3e-8, -2e-8;
  const auto r = hs::plane_response(*m, e, hs::PlaneHypothesis::kPlaneStrain);
  const Eigen::Vector3d linear = r.tangent * Eigen::Vector3d(e(0, 0), e(1, 1), 2 * e(0, 1));
  EXPECT_NEAR((r.stress - linear).norm(), 0.0, 1e-6 * linear.norm());  // nonlinear terms ~1e-7 relative
}

TEST(Material, NamesRoundTrip) {
  for (auto m : {hs::MaterialModel::kNeoHookean, hs::MaterialModel::kStVenantKirchhoff})
    EXPECT_EQ(hs::parse_material_model(hs::to_string(m)), m);
  for (auto h : {hs::PlaneHypothesis::kPlaneStrain, hs::PlaneHypothesis::kPlaneStress})
    EXPECT_EQ(hs::parse_plane_hypothesis(hs::to_string(h)), h);
  EXPECT_THROW(hs::parse_material_model("mooney"), halfeti::UserError);
}

TEST(Material, RejectsBadConstants) {
  EXPECT_THROW(hs::NeoHookean(-1.0, 0.3), halfeti::UserError);
  EXPECT_THROW(hs::NeoHookean(1e6, 0.5), halfeti::UserError);
}

TEST(Material, VonMisesOfUniaxialStressIsThatStress) {
  EXPECT_NEAR(hs::von_mises(Eigen::Vector4d(5.0, 0.0, 0.0, 0.0)), 5.0, 1e-12);
  EXPECT_NEAR(hs::von_mises(Eigen::Vector4d(0.0, 0.0, 2.0, 0.0)), 2.0 * std::sqrt(3.0), 1e-12);
}

}  // namespace
