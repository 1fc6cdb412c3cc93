#include "halfeti/structure/q4_eas_element.hpp"

#include <cmath>

#include "halfeti/core/error.hpp"

namespace halfeti::structure {

namespace {

constexpr double kGauss2 = 0.5773502691896257;  // 1 / sqrt(3)
constexpr int kMaxLocalIterations = 25;
// Local Newton stops when the next correction |d alpha|_inf is below kLocalRtol |alpha|_inf + kLocalAtol * size;
// that last correction is not applied to the stress state but enters the force linearly (f_u + K_ua d alpha),
// so the force is accurate to O(|d alpha|^2) (quadratic convergence): far below round-off of the stresses.
constexpr double kLocalRtol = 1e-8;
constexpr double kLocalAtol = 1e-13;

}  // namespace

void q4_shape(double xi, double eta, Eigen::Matrix<double, kQ4Nodes, 1>& n,
              Eigen::Matrix<double, kQ4Nodes, 2>& dn_dxi) {
  const double lx[2] = {0.5 * (1.0 - xi), 0.5 * (1.0 + xi)};
  const double ly[2] = {0.5 * (1.0 - eta), 0.5 * (1.0 + eta)};
  const double dl[2] = {-0.5, 0.5};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = i + 2 * j;
      n(a) = lx[i] * ly[j];
      dn_dxi(a, 0) = dl[i] * ly[j];
      dn_dxi(a, 1) = lx[i] * dl[j];
    }
}

HyperelasticQ4Eas::HyperelasticQ4Eas(const Material& material, Q4EasOptions options)
    : material_(material), options_(options) {
  closed_form_ = options_.specialised_kernel && options_.hypothesis == PlaneHypothesis::kPlaneStrain &&
                 dynamic_cast<const NeoHookean*>(&material_) != nullptr;
}

Q4EasGeometry HyperelasticQ4Eas::reference_geometry(const Q4Coordinates& reference) {
  Q4EasGeometry g;
  Eigen::Matrix<double, kQ4Nodes, 1> n;
  Eigen::Matrix<double, kQ4Nodes, 2> dn_dxi;
  q4_shape(0.0, 0.0, n, dn_dxi);
  const Eigen::Matrix2d j0 = reference.transpose() * dn_dxi;  // J0(I, beta) = dX_I / dxi_beta at the centre
  const double det0 = j0.determinant();
  if (!(det0 > 0.0))
    HALFETI_USER_ERROR("structure mesh: Q4 element inverted or degenerate (det J0 = " << det0 << ")");
  const Eigen::Matrix2d j0_inverse = j0.inverse();  // (beta, J)
  for (int q = 0; q < 4; ++q) {
    const double xi = (q % 2 == 0 ? -1.0 : 1.0) * kGauss2, eta = (q / 2 == 0 ? -1.0 : 1.0) * kGauss2;
    Q4EasPoint& p = g.points[q];
    q4_shape(xi, eta, p.shape, dn_dxi);
    const Eigen::Matrix2d jacobian = reference.transpose() * dn_dxi;
    const double det = jacobian.determinant();
    if (!(det > 0.0))
      HALFETI_USER_ERROR("structure mesh: Q4 element inverted or degenerate (det J = " << det << ")");
    p.gradient.topRows<kQ4Nodes>() = dn_dxi * jacobian.inverse();
    // Enhanced modes (Simo & Armero 1992): gradient of mode m is (j0 / j) xi_m (J0^-1) row m.
    p.gradient.row(4) = (det0 / det) * xi * j0_inverse.row(0);
    p.gradient.row(5) = (det0 / det) * eta * j0_inverse.row(1);
    p.weight = det;  // Gauss weights are 1
    g.area += det;
  }
  g.size = std::sqrt(g.area);
  for (const auto& p : g.points) g.laplacian.noalias() += p.weight * p.gradient * p.gradient.transpose();
  return g;
}

