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

// The sums over the points of the closed-form Neo-Hookean kernel below, as rank-one updates on contiguous
// 9-vectors (the columns of the column-major blocks); K_00 and K_11 are symmetric, only their lower triangles
// are read. Compiled twice (AVX2 and baseline, chosen at run time): each entry is summed in the same order in both,
// without fused multiply-adds (ISO C++ mode), so both give the same bits.
__attribute__((target_clones("avx2", "default"))) void rank_one_sums(
    int points, const double* __restrict q0, const double* __restrict q1, const double* __restrict diagonal,
    const double* __restrict cross_lambda, const double* __restrict cross_m,
    double (*__restrict k00)[kQ9Nodes], double (*__restrict k11)[kQ9Nodes],
    double (*__restrict k01)[kQ9Nodes]) {
  for (int b = 0; b < kQ9Nodes; ++b)
    for (int a = 0; a < kQ9Nodes; ++a) k00[b][a] = k11[b][a] = k01[b][a] = 0.0;
  for (int p = 0; p < points; ++p) {
    const double* c0 = q0 + kQ9Nodes * p;
    const double* c1 = q1 + kQ9Nodes * p;
    double d0[kQ9Nodes], d1[kQ9Nodes], l0[kQ9Nodes], m1[kQ9Nodes];
    for (int a = 0; a < kQ9Nodes; ++a) {
      d0[a] = diagonal[p] * c0[a];
      d1[a] = diagonal[p] * c1[a];
      l0[a] = cross_lambda[p] * c0[a];
      m1[a] = cross_m[p] * c1[a];
    }
    if (cross_lambda[p] == 0.0) {  // a shear point: no lambda term in K_01
      for (int b = 0; b < kQ9Nodes; ++b) {
        const double c0b = c0[b], c1b = c1[b];
        for (int a = 0; a < kQ9Nodes; ++a) {
          k00[b][a] += d0[a] * c0b;
          k11[b][a] += d1[a] * c1b;
          k01[b][a] += m1[a] * c0b;
        }
      }
    } else {
      for (int b = 0; b < kQ9Nodes; ++b) {
        const double c0b = c0[b], c1b = c1[b];
        for (int a = 0; a < kQ9Nodes; ++a) {
          k00[b][a] += d0[a] * c0b;
          k11[b][a] += d1[a] * c1b;
          k01[b][a] += l0[a] * c1b + m1[a] * c0b;
        }
      }
    }
  }
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
    : material_(material), options_(options) {
  closed_form_ = options_.specialised_kernel && options_.hypothesis == PlaneHypothesis::kPlaneStrain &&
                 dynamic_cast<const NeoHookean*>(&material_) != nullptr;
}

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
  for (const auto& p : g.full) g.laplacian.noalias() += p.weight * p.gradient * p.gradient.transpose();
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

// Neo-Hookean in plane strain, closed form. With b = F^-T and q_a = F^-T dN_a/dX (the spatial gradient), the
// mixed tangent A_iJkL = F_iI F_kK D_IJKL + delta_ik S_JL of W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2
// reduces, using F C^-1 F^T = I and F C^-1 = b, to
//   A_iJkL = lambda b_iJ b_kL + m b_iL b_kJ + mu delta_ik delta_JL,   m = mu - lambda ln J,
// (the geometric term delta_ik S_JL and the delta_ik C^-1_JL part of D add up to mu delta_ik delta_JL). So at a
// point of weight w
//   K_ab(i, k) = w (lambda q_ai q_bk + m q_ak q_bi + mu delta_ik dN_a/dX . dN_b/dX).
// The last term does not depend on u: summed over the 3x3 points once (Q9Geometry::laplacian). The rest are
// rank-one products of the columns of q: with the points as columns of Q0, Q1 (9 x 13),
//   K_00 = Q0 diag(w (lambda + m)) Q0^T + mu L,   K_11 = Q1 diag(w (lambda + m)) Q1^T + mu L,
//   K_01 = Q0 diag(w lambda) Q1^T + Q1 diag(w m) Q0^T.
// Each energy part is the same formula with the other Lame constant set to zero (shear part: lambda = 0,
// m = mu; bulk part: mu = 0, m = -lambda ln J), so the selective split costs nothing extra. The force is
// f_a = w F S dN_a/dX with S computed as in NeoHookean::evaluate (2 C^-1 E, log1p), which keeps its digits.
template <bool kTangent>
void HyperelasticQ9::neo_hookean_plane_strain(const Q9Geometry& g, const Q9Coordinates& u, Q9Vector& force,
                                              Q9Matrix* component_major) const {
  constexpr int kPoints = 13;
  const double mu = material_.mu(), lambda = material_.lambda();
  Eigen::Matrix<double, kQ9Nodes, kPoints> q0, q1;
  Eigen::Matrix<double, kPoints, 1> diagonal, cross_lambda, cross_m;
  Eigen::Matrix<double, kQ9Nodes, 2> nodal = Eigen::Matrix<double, kQ9Nodes, 2>::Zero();
  int n = 0;
  auto point = [&](const Q9Point& p, double mu_p, double lambda_p) {
    const double* gx = p.gradient.col(0).data();  // dN_a/dX
    const double* gy = p.gradient.col(1).data();  // dN_a/dY
    const double* ux = u.col(0).data();
    const double* uy = u.col(1).data();
    double h00 = 0.0, h01 = 0.0, h10 = 0.0, h11 = 0.0;  // H = sum_a u_a (x) dN_a/dX
    for (int a = 0; a < kQ9Nodes; ++a) {
      h00 += ux[a] * gx[a];
      h01 += ux[a] * gy[a];
      h10 += uy[a] * gx[a];
      h11 += uy[a] * gy[a];
    }
    const double f00 = 1.0 + h00, f01 = h01, f10 = h10, f11 = 1.0 + h11;
    const double det_f = f00 * f11 - f01 * f10;
    if (!(det_f > 0.0))
      HALFETI_NUMERICAL_ERROR(
          "structure: inverted element point (det F = " << det_f << " <= 0): deformation too large");
    // E = (H + H^T + H^T H) / 2 and det C - 1 = 2 tr E + 4 det E without forming C (see material.hpp).
    const double e00 = h00 + 0.5 * (h00 * h00 + h10 * h10);
    const double e11 = h11 + 0.5 * (h01 * h01 + h11 * h11);
    const double e01 = 0.5 * (h01 + h10 + h00 * h01 + h10 * h11);
    const double det_c_minus_one = 2.0 * (e00 + e11) + 4.0 * (e00 * e11 - e01 * e01);
    if (!(det_c_minus_one > -1.0))
      HALFETI_NUMERICAL_ERROR("Neo-Hookean point inverted: det C <= 0 (E = [" << e00 << ", " << e11 << ", "
                                                                              << e01 << "], E33 = 0)");
    const double inv_det_c = 1.0 / (1.0 + det_c_minus_one);
    const double ci00 = (1.0 + 2.0 * e11) * inv_det_c, ci11 = (1.0 + 2.0 * e00) * inv_det_c,
                 ci01 = -2.0 * e01 * inv_det_c;
    const double log_j = lambda_p != 0.0 ? 0.5 * std::log1p(det_c_minus_one) : 0.0;
    // S = 2 mu C^-1 E + lambda ln J C^-1 (symmetric).
    const double bulk = lambda_p * log_j;
    const double s00 = 2.0 * mu_p * (ci00 * e00 + ci01 * e01) + bulk * ci00;
    const double s11 = 2.0 * mu_p * (ci01 * e01 + ci11 * e11) + bulk * ci11;
    const double s01 = 2.0 * mu_p * (ci00 * e01 + ci01 * e11) + bulk * ci01;
    // P = F S; f_a += w P dN_a/dX.
    const double w = p.weight;
    const double p00 = w * (f00 * s00 + f01 * s01), p01 = w * (f00 * s01 + f01 * s11),
                 p10 = w * (f10 * s00 + f11 * s01), p11 = w * (f10 * s01 + f11 * s11);
    double* nx = nodal.col(0).data();
    double* ny = nodal.col(1).data();
    for (int a = 0; a < kQ9Nodes; ++a) {
      nx[a] += p00 * gx[a] + p01 * gy[a];
      ny[a] += p10 * gx[a] + p11 * gy[a];
    }
    if constexpr (kTangent) {
      // q_a = F^-T dN_a/dX: q(a, i) = sum_J dN_a/dX_J (F^-1)_Ji.
      const double inv = 1.0 / det_f;
      const double i00 = f11 * inv, i01 = -f01 * inv, i10 = -f10 * inv, i11 = f00 * inv;
      double* c0 = q0.col(n).data();
      double* c1 = q1.col(n).data();
      for (int a = 0; a < kQ9Nodes; ++a) {
        c0[a] = gx[a] * i00 + gy[a] * i10;
        c1[a] = gx[a] * i01 + gy[a] * i11;
      }
      const double m = mu_p - lambda_p * log_j;
      diagonal(n) = w * (lambda_p + m);
      cross_lambda(n) = w * lambda_p;
      cross_m(n) = w * m;
    }
    ++n;
  };
  if (split()) {
    for (const auto& p : g.full) point(p, mu, 0.0);
    for (const auto& p : g.reduced) point(p, 0.0, lambda);
  } else {
    for (const auto& p : g.full) point(p, mu, lambda);
  }
  for (int a = 0; a < kQ9Nodes; ++a) force.segment<2>(2 * a) = nodal.row(a).transpose();
  if constexpr (kTangent) {
    double k00[kQ9Nodes][kQ9Nodes], k11[kQ9Nodes][kQ9Nodes], k01[kQ9Nodes][kQ9Nodes];
    rank_one_sums(n, q0.data(), q1.data(), diagonal.data(), cross_lambda.data(), cross_m.data(), k00, k11,
                  k01);
    Q9Matrix& k = *component_major;
    for (int b = 0; b < kQ9Nodes; ++b)
      for (int a = b; a < kQ9Nodes; ++a) {
        const double mu_l = mu * g.laplacian(a, b);
        k(a, b) = k(b, a) = k00[b][a] + mu_l;
        k(kQ9Nodes + a, kQ9Nodes + b) = k(kQ9Nodes + b, kQ9Nodes + a) = k11[b][a] + mu_l;
      }
    for (int b = 0; b < kQ9Nodes; ++b)
      for (int a = 0; a < kQ9Nodes; ++a) k(a, kQ9Nodes + b) = k(kQ9Nodes + b, a) = k01[b][a];
  }
}

namespace {
// From the component-major blocks (upper ones read) to the full, interleaved
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
  if (closed_form_) return neo_hookean_plane_strain<false>(g, u, force, nullptr);
  force.setZero();
  if (split()) {
    for (const auto& p : g.full) accumulate<false>(p, u, EnergyPart::kShear, force, nullptr);
    for (const auto& p : g.reduced) accumulate<false>(p, u, EnergyPart::kBulk, force, nullptr);
  } else {
    for (const auto& p : g.full) accumulate<false>(p, u, EnergyPart::kAll, force, nullptr);
  }
}

void HyperelasticQ9::internal_force_and_tangent_component_major(const Q9Geometry& g, const Q9Coordinates& u,
                                                                Q9Vector& force,
                                                                Q9Matrix& component_major) const {
  if (closed_form_) return neo_hookean_plane_strain<true>(g, u, force, &component_major);
  force.setZero();
  component_major.setZero();
  if (split()) {
    for (const auto& p : g.full) accumulate<true>(p, u, EnergyPart::kShear, force, &component_major);
    for (const auto& p : g.reduced) accumulate<true>(p, u, EnergyPart::kBulk, force, &component_major);
  } else {
    for (const auto& p : g.full) accumulate<true>(p, u, EnergyPart::kAll, force, &component_major);
  }
  component_major.block<kQ9Nodes, kQ9Nodes>(kQ9Nodes, 0) =
      component_major.block<kQ9Nodes, kQ9Nodes>(0, kQ9Nodes).transpose();
}

void HyperelasticQ9::internal_force_and_tangent(const Q9Geometry& g, const Q9Coordinates& u, Q9Vector& force,
                                                Q9Matrix& tangent) const {
  Q9Matrix component_major;
  internal_force_and_tangent_component_major(g, u, force, component_major);
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
