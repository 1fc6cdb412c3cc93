// The contact constraint of one invader against one surface segment (eq. 19) and its consistent
// linearisation. Unknowns q = (x_p, x_F, x_S): particle position, first and second node of the segment
// (current positions). Two forms (docs/coupling.md):
//   kTied   (eq. 19 as printed, C a vector): c = x_p - (1 - eta) x_F - eta x_S - g* n = 0, eta frozen at the
//           search (the particle is tied to a material point of the segment: normal AND tangential);
//   kNormal (frictionless): c = n . (x_p - x_F) - g* = 0, eta the current projection.
// g* is the target gap: 0 (plain contact) or the SSOSD relocated gap (eq. 22). The multiplier lambda is the
// contact force on the particle (kTied: the vector; kNormal: lambda n); the segment's nodes receive the
// opposite.
#pragma once

#include <Eigen/Dense>

namespace halfeti::coupling {

enum class ContactConstraint { kTied, kNormal };

inline int constraint_rows(ContactConstraint c) {
  return c == ContactConstraint::kTied ? 2 : 1;
}

struct ConstraintTerms {
  int rows = 0;                                                                // 2 (tied) or 1 (normal)
  Eigen::Vector2d value = Eigen::Vector2d::Zero();                             // c (first `rows` entries)
  Eigen::Matrix<double, 2, 6> gradient = Eigen::Matrix<double, 2, 6>::Zero();  // dc/dq
  Eigen::Matrix<double, 6, 6> hessian = Eigen::Matrix<double, 6, 6>::Zero();   // d2(lambda . c)/dq2
};

// lambda: the multiplier (first `rows` entries used). eta_frozen is used by kTied only.
ConstraintTerms evaluate_constraint(ContactConstraint form, const Eigen::Vector2d& xp,
                                    const Eigen::Vector2d& xf, const Eigen::Vector2d& xs, double eta_frozen,
                                    double target_gap, const Eigen::Vector2d& lambda);

// Forces of the contact on (particle, F, S) = gradient^T lambda (6 entries; they sum to zero per component).
Eigen::Matrix<double, 6, 1> contact_forces(const ConstraintTerms& terms, const Eigen::Vector2d& lambda);

}  // namespace halfeti::coupling