// The uncondensed element at U (rows 0-3 nodal displacements, rows 4-5 the mode vectors): force(a, i) =
// sum_points w P_iJ g_aJ and the tangent K(6 i + a, 6 k + b) = sum_points w g_aJ A_iJkL g_bL with
// A_iJkL = F_iI F_kK D_IJKL + delta_ik S_JL (material + geometric stiffness), as for the Q9.
// Closed form for Neo-Hookean in plane strain (derivation in q9_element.cpp): with q = g F^-1 (spatial
// gradients) and m = mu - lambda ln J, K(6i+a, 6k+b) = w (lambda q_ai q_bk + m q_ak q_bi) + mu delta_ik L_ab.
template <bool kFull>
void HyperelasticQ4Eas::evaluate(const Q4EasGeometry& g, const Extended& U, Extended& force,
                                 Tangent12& k) const {
  // kFull false (the force-only path) fills the alpha rows of the tangent only (the local solve and the force's
  // condensation need nothing else), each entry computed exactly as in the full path.
  force.setZero();
  const double mu = material_.mu(), lambda = material_.lambda();
  // Closed form: per point, K_00 += (wl + wm) q0 q0^T, K_11 += (wl + wm) q1 q1^T, K_01 += wl q0 q1^T + wm q1 q0^T
  // (entry [b][a] = row a, column b), K_10 = K_01^T.
  double k00[6][6] = {}, k11[6][6] = {}, k01[6][6] = {};
  if (!closed_form_) k.setZero();
  for (const auto& p : g.points) {
    const Eigen::Matrix<double, 6, 2>& gr = p.gradient;
    const Eigen::Matrix2d h = U.transpose() * gr;  // H = sum_a U_a (x) g_a
    const double f00 = 1.0 + h(0, 0), f01 = h(0, 1), f10 = h(1, 0), f11 = 1.0 + h(1, 1);
    const double det_f = f00 * f11 - f01 * f10;
    if (!(det_f > 0.0))
      HALFETI_NUMERICAL_ERROR(
          "structure: inverted element point (det F = " << det_f << " <= 0): deformation too large");
    const double w = p.weight;
    Eigen::Matrix2d s;
    if (closed_form_) {
      const double e00 = h(0, 0) + 0.5 * (h(0, 0) * h(0, 0) + h(1, 0) * h(1, 0));
      const double e11 = h(1, 1) + 0.5 * (h(0, 1) * h(0, 1) + h(1, 1) * h(1, 1));
      const double e01 = 0.5 * (h(0, 1) + h(1, 0) + h(0, 0) * h(0, 1) + h(1, 0) * h(1, 1));
      const double det_c_minus_one = 2.0 * (e00 + e11) + 4.0 * (e00 * e11 - e01 * e01);
      const double inv_det_c = 1.0 / (1.0 + det_c_minus_one);
      const double ci00 = (1.0 + 2.0 * e11) * inv_det_c, ci11 = (1.0 + 2.0 * e00) * inv_det_c,
                   ci01 = -2.0 * e01 * inv_det_c;
      const double log_j = 0.5 * std::log1p(det_c_minus_one);
      // S = 2 mu C^-1 E + lambda ln J C^-1 (as NeoHookean::evaluate, no cancellation at small strain).
      const double bulk = lambda * log_j;
      s(0, 0) = 2.0 * mu * (ci00 * e00 + ci01 * e01) + bulk * ci00;
      s(1, 1) = 2.0 * mu * (ci01 * e01 + ci11 * e11) + bulk * ci11;
      s(0, 1) = s(1, 0) = 2.0 * mu * (ci00 * e01 + ci01 * e11) + bulk * ci01;
      const double inv = 1.0 / det_f;
      const double i00 = f11 * inv, i01 = -f01 * inv, i10 = -f10 * inv, i11 = f00 * inv;  // F^-1
      double q0[6], q1[6], d0[6], d1[6], l0[6], m1[6];
      const double wl = w * lambda, wm = w * (mu - lambda * log_j);
      for (int a = 0; a < 6; ++a) {
        q0[a] = gr(a, 0) * i00 + gr(a, 1) * i10;
        q1[a] = gr(a, 0) * i01 + gr(a, 1) * i11;
        d0[a] = (wl + wm) * q0[a];
        d1[a] = (wl + wm) * q1[a];
        l0[a] = wl * q0[a];
        m1[a] = wm * q1[a];
      }
      if constexpr (kFull) {
        for (int b = 0; b < 6; ++b)
          for (int a = 0; a < 6; ++a) {
            k00[b][a] += d0[a] * q0[b];
            k11[b][a] += d1[a] * q1[b];
            k01[b][a] += l0[a] * q1[b] + m1[a] * q0[b];
          }
      } else {
        // The alpha rows only: K(4 + m, .) and K(10 + m, .), i.e. k00, k11, k01 at a = 4, 5 and k01 at b = 4, 5;
        // each entry by the same expression as above (same bits).
        for (int b = 0; b < 6; ++b)
          for (int a = 4; a < 6; ++a) {
            k00[b][a] += d0[a] * q0[b];
            k11[b][a] += d1[a] * q1[b];
            k01[b][a] += l0[a] * q1[b] + m1[a] * q0[b];
          }
        for (int b = 4; b < 6; ++b)
          for (int a = 0; a < 4; ++a) k01[b][a] += l0[a] * q1[b] + m1[a] * q0[b];
      }
    } else {
      const PlaneResponse r = plane_response(material_, green_lagrange(h), options_.hypothesis);
      s << r.stress(0), r.stress(2), r.stress(2), r.stress(1);
      const Eigen::Matrix2d f = Eigen::Matrix2d::Identity() + h;
      static constexpr int kVoigt[2][2] = {{0, 2}, {2, 1}};
      for (int i = 0; i < 2; ++i)
        for (int kk = 0; kk < 2; ++kk) {
          Eigen::Matrix2d a_ik;  // w A_iJkL as (J, L)
          for (int jj = 0; jj < 2; ++jj)
            for (int ll = 0; ll < 2; ++ll) {
              double sum = i == kk ? s(jj, ll) : 0.0;
              for (int ii = 0; ii < 2; ++ii)
                for (int k2 = 0; k2 < 2; ++k2)
                  sum += f(i, ii) * f(kk, k2) * r.tangent(kVoigt[ii][jj], kVoigt[k2][ll]);
              a_ik(jj, ll) = w * sum;
            }
          const Eigen::Matrix<double, 6, 2> ga = gr * a_ik;
          k.block<6, 6>(6 * i, 6 * kk).noalias() += ga * gr.transpose();
        }
    }
    // P = F S; force(a, i) += w P_iJ g_aJ.
    const double p00 = w * (f00 * s(0, 0) + f01 * s(1, 0)), p01 = w * (f00 * s(0, 1) + f01 * s(1, 1)),
                 p10 = w * (f10 * s(0, 0) + f11 * s(1, 0)), p11 = w * (f10 * s(0, 1) + f11 * s(1, 1));
    for (int a = 0; a < 6; ++a) {
      force(a, 0) += p00 * gr(a, 0) + p01 * gr(a, 1);
      force(a, 1) += p10 * gr(a, 0) + p11 * gr(a, 1);
    }
  }
  if (closed_form_)
    for (int b = 0; b < 6; ++b)
      for (int a = 0; a < 6; ++a) {
        const double mu_l = mu * g.laplacian(a, b);
        k(a, b) = k00[b][a] + mu_l;
        k(6 + a, 6 + b) = k11[b][a] + mu_l;
        k(a, 6 + b) = k(6 + b, a) = k01[b][a];
      }
}

