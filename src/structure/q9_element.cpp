#include "halfeti/structure/q9_element.hpp"

#include <cmath>

#include "halfeti/core/error.hpp"

namespace halfeti::structure {

namespace {

// Gauss-Legendre rules on [-1, 1].
constexpr double kGauss3[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kWeight3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
constexpr double kGauss2[2] = {-0.5773502691896257, 0.5773502691896257};

Q9Point reference_point(const Q9Coordinates& reference, double xi, double eta, double weight) {
  Q9Point p;
  Eigen::Matrix<double, kQ9Nodes, 2> dn_dxi;
  q9_shape(xi, eta, p.shape, dn_dxi);
  const Eigen::Matrix2d jacobian = reference.transpose() * dn_dxi;  // J(I, alpha) = dX_I / dxi_alpha
  const double det = jacobian.determinant();
  if (!(det > 0.0))
    HALFETI_USER_ERROR("structure mesh: Q9 element inverted or degenerate (det J = " << det << ")");
  p.gradient = dn_dxi * jacobian.inverse();
  p.weight = weight * det;
  return p;
}

}  // namespace

void q9_shape(double xi, double eta, Eigen::Matrix<double, kQ9Nodes, 1>& n,
              Eigen::Matrix<double, kQ9Nodes, 2>& dn_dxi) {
  const double lx[3] = {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
  const double dlx[3] = {xi - 0.5, -2.0 * xi, xi + 0.5};
  const double ly[3] = {0.5 * eta * (eta - 1.0), 1.0 - eta * eta, 0.5 * eta * (eta + 1.0)};
  const double dly[3] = {eta - 0.5, -2.0 * eta, eta + 0.5};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = i + 3 * j;
      n(a) = lx[i] * ly[j];
      dn_dxi(a, 0) = dlx[i] * ly[j];
      dn_dxi(a, 1) = lx[i] * dly[j];
    }
}

HyperelasticQ9::HyperelasticQ9(const Material& material, Q9Options options)
    : material_(material), options_(options) {}

Q9Geometry HyperelasticQ9::reference_geometry(const Q9Coordinates& reference) {
  Q9Geometry g;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      g.full[i + 3 * j] = reference_point(reference, kGauss3[i], kGauss3[j], kWeight3[i] * kWeight3[j]);
      g.area += g.full[i + 3 * j].weight;
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) g.reduced[i + 2 * j] = reference_point(reference, kGauss2[i], kGauss2[j], 1.0);
  return g;
}

bool HyperelasticQ9::split() const {
  return options_.selective_reduced_integration && options_.hypothesis == PlaneHypothesis::kPlaneStrain;
}

template <bool kTangent>
void HyperelasticQ9::accumulate(const Q9Point& p, const Q9Coordinates& x, EnergyPart part, Q9Vector& force,
                                Q9Matrix* tangent) const {
  const auto& g = p.gradient;
  const Eigen::Matrix2d f = x.transpose() * g;  // F(i, I) = sum_a x_ai dN_a/dX_I
  if (!(f.determinant() > 0.0))
    HALFETI_NUMERICAL_ERROR("structure: inverted element point (det F = " << f.determinant()
                                                                           << " <= 0): deformation too large");
  const PlaneResponse r = plane_response(material_, f.transpose() * f, options_.hypothesis, part);
  Eigen::Matrix2d s;
  s << r.stress(0), r.stress(2), r.stress(2), r.stress(1);
  const double w = p.weight;

  // f_a = w P dN_a/dX with P = F S (first Piola-Kirchhoff).
  const Eigen::Matrix<double, kQ9Nodes, 2> nodal = w * g * (f * s).transpose();
  for (int a = 0; a < kQ9Nodes; ++a) force.segment<2>(2 * a) += nodal.row(a).transpose();
  if constexpr (!kTangent) return;

  // Material part B^T D B, with B the variation of E_v = [E11, E22, 2 E12] at the current F.
  Eigen::Matrix<double, 3, kQ9Dofs> b;
  for (int a = 0; a < kQ9Nodes; ++a) {
    const double g0 = g(a, 0), g1 = g(a, 1);
    for (int i = 0; i < 2; ++i) {
      b(0, 2 * a + i) = f(i, 0) * g0;
      b(1, 2 * a + i) = f(i, 1) * g1;
      b(2, 2 * a + i) = f(i, 0) * g1 + f(i, 1) * g0;
    }
  }
  const Eigen::Matrix<double, 3, kQ9Dofs> db = w * r.tangent * b;
  tangent->noalias() += b.transpose() * db;
  // Geometric part: (dN_a^T S dN_b) I.
  const Eigen::Matrix<double, kQ9Nodes, kQ9Nodes> geometric = w * g * s * g.transpose();
  for (int a = 0; a < kQ9Nodes; ++a)
    for (int c = 0; c < kQ9Nodes; ++c) {
      (*tangent)(2 * a, 2 * c) += geometric(a, c);
      (*tangent)(2 * a + 1, 2 * c + 1) += geometric(a, c);
    }
}

double HyperelasticQ9::energy(const Q9Geometry& g, const Q9Coordinates& x) const {
  double e = 0.0;
  auto add = [&](const Q9Point& p, EnergyPart part) {
    const Eigen::Matrix2d f = x.transpose() * p.gradient;
    e += p.weight * plane_response(material_, f.transpose() * f, options_.hypothesis, part).energy;
  };
  if (split()) {
    for (const auto& p : g.full) add(p, EnergyPart::kShear);
    for (const auto& p : g.reduced) add(p, EnergyPart::kBulk);
  } else {
    for (const auto& p : g.full) add(p, EnergyPart::kAll);
  }
  return e;
}

void HyperelasticQ9::internal_force(const Q9Geometry& g, const Q9Coordinates& x, Q9Vector& force) const {
  force.setZero();
  if (split()) {
    for (const auto& p : g.full) accumulate<false>(p, x, EnergyPart::kShear, force, nullptr);
    for (const auto& p : g.reduced) accumulate<false>(p, x, EnergyPart::kBulk, force, nullptr);
  } else {
    for (const auto& p : g.full) accumulate<false>(p, x, EnergyPart::kAll, force, nullptr);
  }
}

void HyperelasticQ9::internal_force_and_tangent(const Q9Geometry& g, const Q9Coordinates& x, Q9Vector& force,
                                                Q9Matrix& tangent) const {
  force.setZero();
  tangent.setZero();
  if (split()) {
    for (const auto& p : g.full) accumulate<true>(p, x, EnergyPart::kShear, force, &tangent);
    for (const auto& p : g.reduced) accumulate<true>(p, x, EnergyPart::kBulk, force, &tangent);
  } else {
    for (const auto& p : g.full) accumulate<true>(p, x, EnergyPart::kAll, force, &tangent);
  }
}

Eigen::Matrix<double, kQ9Nodes, kQ9Nodes> HyperelasticQ9::scalar_mass(const Q9Geometry& g, double density) {
  Eigen::Matrix<double, kQ9Nodes, kQ9Nodes> m = Eigen::Matrix<double, kQ9Nodes, kQ9Nodes>::Zero();
  for (const auto& p : g.full) m.noalias() += density * p.weight * p.shape * p.shape.transpose();
  return m;
}

std::array<Eigen::Vector4d, 9> HyperelasticQ9::cauchy_at_points(const Q9Geometry& g, const Q9Coordinates& x) const {
  std::array<Eigen::Vector4d, 9> out;
  for (int q = 0; q < 9; ++q) {
    const Eigen::Matrix2d f = x.transpose() * g.full[q].gradient;
    const PlaneResponse r = plane_response(material_, f.transpose() * f, options_.hypothesis);
    const Eigen::Vector4d s(r.stress(0), r.stress(1), r.stress(2), r.s33);
    out[q] = cauchy_stress(f, std::sqrt(r.c33), s);
  }
  return out;
}

}  // namespace halfeti::structure
