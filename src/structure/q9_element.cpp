#include "halfeti/structure/q9_element.hpp"

#include <cmath>

#include "halfeti/core/error.hpp"

namespace halfeti::structure {

namespace {

// Gauss-Legendre rules on [-1, 1].
constexpr double kGauss3[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kWeight3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
constexpr double kGauss2[2] = {-0.5773502691896257, 0.5773502691896257};

// H = sum_a u_a (x) dN_a/dX, F = I + H (no round-off from the size of the coordinates).
Eigen::Matrix2d displacement_gradient(const Q9Coordinates& u, const Eigen::Matrix<double, kQ9Nodes, 2>& g) {
  return u.transpose() * g;
}

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
    for (int i = 0; i < 2; ++i)
      g.reduced[i + 2 * j] = reference_point(reference, kGauss2[i], kGauss2[j], 1.0);
  return g;
}

bool HyperelasticQ9::split() const {
  return options_.selective_reduced_integration && options_.hypothesis == PlaneHypothesis::kPlaneStrain;
}

template <bool kTangent>
void HyperelasticQ9::accumulate(const Q9Point& p, const Q9Coordinates& u, EnergyPart part, Q9Vector& force,
                                Q9Matrix* tangent) const {
  const auto& g = p.gradient;
  const Eigen::Matrix2d h = displacement_gradient(u, g);
  const Eigen::Matrix2d f = Eigen::Matrix2d::Identity() + h;
  if (!(f.determinant() > 0.0))
    HALFETI_NUMERICAL_ERROR("structure: inverted element point (det F = " << f.determinant()
                                                                          << " <= 0): deformation too large");
  const PlaneResponse r = plane_response(material_, green_lagrange(h), options_.hypothesis, part);
  Eigen::Matrix2d s;
  s << r.stress(0), r.stress(2), r.stress(2), r.stress(1);
  const double w = p.weight;

  // f_a = w P dN_a/dX with P = F S (first Piola-Kirchhoff).
  const Eigen::Matrix<double, kQ9Nodes, 2> nodal = w * g * (f * s).transpose();
  for (int a = 0; a < kQ9Nodes; ++a) force.segment<2>(2 * a) += nodal.row(a).transpose();
  if constexpr (!kTangent) return;

  // Tangent in the mixed form K_ab(i, k) = w sum_JL dN_a/dX_J A_iJkL dN_b/dX_L with
  //   A_iJkL = F_iI F_kK D_IJKL + delta_ik S_JL   (material + geometric stiffness together).
  // Accumulated component-major (row 9 i + a): each 9x9 block K_ik = G A_ik G^T is two small dense products,
  // which vectorise; about 4x fewer operations than B^T D B with a dense 3 x 18 B. K_10 = K_01^T is left to
  // the caller (mirror_and_interleave).
  static constexpr int kVoigt[2][2] = {{0, 2}, {2, 1}};
  Eigen::Matrix4d a4;
  for (int i = 0; i < 2; ++i)
    for (int jj = 0; jj < 2; ++jj)
      for (int k = 0; k < 2; ++k)
        for (int ll = 0; ll < 2; ++ll) {
          double sum = i == k ? s(jj, ll) : 0.0;
          for (int ii = 0; ii < 2; ++ii)
            for (int kk = 0; kk < 2; ++kk)
              sum += f(i, ii) * f(k, kk) * r.tangent(kVoigt[ii][jj], kVoigt[kk][ll]);
          a4(2 * i + jj, 2 * k + ll) = w * sum;
        }
  for (int i = 0; i < 2; ++i)
    for (int k = i; k < 2; ++k) {
      const Eigen::Matrix<double, kQ9Nodes, 2> ga = g * a4.block<2, 2>(2 * i, 2 * k);
      tangent->block<kQ9Nodes, kQ9Nodes>(kQ9Nodes * i, kQ9Nodes * k) += ga.lazyProduct(g.transpose());
    }
}

namespace {
// From the component-major upper blocks accumulated by accumulate<true>() to the full, interleaved
// (x0 y0 x1 y1 ...) element matrix.
void mirror_and_interleave(const Q9Matrix& component_major, Q9Matrix& k) {
  for (int b = 0; b < kQ9Nodes; ++b)
    for (int a = 0; a < kQ9Nodes; ++a) {
      k(2 * a, 2 * b) = component_major(a, b);
      k(2 * a, 2 * b + 1) = component_major(a, kQ9Nodes + b);
      k(2 * a + 1, 2 * b) = component_major(b, kQ9Nodes + a);
      k(2 * a + 1, 2 * b + 1) = component_major(kQ9Nodes + a, kQ9Nodes + b);
    }
}
}  // namespace

double HyperelasticQ9::energy(const Q9Geometry& g, const Q9Coordinates& u) const {
  double e = 0.0;
  auto add = [&](const Q9Point& p, EnergyPart part) {
    const Eigen::Matrix2d h = displacement_gradient(u, p.gradient);
    e += p.weight * plane_response(material_, green_lagrange(h), options_.hypothesis, part).energy;
  };
  if (split()) {
    for (const auto& p : g.full) add(p, EnergyPart::kShear);
    for (const auto& p : g.reduced) add(p, EnergyPart::kBulk);
  } else {
    for (const auto& p : g.full) add(p, EnergyPart::kAll);
  }
  return e;
}

void HyperelasticQ9::internal_force(const Q9Geometry& g, const Q9Coordinates& u, Q9Vector& force) const {
  force.setZero();
  if (split()) {
    for (const auto& p : g.full) accumulate<false>(p, u, EnergyPart::kShear, force, nullptr);
    for (const auto& p : g.reduced) accumulate<false>(p, u, EnergyPart::kBulk, force, nullptr);
  } else {
    for (const auto& p : g.full) accumulate<false>(p, u, EnergyPart::kAll, force, nullptr);
  }
}

void HyperelasticQ9::internal_force_and_tangent(const Q9Geometry& g, const Q9Coordinates& u, Q9Vector& force,
                                                Q9Matrix& tangent) const {
  force.setZero();
  Q9Matrix component_major = Q9Matrix::Zero();
  if (split()) {
    for (const auto& p : g.full) accumulate<true>(p, u, EnergyPart::kShear, force, &component_major);
    for (const auto& p : g.reduced) accumulate<true>(p, u, EnergyPart::kBulk, force, &component_major);
  } else {
    for (const auto& p : g.full) accumulate<true>(p, u, EnergyPart::kAll, force, &component_major);
  }
  mirror_and_interleave(component_major, tangent);
}

Eigen::Matrix<double, kQ9Nodes, kQ9Nodes> HyperelasticQ9::scalar_mass(const Q9Geometry& g, double density) {
  Eigen::Matrix<double, kQ9Nodes, kQ9Nodes> m = Eigen::Matrix<double, kQ9Nodes, kQ9Nodes>::Zero();
  for (const auto& p : g.full) m.noalias() += density * p.weight * p.shape * p.shape.transpose();
  return m;
}

std::array<Eigen::Vector4d, 9> HyperelasticQ9::cauchy_at_points(const Q9Geometry& g,
                                                                const Q9Coordinates& u) const {
  std::array<Eigen::Vector4d, 9> out;
  for (int q = 0; q < 9; ++q) {
    const Eigen::Matrix2d h = displacement_gradient(u, g.full[q].gradient);
    const Eigen::Matrix2d f = Eigen::Matrix2d::Identity() + h;
    const PlaneResponse r = plane_response(material_, green_lagrange(h), options_.hypothesis);
    const Eigen::Vector4d s(r.stress(0), r.stress(1), r.stress(2), r.s33);
    out[q] = cauchy_stress(f, std::sqrt(r.c33), s);
  }
  return out;
}

}  // namespace halfeti::structure