template <bool kFull>
void HyperelasticQ4Eas::solve_local(const Q4EasGeometry& g, const Q4Coordinates& u, EasParameters& alpha,
                                    Extended& force, Tangent12& k, Eigen::Matrix4d& kaa_inverse,
                                    EasParameters& correction) const {
  Extended U;
  U.topRows<kQ4Nodes>() = u;
  for (int it = 0; it < kMaxLocalIterations; ++it) {
    for (int i = 0; i < 2; ++i)
      for (int m = 0; m < 2; ++m) U(4 + m, i) = alpha(2 * i + m);
    evaluate<kFull>(g, U, force, k);
    EasParameters h;
    Eigen::Matrix4d kaa;
    for (int i = 0; i < 2; ++i)
      for (int m = 0; m < 2; ++m) {
        h(2 * i + m) = force(4 + m, i);
        for (int kk = 0; kk < 2; ++kk)
          for (int n = 0; n < 2; ++n) kaa(2 * i + m, 2 * kk + n) = k(6 * i + 4 + m, 6 * kk + 4 + n);
      }
    kaa_inverse = kaa.inverse();
    correction = -kaa_inverse * h;
    if (!correction.allFinite())
      HALFETI_NUMERICAL_ERROR(
          "structure: Q4-EAS enhanced stiffness singular (det K_aa = " << kaa.determinant() << ")");
    if (correction.lpNorm<Eigen::Infinity>() <=
        kLocalRtol * alpha.lpNorm<Eigen::Infinity>() + kLocalAtol * g.size) {
      last_local_iterations_ = it + 1;
      return;
    }
    alpha += correction;
  }
  HALFETI_NUMERICAL_ERROR("structure: Q4-EAS local Newton on the enhanced parameters did not converge in "
                          << kMaxLocalIterations << " iterations (last |d alpha| = "
                          << correction.lpNorm<Eigen::Infinity>() << " m)");
}

