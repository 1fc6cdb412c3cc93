// The condensed solve of eq. 21. Each invader's unknowns z = (dy, dl) couple only to the 4 dofs s of its
// segment:
//   [K + H_ss   C^T] [du_s]   [b_s]        B = [ M_p + H_yy  -A_y^T ]     C = [ H_ys ]
//   [C          B  ] [z   ] = [b_z],           [ -A_y         0     ],        [ -A_s ],
// B is invertible (A_y = I tied, n^T normal; M_p > 0), so z = B^-1 (b_z - C du_s) and the plate solves
//   (K + H_ss - C^T B^-1 C) du = b_s - C^T B^-1 b_z
// with its own matrix, pattern and KSP (the segment's nodes already share an element). Exact block
// elimination: the same Newton iterates as the saddle-point matrix, to round-off.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "halfeti/core/error.hpp"
#include "halfeti/coupling/contact_system.hpp"

namespace halfeti::coupling {

std::pair<double, double> ContactSystem::assemble_condensed(const std::vector<ContactInvader>& invaders,
                                                            double dt) {
  ScopedTimer timer(timers_, "assembly");
  solver_.assemble_newton_system();  // K_eff and r of the plate in its own (fast) assembly
  structure_force_ = Eigen::VectorXd::Zero(n_struct_);
  force_.assign(static_cast<std::size_t>(n_inv_), Eigen::Vector2d::Zero());
  eliminated_.assign(static_cast<std::size_t>(n_inv_), Eliminated{});
  local_q_.assign(4 * static_cast<std::size_t>(n_inv_), -1);
  Mat a = solver_.newton_matrix();
  Vec rhs = solver_.newton_residual();
  // The plate's rows of eq. 21's residual before the elimination: r + A_s^T lambda (A_s^T lambda added
  // below).
  Eigen::VectorXd plate_rows(n_struct_);
  {
    const PetscScalar* values = nullptr;
    HALFETI_PETSC_CALL(VecGetArrayRead(rhs, &values));
    std::copy(values, values + n_struct_, plate_rows.data());
    HALFETI_PETSC_CALL(VecRestoreArrayRead(rhs, &values));
  }

  double particle2 = 0.0, gap = 0.0;
  const int r = rows_per_, nz = 2 + rows_per_;
  for (int i = 0; i < n_inv_; ++i) {
    const LocalContact lc = local_contact(i, invaders[i], dt);
    const Eigen::Matrix<double, 6, 6> h = -lc.terms.hessian;
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(nz, nz), c = Eigen::MatrixXd::Zero(nz, 4);
    Eigen::VectorXd bz(nz);
    b.topLeftCorner<2, 2>() = h.topLeftCorner<2, 2>() + lc.participation * Eigen::Matrix2d::Identity();
    b.topRightCorner(2, r) = -lc.terms.gradient.topLeftCorner(r, 2).transpose();
    b.bottomLeftCorner(r, 2) = -lc.terms.gradient.topLeftCorner(r, 2);
    c.topRows<2>() = h.block<2, 4>(0, 2);
    c.bottomRows(r) = -lc.terms.gradient.block(0, 2, r, 4);
    bz.head<2>() =
        lc.rhs.head<2>();  // (fixed-size halves: the comma initialiser's dynamic blocks make GCC 12 warn)
    bz.tail(r) = lc.terms.value.head(r);
    particle2 += lc.rhs.head<2>().squaredNorm();
    gap = std::max(gap, lc.terms.value.head(r).cwiseAbs().maxCoeff());

    // B spans ~17 orders of magnitude (2m/dt^2 ~ 1e8 against the constraint's unit entries, Schur pivot
    // -dt^2/2m): a rank-revealing LU would call its last pivot zero. B is invertible by construction, so
    // partial pivoting solves it exactly.
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(b);
    const Eigen::MatrixXd binv_c = lu.solve(c);
    const Eigen::VectorXd binv_b = lu.solve(bz);
    eliminated_[i].binv_c.topRows(nz) = binv_c;
    eliminated_[i].binv_b.head(nz) = binv_b;
    // Row-major 4 x 4 Schur update of the segment's dofs; the right-hand side carries the contact forces too.
    const Eigen::Matrix<double, 4, 4, Eigen::RowMajor> update = h.block<4, 4>(2, 2) - c.transpose() * binv_c;
    const Eigen::Vector4d rhs_s = lc.rhs.segment<4>(2) - c.transpose() * binv_b;
    std::copy(lc.q + 2, lc.q + 6, local_q_.begin() + 4 * i);
    HALFETI_PETSC_CALL(MatSetValues(a, 4, lc.q + 2, 4, lc.q + 2, update.data(), ADD_VALUES));
    add_to_vector(rhs, 4, lc.q + 2, rhs_s.data(), "condensed contact: plate rows of an invader's segment");
  }
  HALFETI_PETSC_CALL(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(VecAssemblyBegin(rhs));
  HALFETI_PETSC_CALL(VecAssemblyEnd(rhs));
  for (int k = 0; k < n_struct_; ++k)
    if (!solver_.is_clamped(k / 2)) plate_rows(k) += structure_force_(k);  // clamped rows carry no residual
  return {std::sqrt(plate_rows.squaredNorm() + particle2), gap};
}

double ContactSystem::solve_condensed(double when) {
  ScopedTimer timer(timers_, "solve");
  Vec du = nullptr;
  try {
    du = solver_.solve_newton_increment();  // the plate's KSP ("-structure_" options)
  } catch (const NumericalError& e) {
    HALFETI_NUMERICAL_ERROR("coupling: condensed contact solve (eq. 21) at t = "
                            << when << " s with " << n_inv_ << " invaders: " << e.what());
  }
  solver_.apply_increment(du, 0);
  const PetscScalar* s = nullptr;
  HALFETI_PETSC_CALL(VecGetArrayRead(du, &s));
  double increment = 0.0;
  for (int k = 0; k < n_struct_; ++k)
    if (!solver_.is_clamped(k / 2)) increment = std::max(increment, std::abs(s[k]));
  for (int i = 0; i < n_inv_; ++i) {
    // Back-substitution: z = B^-1 b_z - B^-1 C du_s.
    Eigen::Vector4d dus = Eigen::Vector4d::Zero();
    const PetscInt* q = local_q_.data() + 4 * i;
    for (int k = 0; k < 4; ++k) dus(k) = q[k] < 0 ? 0.0 : s[q[k]];
    const Eigen::Vector4d z = eliminated_[i].binv_b - eliminated_[i].binv_c * dus;
    y_[i] += z.head<2>();
    increment = std::max(increment, z.head<2>().cwiseAbs().maxCoeff());
    for (int k = 0; k < rows_per_; ++k) lambda_[i](k) += z(2 + k);
  }
  HALFETI_PETSC_CALL(VecRestoreArrayRead(du, &s));
  if (!std::isfinite(increment))
    HALFETI_NUMERICAL_ERROR("coupling: contact Newton increment is not finite at t = " << when << " s");
  return increment;
}

}  // namespace halfeti::coupling
