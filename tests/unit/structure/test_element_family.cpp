// The element families' one interface (element_family.hpp), the same checks for Q9 and Q4-EAS through it: the
// masses add up to rho x area, the force is the energy's gradient and the tangent the force's (central
// differences), and an evaluation without the matrix gives the same force and a zero matrix.
#include <gtest/gtest.h>

#include <random>

#include "halfeti/structure/element_family.hpp"

using namespace halfeti::structure;

namespace {
template <typename Family>
Family make(ElementType type, PlateMesh& mesh, std::unique_ptr<Material>& material) {
  PlateGeometry g;
  g.height = 0.08;
  g.thickness = 0.006;
  g.cells_across = 2;
  g.cells_along = 3;
  g.element = type;
  mesh = make_plate_mesh(g);
  material = make_material(MaterialModel::kNeoHookean, 1e7, 0.45);
  if constexpr (std::is_same_v<Family, Q9Family>)
    return Q9Family(*material, Q9Options{PlaneHypothesis::kPlaneStrain, true}, mesh, 1150.0);
  else
    return Q4EasFamily(*material, Q4EasOptions{PlaneHypothesis::kPlaneStrain}, mesh, 1150.0);
}

template <typename Family>
void check_family(ElementType type) {
  PlateMesh mesh;
  std::unique_ptr<Material> material;
  Family family = make<Family>(type, mesh, material);
  ASSERT_EQ(family.count(), mesh.element_count());
  double mass = 0.0;
  for (int e = 0; e < family.count(); ++e) mass += family.mass(e).sum();
  EXPECT_NEAR(mass, 1150.0 * 0.08 * 0.006, 1e-12 * mass);

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> r(-1e-4, 1e-4);
  const int e = 1;
  typename Family::Coordinates u;
  for (int a = 0; a < Family::kNodes; ++a) u.row(a) << r(rng) + 2e-4, r(rng);
  typename Family::Vector f, f2, fp, fm;
  typename Family::Matrix k, k2, scratch;
  family.evaluate(e, u, true, true, f, k);
  family.evaluate(e, u, false, true, f2, k2);  // force only: the same force
  EXPECT_EQ(f, f2);
  family.evaluate(e, u, true, false, f2, k2);  // the matrix without the tangent: zero
  EXPECT_EQ(f, f2);
  EXPECT_EQ(k2.norm(), 0.0);
  const double h = 1e-8, scale = f.cwiseAbs().maxCoeff(), kscale = k.cwiseAbs().maxCoeff();
  for (int a = 0; a < Family::kNodes; ++a)
    for (int c = 0; c < 2; ++c) {
      typename Family::Coordinates up = u, um = u;
      up(a, c) += h;
      um(a, c) -= h;
      // The force (interleaved x0 y0 x1 ...) is dE/du.
      const double de = (family.energy(e, up) - family.energy(e, um)) / (2 * h);
      EXPECT_NEAR(f(2 * a + c), de, 1e-5 * scale) << Family::kName << " node " << a << " component " << c;
      // The tangent (component-major: column kNodes c + a) is d force / du.
      family.evaluate(e, up, false, false, fp, scratch);
      family.evaluate(e, um, false, false, fm, scratch);
      for (int b = 0; b < Family::kNodes; ++b)
        for (int d = 0; d < 2; ++d)
          EXPECT_NEAR(k(Family::kNodes * d + b, Family::kNodes * c + a),
                      (fp(2 * b + d) - fm(2 * b + d)) / (2 * h), 1e-5 * kscale)
              << Family::kName;
    }
}
}  // namespace

TEST(ElementFamily, Q9ThroughTheInterface) {
  check_family<Q9Family>(ElementType::kQ9);
}
TEST(ElementFamily, Q4EasThroughTheInterface) {
  check_family<Q4EasFamily>(ElementType::kQ4Eas);
}