void HyperelasticQ4Eas::internal_force(const Q4EasGeometry& g, const Q4Coordinates& u, EasParameters& alpha,
                                       Q4Vector& force) const {
  Extended f;
  Tangent12 k;
  Eigen::Matrix4d kaa_inverse;
  EasParameters correction;
  solve_local<false>(g, u, alpha, f, k, kaa_inverse, correction);
  // f_u + K_ua d alpha, with K_ua = K_au^T (the alpha rows, which both paths compute identically).
  for (int i = 0; i < 2; ++i)
    for (int a = 0; a < kQ4Nodes; ++a) {
      double sum = f(a, i);
      for (int kk = 0; kk < 2; ++kk)
        for (int n = 0; n < 2; ++n) sum += k(6 * kk + 4 + n, 6 * i + a) * correction(2 * kk + n);
      force(2 * a + i) = sum;
    }
  alpha += correction;
}

void HyperelasticQ4Eas::internal_force_and_tangent_component_major(const Q4EasGeometry& g,
                                                                   const Q4Coordinates& u,
                                                                   EasParameters& alpha, Q4Vector& force,
                                                                   Q4Matrix& component_major,
                                                                   EasUpdate* update) const {
  Extended f;
  Tangent12 k;
  Eigen::Matrix4d kaa_inverse;
  EasParameters correction;
  solve_local<true>(g, u, alpha, f, k, kaa_inverse, correction);
  Eigen::Matrix<double, kEasModes, kQ4Dofs> kau;  // alpha rows, u columns (component-major 4 i + a)
  for (int i = 0; i < 2; ++i)
    for (int m = 0; m < 2; ++m)
      for (int kk = 0; kk < 2; ++kk)
        for (int b = 0; b < kQ4Nodes; ++b) kau(2 * i + m, 4 * kk + b) = k(6 * i + 4 + m, 6 * kk + b);
  for (int i = 0; i < 2; ++i)
    for (int a = 0; a < kQ4Nodes; ++a) {
      double sum = f(a, i);
      for (int kk = 0; kk < 2; ++kk)
        for (int n = 0; n < 2; ++n) sum += k(6 * kk + 4 + n, 6 * i + a) * correction(2 * kk + n);
      force(2 * a + i) = sum;
    }
  // Condensation: K* = K_uu - K_ua K_aa^-1 K_au = K_uu + K_au^T C, C = -K_aa^-1 K_au = d alpha / du.
  const EasUpdate c = -kaa_inverse * kau;
  for (int i = 0; i < 2; ++i)
    for (int kk = 0; kk < 2; ++kk)
      for (int b = 0; b < kQ4Nodes; ++b)
        for (int a = 0; a < kQ4Nodes; ++a) component_major(4 * i + a, 4 * kk + b) = k(6 * i + a, 6 * kk + b);
  component_major.noalias() += kau.transpose() * c;
  if (update != nullptr) *update = c;
  alpha += correction;
}

