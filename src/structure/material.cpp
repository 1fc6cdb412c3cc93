#include "halfeti/structure/material.hpp"

#include <algorithm>
#include <cmath>

#include "halfeti/core/error.hpp"

namespace halfeti::structure {

namespace {

// Voigt index -> tensor indices, order [11, 22, 12, 33].
constexpr int kVoigtI[4] = {0, 1, 0, 2};
constexpr int kVoigtJ[4] = {0, 1, 1, 2};

Eigen::Matrix3d full_3d(const Eigen::Matrix2d& in_plane, double out_of_plane) {
  Eigen::Matrix3d full = Eigen::Matrix3d::Zero();
  full.topLeftCorner<2, 2>() = in_plane;
  full(2, 2) = out_of_plane;
  return full;
}

Eigen::Vector4d to_voigt(const Eigen::Matrix3d& s) {
  return {s(0, 0), s(1, 1), s(0, 1), s(2, 2)};
}

// D(p, q) = a A_IJ A_KL + b (B_IK B_JL + B_IL B_JK) for symmetric 3x3 A, B: the two shapes every tangent
// below has.
Eigen::Matrix4d tensor_tangent(double a, const Eigen::Matrix3d& A, double b, const Eigen::Matrix3d& B) {
  Eigen::Matrix4d d;
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) {
      const int i = kVoigtI[p], j = kVoigtJ[p], k = kVoigtI[q], l = kVoigtJ[q];
      d(p, q) = a * A(i, j) * A(k, l) + b * (B(i, k) * B(j, l) + B(i, l) * B(j, k));
    }
  return d;
}

}  // namespace

Material::Material(double youngs_modulus, double poisson_ratio)
    : youngs_modulus_(youngs_modulus), poisson_ratio_(poisson_ratio) {
  if (!(youngs_modulus > 0.0))
    HALFETI_USER_ERROR("structure material: Young's modulus " << youngs_modulus << " Pa must be positive");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    HALFETI_USER_ERROR("structure material: Poisson ratio " << poisson_ratio << " must lie in (-1, 0.5)");
  mu_ = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  lambda_ = youngs_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
}

MaterialResponse NeoHookean::evaluate(const Eigen::Matrix2d& e, double e33, EnergyPart part) const {
  // det C = det(I + 2E) = (1 + 2 tr e + 4 det e)(1 + 2 e33) in 2D + 1: taken through log1p, ln J keeps its
  // digits.
  const double det_in_plane_minus_one = 2.0 * e.trace() + 4.0 * e.determinant();
  if (!(det_in_plane_minus_one > -1.0) || !(e33 > -0.5))
    HALFETI_NUMERICAL_ERROR("Neo-Hookean point inverted: det C <= 0 (E = ["
                            << e(0, 0) << ", " << e(1, 1) << ", " << e(0, 1) << "], E33 = " << e33 << ")");
  const double log_j = 0.5 * (std::log1p(det_in_plane_minus_one) + std::log1p(2.0 * e33));
  const Eigen::Matrix3d strain = full_3d(e, e33);
  const Eigen::Matrix3d c_inv = (Eigen::Matrix3d::Identity() + 2.0 * strain).inverse();
  const bool shear = part != EnergyPart::kBulk, bulk = part != EnergyPart::kShear;
  const double mu = shear ? this->mu() : 0.0, lambda = bulk ? this->lambda() : 0.0;

  MaterialResponse r;
  r.energy = mu * strain.trace() - mu * log_j + 0.5 * lambda * log_j * log_j;  // I1 - 3 = 2 tr E
  // I - C^-1 = C^-1 (C - I) = 2 C^-1 E: no cancellation at small strain.
  r.stress = to_voigt(2.0 * mu * c_inv * strain + lambda * log_j * c_inv);
  // D = 2 dS/dC = lambda C^-1 (x) C^-1 + (mu - lambda ln J)(C^-1_IK C^-1_JL + C^-1_IL C^-1_JK)
  r.tangent = tensor_tangent(lambda, c_inv, mu - lambda * log_j, c_inv);
  return r;
}

MaterialResponse StVenantKirchhoff::evaluate(const Eigen::Matrix2d& e2, double e33, EnergyPart part) const {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d e = full_3d(e2, e33);
  const bool shear = part != EnergyPart::kBulk, bulk = part != EnergyPart::kShear;
  const double mu = shear ? this->mu() : 0.0, lambda = bulk ? this->lambda() : 0.0;
  const double tr_e = e.trace();

  MaterialResponse r;
  r.energy = 0.5 * lambda * tr_e * tr_e + mu * (e.array() * e.array()).sum();
  r.stress = to_voigt(lambda * tr_e * identity + 2.0 * mu * e);
  r.tangent = tensor_tangent(lambda, identity, mu, identity);
  return r;
}

