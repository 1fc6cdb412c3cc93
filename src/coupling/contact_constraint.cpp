// Eq. 19's constraint and its derivatives. With r = x_p - x_F, d = x_S - x_F, l = |d|, t = d / l and n = t
// turned clockwise, the only nonlinear piece is the normal n(d), whose derivative is dn = -t (n . dd) / l.
// For any fixed vector a, the Hessian of a . n(d) is -[(n.a) n n^T - (t.a)(t n^T + n t^T)] / l^2 (derivation:
// docs/coupling.md).
#include "halfeti/coupling/contact_constraint.hpp"

#include "halfeti/core/error.hpp"

namespace halfeti::coupling {

namespace {

using Mat2 = Eigen::Matrix2d;

// d2 (a . n(d)) / dd2.
Mat2 normal_hessian(const Eigen::Vector2d& a, const Eigen::Vector2d& t, const Eigen::Vector2d& n, double l) {
  return -(n.dot(a) * n * n.transpose() - t.dot(a) * (t * n.transpose() + n * t.transpose())) / (l * l);
}

// Maps a Hessian in (r, d) to q = (x_p, x_F, x_S): r = x_p - x_F, d = x_S - x_F.
Eigen::Matrix<double, 6, 6> to_q(const Eigen::Matrix4d& h_rd) {
  Eigen::Matrix<double, 4, 6> b = Eigen::Matrix<double, 4, 6>::Zero();
  b.block<2, 2>(0, 0) = Mat2::Identity();
  b.block<2, 2>(0, 2) = -Mat2::Identity();
  b.block<2, 2>(2, 2) = -Mat2::Identity();
  b.block<2, 2>(2, 4) = Mat2::Identity();
  return b.transpose() * h_rd * b;
}

}  // namespace

ConstraintTerms evaluate_constraint(ContactConstraint form, const Eigen::Vector2d& xp,
                                    const Eigen::Vector2d& xf, const Eigen::Vector2d& xs, double eta_frozen,
                                    double target_gap, const Eigen::Vector2d& lambda) {
  ConstraintTerms out;
  const Eigen::Vector2d d = xs - xf, r = xp - xf;
  const double l = d.norm();
  HALFETI_CHECK(l > 0.0, "degenerate contact segment");
  const Eigen::Vector2d t = d / l, n(t.y(), -t.x());
  const Mat2 dn_dd = -t * n.transpose() / l;    // dn = dn_dd dd
  Eigen::Matrix4d h = Eigen::Matrix4d::Zero();  // Hessian of lambda . c in (r, d)

  if (form == ContactConstraint::kNormal) {
    out.rows = 1;
    const double gap = n.dot(r), eta = t.dot(r) / l;
    out.value(0) = gap - target_gap;
    out.gradient.block<1, 2>(0, 0) = n.transpose();                 // dg/dx_p
    out.gradient.block<1, 2>(0, 2) = -(1.0 - eta) * n.transpose();  // dg/dx_F
    out.gradient.block<1, 2>(0, 4) = -eta * n.transpose();          // dg/dx_S
    const double lam = lambda(0);
    h.block<2, 2>(0, 2) = lam * dn_dd;
    h.block<2, 2>(2, 0) = lam * dn_dd.transpose();
    h.block<2, 2>(2, 2) = lam * normal_hessian(r, t, n, l);
  } else {
    out.rows = 2;
    const double eta = eta_frozen;
    out.value = xp - (1.0 - eta) * xf - eta * xs - target_gap * n;
    out.gradient.block<2, 2>(0, 0) = Mat2::Identity();
    out.gradient.block<2, 2>(0, 2) = -(1.0 - eta) * Mat2::Identity() + target_gap * dn_dd;
    out.gradient.block<2, 2>(0, 4) = -eta * Mat2::Identity() - target_gap * dn_dd;
    h.block<2, 2>(2, 2) = -target_gap * normal_hessian(lambda, t, n, l);
  }
  out.hessian = to_q(h);
  return out;
}

Eigen::Matrix<double, 6, 1> contact_forces(const ConstraintTerms& terms, const Eigen::Vector2d& lambda) {
  return terms.gradient.topRows(terms.rows).transpose() * lambda.head(terms.rows);
}

}  // namespace halfeti::coupling