void HyperelasticQ4Eas::internal_force_and_tangent(const Q4EasGeometry& g, const Q4Coordinates& u,
                                                   EasParameters& alpha, Q4Vector& force,
                                                   Q4Matrix& tangent) const {
  Q4Matrix cm;
  internal_force_and_tangent_component_major(g, u, alpha, force, cm, nullptr);
  for (int i = 0; i < 2; ++i)
    for (int kk = 0; kk < 2; ++kk)
      for (int b = 0; b < kQ4Nodes; ++b)
        for (int a = 0; a < kQ4Nodes; ++a) tangent(2 * a + i, 2 * b + kk) = cm(4 * i + a, 4 * kk + b);
}

double HyperelasticQ4Eas::energy(const Q4EasGeometry& g, const Q4Coordinates& u, EasParameters alpha) const {
  Q4Vector force;
  internal_force(g, u, alpha, force);
  Extended U;
  U.topRows<kQ4Nodes>() = u;
  for (int i = 0; i < 2; ++i)
    for (int m = 0; m < 2; ++m) U(4 + m, i) = alpha(2 * i + m);
  double e = 0.0;
  for (const auto& p : g.points) {
    const Eigen::Matrix2d h = U.transpose() * p.gradient;
    e += p.weight * plane_response(material_, green_lagrange(h), options_.hypothesis).energy;
  }
  return e;
}

Eigen::Matrix<double, kQ4Nodes, kQ4Nodes> HyperelasticQ4Eas::scalar_mass(const Q4EasGeometry& g,
                                                                         double density) {
  // 2x2 Gauss integrates N_a N_b exactly on parallelograms (the plate's rectangles).
  Eigen::Matrix<double, kQ4Nodes, kQ4Nodes> m = Eigen::Matrix<double, kQ4Nodes, kQ4Nodes>::Zero();
  for (const auto& p : g.points) m.noalias() += density * p.weight * p.shape * p.shape.transpose();
  return m;
}

std::array<Eigen::Vector4d, 4> HyperelasticQ4Eas::cauchy_at_points(const Q4EasGeometry& g,
                                                                   const Q4Coordinates& u,
                                                                   EasParameters alpha) const {
  Q4Vector force;
  internal_force(g, u, alpha, force);
  Extended U;
  U.topRows<kQ4Nodes>() = u;
  for (int i = 0; i < 2; ++i)
    for (int m = 0; m < 2; ++m) U(4 + m, i) = alpha(2 * i + m);
  std::array<Eigen::Vector4d, 4> out;
  for (int q = 0; q < 4; ++q) {
    const Eigen::Matrix2d h = U.transpose() * g.points[q].gradient;
    const Eigen::Matrix2d f = Eigen::Matrix2d::Identity() + h;
    const PlaneResponse r = plane_response(material_, green_lagrange(h), options_.hypothesis);
    const Eigen::Vector4d s(r.stress(0), r.stress(1), r.stress(2), r.s33);
    out[q] = cauchy_stress(f, std::sqrt(r.c33), s);
  }
  return out;
}

}  // namespace halfeti::structure