std::unique_ptr<Material> make_material(MaterialModel model, double youngs_modulus, double poisson_ratio) {
  switch (model) {
    case MaterialModel::kNeoHookean:
      return std::make_unique<NeoHookean>(youngs_modulus, poisson_ratio);
    case MaterialModel::kStVenantKirchhoff:
      return std::make_unique<StVenantKirchhoff>(youngs_modulus, poisson_ratio);
  }
  HALFETI_CHECK(false, "unknown material model");
}

MaterialModel parse_material_model(const std::string& name) {
  if (name == "neo_hookean") return MaterialModel::kNeoHookean;
  if (name == "st_venant_kirchhoff") return MaterialModel::kStVenantKirchhoff;
  HALFETI_USER_ERROR("structure.material.model: unknown '" << name
                                                           << "' (known: neo_hookean, st_venant_kirchhoff)");
}

PlaneHypothesis parse_plane_hypothesis(const std::string& name) {
  if (name == "plane_strain") return PlaneHypothesis::kPlaneStrain;
  if (name == "plane_stress") return PlaneHypothesis::kPlaneStress;
  HALFETI_USER_ERROR("structure.material.hypothesis: unknown '" << name
                                                                << "' (known: plane_strain, plane_stress)");
}

std::string to_string(MaterialModel model) {
  return model == MaterialModel::kNeoHookean ? "neo_hookean" : "st_venant_kirchhoff";
}

std::string to_string(PlaneHypothesis hypothesis) {
  return hypothesis == PlaneHypothesis::kPlaneStrain ? "plane_strain" : "plane_stress";
}

PlaneResponse plane_response(const Material& material, const Eigen::Matrix2d& e, PlaneHypothesis hypothesis,
                             EnergyPart part) {
  PlaneResponse out;
  MaterialResponse r;
  double e33 = 0.0;
  if (hypothesis == PlaneHypothesis::kPlaneStrain) {
    r = material.evaluate(e, 0.0, part);
    out.tangent = r.tangent.topLeftCorner<3, 3>();
  } else {
    HALFETI_CHECK(part == EnergyPart::kAll,
                  "plane stress has no volumetric locking: integrate the whole energy");
    // Newton on S33(E33) = 0, dS33/dE33 = D33, from E33 = 0.
    const double scale = material.mu() + material.lambda();
    for (int it = 0;; ++it) {
      r = material.evaluate(e, e33, part);
      if (std::abs(r.stress(3)) <= 1e-13 * scale * std::max(1.0, e.norm())) break;
      if (it == 50)
        HALFETI_NUMERICAL_ERROR(
            "plane stress: S33 = 0 not reached at E33 = " << e33 << " (S33 = " << r.stress(3) << " Pa)");
      const double next = e33 - r.stress(3) / r.tangent(3, 3);
      e33 = next > -0.5 ? next : 0.5 * (e33 - 0.5);  // keep C33 = 1 + 2 E33 positive
    }
    out.tangent = r.tangent.topLeftCorner<3, 3>() -
                  r.tangent.topRightCorner<3, 1>() * r.tangent.bottomLeftCorner<1, 3>() / r.tangent(3, 3);
  }
  out.c33 = 1.0 + 2.0 * e33;
  out.energy = r.energy;
  out.stress = r.stress.head<3>();
  out.s33 = r.stress(3);
  return out;
}

Eigen::Matrix2d green_lagrange(const Eigen::Matrix2d& h) {
  return 0.5 * (h + h.transpose() + h.transpose() * h);
}

Eigen::Vector4d cauchy_stress(const Eigen::Matrix2d& f, double f33, const Eigen::Vector4d& s) {
  Eigen::Matrix2d s2;
  s2 << s(0), s(2), s(2), s(1);
  const double j = f.determinant() * f33;
  const Eigen::Matrix2d sigma = f * s2 * f.transpose() / j;
  return {sigma(0, 0), sigma(1, 1), sigma(0, 1), f33 * f33 * s(3) / j};
}

double von_mises(const Eigen::Vector4d& t) {
  const double a = t(0) - t(1), b = t(1) - t(3), d = t(3) - t(0);
  return std::sqrt(0.5 * (a * a + b * b + d * d) + 3.0 * t(2) * t(2));
}

}  // namespace halfeti::structure
