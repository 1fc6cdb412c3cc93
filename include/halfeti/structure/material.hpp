// Hyperelastic materials at a point (the first of the three MFEM-style layers: material -> element integrator
// -> global assembly). A material gives the strain energy density W, the second Piola-Kirchhoff stress S and
// the material tangent D = dS/dE at a Green-Lagrange strain E = (C - I)/2 that has an in-plane 2x2 block and
// an out-of-plane component E33 (no out-of-plane shear: the plate is 2D, per unit depth). The input is E, not
// C: at the strains of a vibrating plate (1e-6) C - I and ln J computed from C lose ten digits, and lambda ln
// J (lambda = 3e7 Pa for nu = 0.45) would put a round-off floor under the Newton residual.
//
// Voigt order everywhere: [11, 22, 12, 33]; strains with engineering shear, E_v = [E11, E22, 2 E12, E33], so
// that dS_v = D dE_v with D symmetric.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

namespace halfeti::structure {

// Out-of-plane hypothesis of the 2D solid.
enum class PlaneHypothesis {
  kPlaneStrain,  // F33 = 1 (a plate as deep as the tank: the default)
  kPlaneStress,  // S33 = 0, F33 solved at every point
};

// The Lame split of the energy: W = W_shear(mu) + W_bulk(lambda). The element integrates the bulk part with
// reduced quadrature to avoid volumetric locking near nu = 0.5 (selective reduced integration).
enum class EnergyPart { kAll, kShear, kBulk };

struct MaterialResponse {
  double energy = 0.0;      // W per unit reference volume [J/m^3]
  Eigen::Vector4d stress;   // S in Voigt [11, 22, 12, 33] [Pa]
  Eigen::Matrix4d tangent;  // D = dS/dE_v [Pa]
};

class Material {
 public:
  // E > 0 [Pa], -1 < nu < 0.5. Lame constants of the 3D material (plane strain/stress come from C33).
  Material(double youngs_modulus, double poisson_ratio);
  virtual ~Material() = default;

  virtual std::string name() const = 0;
  // e: in-plane block of E; e33 = (F33^2 - 1)/2. Throws NumericalError if det C <= 0 (an inverted point).
  virtual MaterialResponse evaluate(const Eigen::Matrix2d& e, double e33, EnergyPart part) const = 0;

  double mu() const { return mu_; }
  double lambda() const { return lambda_; }
  double youngs_modulus() const { return youngs_modulus_; }
  double poisson_ratio() const { return poisson_ratio_; }

 private:
  double youngs_modulus_, poisson_ratio_, mu_, lambda_;
};

// Compressible Neo-Hookean (Simo & Pister / Bonet & Wood form):
//   W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,  S = mu (I - C^-1) + lambda ln J C^-1.
class NeoHookean final : public Material {
 public:
  using Material::Material;
  std::string name() const override { return "neo_hookean"; }
  MaterialResponse evaluate(const Eigen::Matrix2d& e, double e33, EnergyPart part) const override;
};

// St. Venant-Kirchhoff: W = lambda/2 (tr E)^2 + mu E:E,  S = lambda tr E I + 2 mu E. Fine for moderate
// strains; unstable in strong compression (it softens), which is why Neo-Hookean is the default.
class StVenantKirchhoff final : public Material {
 public:
  using Material::Material;
  std::string name() const override { return "st_venant_kirchhoff"; }
  MaterialResponse evaluate(const Eigen::Matrix2d& e, double e33, EnergyPart part) const override;
};

enum class MaterialModel { kNeoHookean, kStVenantKirchhoff };
std::unique_ptr<Material> make_material(MaterialModel model, double youngs_modulus, double poisson_ratio);

// Names as a scene writes them: "neo_hookean", "st_venant_kirchhoff"; "plane_strain", "plane_stress".
// Unknown names are UserErrors listing the known ones.
MaterialModel parse_material_model(const std::string& name);
PlaneHypothesis parse_plane_hypothesis(const std::string& name);
std::string to_string(MaterialModel model);
std::string to_string(PlaneHypothesis hypothesis);

// The in-plane response the element uses: S and D in Voigt [11, 22, 12] (engineering shear), energy, and the
// out-of-plane state. Plane strain takes E33 = 0; plane stress solves S33(E33) = 0 by Newton and condenses
// the tangent, D = D_pp - D_p3 D_3p / D_33 (exact linearisation of the constrained point).
struct PlaneResponse {
  double energy = 0.0;
  Eigen::Vector3d stress;
  Eigen::Matrix3d tangent;
  double c33 = 1.0;  // F33^2
  double s33 = 0.0;  // out-of-plane S (non-zero in plane strain)
};

PlaneResponse plane_response(const Material& material, const Eigen::Matrix2d& e, PlaneHypothesis hypothesis,
                             EnergyPart part = EnergyPart::kAll);
// E = (H + H^T + H^T H) / 2 from the displacement gradient H = F - I, without forming C.
Eigen::Matrix2d green_lagrange(const Eigen::Matrix2d& displacement_gradient);

// Cauchy stress (Voigt [11, 22, 12, 33]) and its von Mises equivalent from F (2x2), F33 and S.
Eigen::Vector4d cauchy_stress(const Eigen::Matrix2d& f, double f33, const Eigen::Vector4d& s);
double von_mises(const Eigen::Vector4d& cauchy);

}  // namespace halfeti::structure
