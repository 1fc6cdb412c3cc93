// Assembly and Newton solution of eq. 21 with the plate (see the header for the block layout).
#include "halfeti/coupling/contact_system.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "halfeti/core/error.hpp"

namespace halfeti::coupling {

using structure::PlateSolver;

SurfacePolyline ContactSystem::surface(const PlateSolver& solver) {
  SurfacePolyline s;
  const auto& segments = solver.mesh().surface;
  if (segments.empty()) return s;
  s.nodes.push_back(segments.front().first);
  for (const auto& seg : segments) s.nodes.push_back(seg.second);
  for (int n : s.nodes) s.points.push_back(solver.position(n));
  return s;
}

ContactSystem::ContactSystem(PlateSolver& solver, ContactConstraint form, std::string options_prefix,
                             ContactSolver method, double participation)
    : solver_(solver),
      form_(form),
      prefix_(std::move(options_prefix)),
      method_(method),
      participation_(participation),
      rows_per_(constraint_rows(form)) {
  // The system is built on the structure's rank with the plate's node numbering as PETSc's: one structure
  // rank.
  for (int n = 0; n < solver_.node_count(); ++n)
    for (int c = 0; c < 2; ++c)
      HALFETI_CHECK(solver_.petsc_dof(n, c) == PlateSolver::dof(n, c),
                    "the contact coupling needs the plate on one rank (structure.ranks: 1)");
}

ContactSystem::LocalContact ContactSystem::local_contact(int i, const ContactInvader& inv, double dt) {
  LocalContact lc;
  const auto& seg = solver_.mesh().surface[static_cast<std::size_t>(inv.segment)];
  lc.terms = evaluate_constraint(form_, y_[i], solver_.position(seg.first), solver_.position(seg.second),
                                 inv.eta, inv.target_gap, lambda_[i]);
  lc.q[0] = n_struct_ + 2 * i;
  lc.q[1] = lc.q[0] + 1;
  for (int c = 0; c < 2; ++c) {
    lc.q[2 + c] = solver_.is_clamped(seg.first) ? -1 : 2 * seg.first + c;  // negative: PETSc skips
    lc.q[4 + c] = solver_.is_clamped(seg.second) ? -1 : 2 * seg.second + c;
  }
  // The invader's mass participation (section 2.3): the paper's 2/dt^2 (constant acceleration over the step),
  // or 1/dt^2, the fluid's own kick-drift step (docs/coupling.md).
  lc.participation = participation_ * inv.mass / (dt * dt);
  lc.rhs = contact_forces(lc.terms, lambda_[i]);
  force_[i] = lc.rhs.head<2>();
  structure_force_.segment<2>(2 * seg.first) += lc.rhs.segment<2>(2);
  structure_force_.segment<2>(2 * seg.second) += lc.rhs.segment<2>(4);
  lc.rhs.head<2>() -= lc.participation * (y_[i] - inv.predicted);
  return lc;
}

void ContactSystem::build(const std::vector<ContactInvader>& invaders) {
  n_struct_ = solver_.dof_count();
  n_inv_ = static_cast<int>(invaders.size());
  const int n_particle = 2 * n_inv_, n_mult = rows_per_ * n_inv_;
  const PetscInt total = n_struct_ + n_particle + n_mult;
  const auto& surface = solver_.mesh().surface;

  // Preallocation from the plate's graph plus each invader's couplings: its 2 dofs, its segment's 4 dofs and
  // its multipliers. Rows of a segment node gain the invader's 2 + rows_per_ columns (the node pair is
  // already coupled through their element).
  std::vector<PetscInt> nnz(static_cast<std::size_t>(total), 0);
  const auto adjacency = solver_.node_adjacency();
  for (int node = 0; node < solver_.node_count(); ++node)
    for (int c = 0; c < 2; ++c) nnz[2 * node + c] = 2 * static_cast<PetscInt>(adjacency[node].size());
  for (int i = 0; i < n_inv_; ++i) {
    const auto& seg = surface.at(static_cast<std::size_t>(invaders[i].segment));
    for (int node : {seg.first, seg.second})
      for (int c = 0; c < 2; ++c) nnz[2 * node + c] += 2 + rows_per_;
    for (int c = 0; c < 2; ++c) nnz[n_struct_ + 2 * i + c] = 6 + rows_per_;
    for (int k = 0; k < rows_per_; ++k) nnz[n_struct_ + n_particle + rows_per_ * i + k] = 7;  // 6 + diagonal
  }
  for (auto& v : nnz) v = std::min<PetscInt>(v, total);
  HALFETI_PETSC_CALL(MatCreateSeqAIJ(PETSC_COMM_SELF, total, total, 0, nnz.data(), matrix_.out()));
  HALFETI_PETSC_CALL(MatSetOptionsPrefix(matrix_.get(), prefix_.c_str()));
  HALFETI_PETSC_CALL(MatSetOption(matrix_.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  HALFETI_PETSC_CALL(MatCreateVecs(matrix_.get(), solution_.out(), rhs_.out()));

  // A new KSP per system size: the field index sets change with the invader count. Defaults, then options
  // last.
  HALFETI_PETSC_CALL(KSPCreate(PETSC_COMM_SELF, ksp_.out()));
  HALFETI_PETSC_CALL(KSPSetOptionsPrefix(ksp_.get(), prefix_.c_str()));
  HALFETI_PETSC_CALL(KSPSetType(ksp_.get(), KSPPREONLY));
  PC pc = nullptr;
  HALFETI_PETSC_CALL(KSPGetPC(ksp_.get(), &pc));
  HALFETI_PETSC_CALL(PCSetType(pc, PCLU));
  // The zero block needs pivoting: MUMPS (PETSc's own LU stops at the first zero pivot).
  HALFETI_PETSC_CALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  HALFETI_PETSC_CALL(KSPSetFromOptions(ksp_.get()));
  PetscBool fieldsplit = PETSC_FALSE;
  HALFETI_PETSC_CALL(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCFIELDSPLIT, &fieldsplit));
  if (fieldsplit) {
    IS primal = nullptr, contact = nullptr;
    HALFETI_PETSC_CALL(ISCreateStride(PETSC_COMM_SELF, n_struct_ + n_particle, 0, 1, &primal));
    HALFETI_PETSC_CALL(ISCreateStride(PETSC_COMM_SELF, n_mult, n_struct_ + n_particle, 1, &contact));
    HALFETI_PETSC_CALL(PCFieldSplitSetIS(pc, "primal", primal));
    HALFETI_PETSC_CALL(PCFieldSplitSetIS(pc, "contact", contact));
    HALFETI_PETSC_CALL(ISDestroy(&primal));
    HALFETI_PETSC_CALL(ISDestroy(&contact));
  }
}

std::pair<double, double> ContactSystem::assemble(const std::vector<ContactInvader>& invaders, double dt) {
  ScopedTimer timer(timers_, "assembly");
  Mat a = matrix_.get();
  Vec rhs = rhs_.get();
  PetscBool assembled = PETSC_FALSE;
  HALFETI_PETSC_CALL(MatAssembled(a, &assembled));
  if (assembled) HALFETI_PETSC_CALL(MatZeroEntries(a));
  HALFETI_PETSC_CALL(VecSet(rhs, 0.0));
  solver_.add_newton_system(a, rhs,
                            0);  // K_solid + K_cable + Newmark mass, r = R - F - M a (eq. 21, top rows)

  const int n_particle = 2 * n_inv_;
  structure_force_ = Eigen::VectorXd::Zero(n_struct_);
  force_.assign(static_cast<std::size_t>(n_inv_), Eigen::Vector2d::Zero());
  for (int i = 0; i < n_inv_; ++i) {
    LocalContact lc = local_contact(i, invaders[i], dt);
    const ConstraintTerms& terms = lc.terms;
    PetscInt* q = lc.q;
    PetscInt mult[2];
    for (int k = 0; k < rows_per_; ++k) mult[k] = n_struct_ + n_particle + rows_per_ * i + k;

    // H = -d2(lambda . c): the geometric part of the contact stiffness (symmetric).
    const Eigen::Matrix<double, 6, 6> h = -terms.hessian;
    HALFETI_PETSC_CALL(MatSetValues(a, 6, q, 6, q, h.data(), ADD_VALUES));
    for (int c = 0; c < 2; ++c) HALFETI_PETSC_CALL(MatSetValue(a, q[c], q[c], lc.participation, ADD_VALUES));
    // K_c and K_c^T of eq. 21: -A^T in the multiplier columns, -A in the multiplier rows; explicit zero
    // diagonal.
    double rows_q[6 * 2], rows_m[2 * 6];
    for (int r = 0; r < 6; ++r)
      for (int k = 0; k < rows_per_; ++k) {
        rows_q[r * rows_per_ + k] = -terms.gradient(k, r);
        rows_m[k * 6 + r] = -terms.gradient(k, r);
      }
    HALFETI_PETSC_CALL(MatSetValues(a, 6, q, rows_per_, mult, rows_q, ADD_VALUES));
    HALFETI_PETSC_CALL(MatSetValues(a, rows_per_, mult, 6, q, rows_m, ADD_VALUES));
    for (int k = 0; k < rows_per_; ++k) HALFETI_PETSC_CALL(MatSetValue(a, mult[k], mult[k], 0.0, ADD_VALUES));
    // Right-hand side: contact forces A^T lambda on plate and particle, the particle's inertia, the overlap
    // c.
    add_to_vector(rhs, 6, q, lc.rhs.data(), "contact: rows of an invader and its segment");
    add_to_vector(rhs, rows_per_, mult, terms.value.data(), "contact: an invader's multiplier rows");
  }
  HALFETI_PETSC_CALL(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(VecAssemblyBegin(rhs));
  HALFETI_PETSC_CALL(VecAssemblyEnd(rhs));

  const PetscScalar* r = nullptr;
  HALFETI_PETSC_CALL(VecGetArrayRead(rhs, &r));
  double force2 = 0.0, gap = 0.0;
  for (int k = 0; k < n_struct_ + n_particle; ++k) force2 += r[k] * r[k];
  for (int k = n_struct_ + n_particle; k < n_struct_ + n_particle + rows_per_ * n_inv_; ++k)
    gap = std::max(gap, std::abs(r[k]));
  HALFETI_PETSC_CALL(VecRestoreArrayRead(rhs, &r));
  return {std::sqrt(force2), gap};
}

void ContactSystem::solve_linear(double when) {
  ScopedTimer timer(timers_, "solve");
  const KSPConvergedReason reason = solve_with(ksp_.get(), matrix_.get(), rhs_.get(), solution_.get());
  if (reason < 0)
    HALFETI_NUMERICAL_ERROR("coupling: contact solve (eq. 21) failed at t = "
                            << when << " s with " << n_inv_
                            << " invaders: " << ksp_failure(ksp_.get(), reason) << "; the default is -"
                            << prefix_ << "pc_type lu -" << prefix_ << "pc_factor_mat_solver_type mumps");
}

ContactSolveReport ContactSystem::solve(const std::vector<ContactInvader>& invaders, double dt, double when) {
  HALFETI_CHECK(dt > 0.0, "contact solve needs dt > 0 for the mass participation");
  for (const auto& inv : invaders)
    HALFETI_CHECK(
        inv.mass > 0.0 && inv.segment >= 0 && inv.segment < static_cast<int>(solver_.mesh().surface.size()),
        "invader with mass " << inv.mass << " on segment " << inv.segment);
  ContactSolveReport report;
  y_.clear();
  for (const auto& inv : invaders) y_.push_back(inv.predicted);
  lambda_.assign(invaders.size(), Eigen::Vector2d::Zero());
  n_struct_ = solver_.dof_count();
  n_inv_ = static_cast<int>(invaders.size());
  if (method_ == ContactSolver::kSaddlePoint) {
    ScopedTimer timer(timers_, "setup");
    build(invaders);
  }
  const auto& newton = solver_.parameters().newton;
  const double length_tolerance = newton.increment_rtol * solver_.parameters().geometry.height;
  double reference = 0.0, increment = -1.0;
  for (;;) {
    const auto [force_norm, gap_norm] =
        method_ == ContactSolver::kSaddlePoint ? assemble(invaders, dt) : assemble_condensed(invaders, dt);
    report.residual_history.push_back(force_norm);
    report.gap_history.push_back(gap_norm);
    double contact_norm = 0.0;
    for (const auto& f : force_) contact_norm += f.squaredNorm();
    reference = std::max({reference, report.residual_history.front(), std::sqrt(contact_norm)});
    const bool residual_small =
        force_norm <= std::max(newton.residual_atol, newton.residual_rtol * reference) &&
        gap_norm <= length_tolerance;
    const bool increment_small = increment >= 0.0 && increment <= length_tolerance;
    if (residual_small || increment_small) break;
    if (report.iterations >= newton.max_iterations)
      HALFETI_NUMERICAL_ERROR("coupling: contact Newton (eq. 21) did not converge in "
                              << newton.max_iterations << " iterations at t = " << when << " s with "
                              << n_inv_ << " invaders: ||r|| = " << force_norm << " N/m, overlap residual "
                              << gap_norm << " m, last increment " << increment << " m");
    const auto start = std::chrono::steady_clock::now();
    if (method_ == ContactSolver::kCondensed) {
      increment = solve_condensed(when);
      report.solve_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ++report.iterations;
      continue;
    }
    solve_linear(when);
    report.solve_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++report.iterations;

    solver_.apply_increment(solution_.get(), 0);
    const PetscScalar* s = nullptr;
    HALFETI_PETSC_CALL(VecGetArrayRead(solution_.get(), &s));
    increment = 0.0;
    for (int k = 0; k < n_struct_; ++k)
      if (!solver_.is_clamped(k / 2)) increment = std::max(increment, std::abs(s[k]));
    for (int i = 0; i < n_inv_; ++i) {
      const Eigen::Vector2d dy(s[n_struct_ + 2 * i], s[n_struct_ + 2 * i + 1]);
      y_[i] += dy;
      increment = std::max(increment, dy.cwiseAbs().maxCoeff());
      for (int k = 0; k < rows_per_; ++k) lambda_[i](k) += s[n_struct_ + 2 * n_inv_ + rows_per_ * i + k];
    }
    HALFETI_PETSC_CALL(VecRestoreArrayRead(solution_.get(), &s));
    if (!std::isfinite(increment))
      HALFETI_NUMERICAL_ERROR("coupling: contact Newton increment is not finite at t = " << when << " s");
  }
  return report;
}

}  // namespace halfeti::coupling
