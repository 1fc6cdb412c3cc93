// Newmark-Newton time stepping of the plate, its loads, state and probes. Assembly is in plate_assembly.cpp.
#include "halfeti/structure/plate_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::structure {

void validate(const StructureParameters& p) {
  const auto& m = p.material;
  if (!(m.density > 0.0))
    HALFETI_USER_ERROR("structure.material.density = " << m.density << " kg/m^3 must be > 0");
  if (!(p.newmark.beta > 0.0 && p.newmark.beta <= 0.5))
    HALFETI_USER_ERROR("structure.newmark.beta = " << p.newmark.beta << " must lie in (0, 0.5]");
  if (!(p.newmark.gamma >= 0.5 && p.newmark.gamma <= 1.0))
    HALFETI_USER_ERROR("structure.newmark.gamma = " << p.newmark.gamma << " must lie in [0.5, 1]");
  if (p.newmark.beta < 0.25 * (p.newmark.gamma + 0.5) * (p.newmark.gamma + 0.5) - 1e-14)
    HALFETI_USER_ERROR("structure.newmark: beta = "
                       << p.newmark.beta
                       << " < (gamma + 1/2)^2 / 4 is only "
                          "conditionally stable; use beta >= "
                       << 0.25 * (p.newmark.gamma + 0.5) * (p.newmark.gamma + 0.5));
  if (p.newton.max_iterations < 1)
    HALFETI_USER_ERROR("structure.newton.max_iterations = " << p.newton.max_iterations << " must be >= 1");
  if (!(p.newton.residual_rtol > 0.0 && p.newton.residual_rtol < 1.0))
    HALFETI_USER_ERROR("structure.newton.residual_rtol = " << p.newton.residual_rtol
                                                           << " must lie in (0, 1)");
  if (!(p.newton.residual_atol >= 0.0))
    HALFETI_USER_ERROR("structure.newton.residual_atol = " << p.newton.residual_atol << " must be >= 0");
  if (!(p.newton.increment_rtol > 0.0))
    HALFETI_USER_ERROR("structure.newton.increment_rtol = " << p.newton.increment_rtol << " must be > 0");
}

PlateSolver::PlateSolver(MPI_Comm comm, const StructureParameters& params,
                         const excitation::GroundMotion* ground)
    : comm_(comm), params_(params), ground_(ground) {
  validate(params_);
  rank_ = comm_.rank();
  size_ = comm_.size();
  mesh_ = make_plate_mesh(params_.geometry);
  partition_ = partition_plate(mesh_, comm_.get());
  const auto& m = params_.material;
  material_ = make_material(m.model, m.youngs_modulus, m.poisson_ratio);
  integrator_ =
      std::make_unique<HyperelasticQ9>(*material_, Q9Options{m.hypothesis, m.selective_reduced_integration});
  integrator4_ = std::make_unique<HyperelasticQ4Eas>(*material_, Q4EasOptions{m.hypothesis});

  const int n = node_count();
  clamped_.assign(n, false);
  for (int c : mesh_.clamped_nodes) clamped_[c] = true;
  mass_row_sum_ = Eigen::VectorXd::Zero(n);
  for (const auto& e : mesh_.quads) {
    Q4Coordinates x;
    for (int a = 0; a < kQ4Nodes; ++a) x.row(a) = mesh_.nodes[e[a]].transpose();
    geometry4_.push_back(HyperelasticQ4Eas::reference_geometry(x));
    mass4_.push_back(HyperelasticQ4Eas::scalar_mass(geometry4_.back(), m.density));
    const Eigen::Matrix<double, kQ4Nodes, 1> rows = mass4_.back().rowwise().sum();
    for (int a = 0; a < kQ4Nodes; ++a) mass_row_sum_(e[a]) += rows(a);
  }
  alpha_.assign(mesh_.quads.size(), EasParameters::Zero());
  alpha_update_.assign(mesh_.quads.size(), EasUpdate::Zero());
  alpha_solved_ = alpha_;
  for (const auto& e : mesh_.elements) {
    Q9Coordinates x;
    for (int a = 0; a < kQ9Nodes; ++a) x.row(a) = mesh_.nodes[e[a]].transpose();
    geometry_.push_back(HyperelasticQ9::reference_geometry(x));
    mass_.push_back(HyperelasticQ9::scalar_mass(geometry_.back(), m.density));
    const Eigen::Matrix<double, kQ9Nodes, 1> rows = mass_.back().rowwise().sum();
    for (int a = 0; a < kQ9Nodes; ++a) mass_row_sum_(e[a]) += rows(a);
  }
  for (auto* v :
       {&prescribed_loads_, &external_forces_, &body_forces_, &residual_, &u_, &v_, &a_, &u_n_, &v_n_, &a_n_})
    *v = Eigen::VectorXd::Zero(dof_count());

  // A direct solve by default (small banded systems); -structure_ksp_type / -structure_pc_type override.
  // One rank: K_eff is symmetric (hyperelastic tangent, cables, Newmark mass), so PETSc's Cholesky on the upper
  // triangle (SeqSBAIJ, block size 2) in the natural order, which is banded (nodes numbered across the
  // thickness first): half the work of the LU (docs/structure.md, "Cost of one Newton iteration"). Several
  // ranks: LU by MUMPS (PETSc's own factorisations are sequential).
  HALFETI_PETSC_CALL(KSPCreate(comm_.get(), ksp_.out()));
  HALFETI_PETSC_CALL(KSPSetOptionsPrefix(ksp_.get(), "structure_"));
  HALFETI_PETSC_CALL(KSPSetType(ksp_.get(), KSPPREONLY));
  PC pc = nullptr;
  HALFETI_PETSC_CALL(KSPGetPC(ksp_.get(), &pc));
  if (size_ > 1) {
    HALFETI_PETSC_CALL(PCSetType(pc, PCLU));
    HALFETI_PETSC_CALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  } else {
    HALFETI_PETSC_CALL(PCSetType(pc, PCCHOLESKY));
    HALFETI_PETSC_CALL(PCFactorSetMatOrderingType(pc, MATORDERINGNATURAL));
  }
  HALFETI_PETSC_CALL(KSPSetFromOptions(ksp_.get()));
  // A PETSc LU chosen on the command line (-structure_pc_type lu) keeps the ordering measured fastest for it,
  // reverse Cuthill-McKee, unless the command line names one.
  PetscBool lu = PETSC_FALSE, ordering_given = PETSC_FALSE;
  HALFETI_PETSC_CALL(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCLU, &lu));
  HALFETI_PETSC_CALL(PetscOptionsHasName(nullptr, "structure_", "-pc_factor_mat_ordering_type", &ordering_given));
  if (lu && size_ == 1 && !ordering_given) HALFETI_PETSC_CALL(PCFactorSetMatOrderingType(pc, MATORDERINGRCM));
}

PlateSolver::~PlateSolver() = default;

void PlateSolver::add_nodal_element(NodalElement* element) {
  HALFETI_CHECK(element != nullptr, "null nodal element");
  for (int n : element->nodes())
    HALFETI_CHECK(n >= 0 && n < node_count(), "nodal element node " << n << " outside the plate mesh");
  nodal_elements_.push_back(element);
  matrix_dirty_ = true;  // its couplings change the sparsity pattern
}

void PlateSolver::add_point_load(int node, const Eigen::Vector2d& force) {
  HALFETI_CHECK(node >= 0 && node < node_count(), "point load on node " << node << " outside the mesh");
  prescribed_loads_.segment<2>(2 * node) += force;
}

void PlateSolver::add_edge_load(const std::string& edge_set, const Eigen::Vector2d& traction) {
  auto it = mesh_.edge_sets.find(edge_set);
  if (it == mesh_.edge_sets.end())
    HALFETI_USER_ERROR("structure: no edge set '" << edge_set << "' (have left, right, top)");
  // Uniform traction on a straight edge: consistent nodal shares 1/6, 2/3, 1/6 of t * length on a quadratic
  // edge, 1/2, 1/2 on a linear one (middle -1).
  for (const auto& edge : it->second) {
    const double length = (mesh_.nodes[edge[2]] - mesh_.nodes[edge[0]]).norm();
    const bool linear = edge[1] < 0;
    const double share[3] = {linear ? 0.5 : 1.0 / 6.0, linear ? 0.0 : 2.0 / 3.0, linear ? 0.5 : 1.0 / 6.0};
    for (int k = 0; k < 3; ++k)
      if (edge[k] >= 0) prescribed_loads_.segment<2>(2 * edge[k]) += share[k] * length * traction;
  }
}

void PlateSolver::clear_loads() {
  prescribed_loads_.setZero();
}

void PlateSolver::set_state(const Eigen::VectorXd& displacement, const Eigen::VectorXd& velocity) {
  HALFETI_CHECK(displacement.size() == dof_count() && velocity.size() == dof_count(), "state of wrong size");
  u_ = displacement;
  v_ = velocity;
  for (int n : mesh_.clamped_nodes) u_.segment<2>(2 * n).setZero(), v_.segment<2>(2 * n).setZero();
  // Q4-EAS: the enhanced parameters are re-solved from zero at the next evaluation (local Newton).
  for (auto& alpha : alpha_) alpha.setZero();
  for (auto& alpha : alpha_solved_) alpha.setZero();
  for (auto& update : alpha_update_) update.setZero();
}

void PlateSolver::set_state(const Eigen::VectorXd& displacement, const Eigen::VectorXd& velocity,
                            const Eigen::VectorXd& acceleration) {
  HALFETI_CHECK(acceleration.size() == dof_count(), "acceleration of wrong size");
  set_state(displacement, velocity);
  a_ = acceleration;
  for (int n : mesh_.clamped_nodes) a_.segment<2>(2 * n).setZero();
}

std::vector<double> PlateSolver::save_state() const {
  const auto n = static_cast<std::size_t>(dof_count());
  std::vector<double> out;
  out.reserve(3 * n + alpha_.size() * kEasModes);
  for (const Eigen::VectorXd* v : {&u_, &v_, &a_}) out.insert(out.end(), v->data(), v->data() + n);
  // Each element's parameters live on the rank that owns it: a sum over ranks of zeros elsewhere is exact.
  std::vector<double> alpha(alpha_.size() * kEasModes, 0.0);
  if (mesh_.element_type == ElementType::kQ4Eas)
    for (int e : partition_.owned_elements)
      for (int m = 0; m < kEasModes; ++m) alpha[static_cast<std::size_t>(e) * kEasModes + m] = alpha_[e](m);
  if (size_ > 1 && !alpha.empty())
    MPI_Allreduce(MPI_IN_PLACE, alpha.data(), static_cast<int>(alpha.size()), MPI_DOUBLE, MPI_SUM, comm_.get());
  out.insert(out.end(), alpha.begin(), alpha.end());
  return out;
}

void PlateSolver::restore_state(const std::vector<double>& state) {
  const auto n = static_cast<std::size_t>(dof_count());
  if (state.size() != 3 * n + alpha_.size() * kEasModes)
    HALFETI_USER_ERROR("restart: the plate's state has " << state.size() << " values, this scene's plate needs "
                                                         << 3 * n + alpha_.size() * kEasModes);
  // The matrix pattern first: its pass evaluates the elements and the nodal elements (a cable's warm start), which
  // the caller restores after this.
  prepare_matrix();
  const double* p = state.data();
  for (Eigen::VectorXd* v : {&u_, &v_, &a_}) {
    std::copy(p, p + n, v->data());
    p += n;
  }
  for (auto& alpha : alpha_)
    for (int m = 0; m < kEasModes; ++m) alpha(m) = *p++;
  alpha_solved_ = alpha_;
}

std::string PlateSolver::summary() const {
  const auto& g = params_.geometry;
  const auto& m = params_.material;
  std::ostringstream os;
  os << "structure: plate " << g.height << " m x " << g.thickness << " m, " << g.cells_across << " x "
     << g.cells_along << (g.element == ElementType::kQ9 ? " Q9 (" : " Q4-EAS (") << mesh_.element_count()
     << " elements, " << dof_count() << " dofs), "
     << to_string(m.model) << " E = " << m.youngs_modulus << " Pa, nu = " << m.poisson_ratio
     << ", rho = " << m.density << " kg/m^3, " << to_string(m.hypothesis) << " per unit depth, "
     << (g.element == ElementType::kQ4Eas              ? "2x2 (enhanced strain)"
         : m.selective_reduced_integration ? "selective reduced"
                                           : "full")
     << " integration, Newmark beta = " << params_.newmark.beta << " gamma = " << params_.newmark.gamma
     << ", ranks = " << size_;
  return os.str();
}

void PlateSolver::initialise_acceleration(double t) {
  mode_ = Mode::kInitialAcceleration;
  ramp_ = 1.0;
  compute_external(t);
  assemble_newton_system();
  a_ = gather_in_node_order(solve_newton_increment());
  for (int n : mesh_.clamped_nodes) a_.segment<2>(2 * n).setZero();
}

void PlateSolver::begin_step(double t, double dt) {
  if (!(dt > 0.0)) HALFETI_NUMERICAL_ERROR("structure: time step " << dt << " s must be positive");
  mode_ = Mode::kDynamic;
  dt_ = dt;
  ramp_ = 1.0;
  u_n_ = u_, v_n_ = v_, a_n_ = a_;
  // Predictor u = u_n: robust when a_n holds stiff high-frequency content (a load just released), where the
  // constant-acceleration guess u_n + dt v_n + dt^2/2 a_n can overshoot into inverted elements.
  u_ = u_n_;
  if (next_predictor_.size() == u_.size()) u_ = next_predictor_;
  next_predictor_.resize(0);
  compute_external(t + dt);
  first_residual_norm_ = -1.0;
  increment_norm_ = -1.0;
  last_ = StepReport{};
}

void PlateSolver::set_next_predictor(const Eigen::VectorXd& u) {
  HALFETI_CHECK(u.size() == dof_count(), "plate predictor of " << u.size() << " values for " << dof_count() << " dofs");
  next_predictor_ = u;
  for (int node = 0; node < node_count(); ++node)  // the clamped rows keep their prescribed (zero) displacement
    if (clamped_[node]) next_predictor_.segment<2>(2 * node) = u_.segment<2>(2 * node);
}

void PlateSolver::begin_static(double t) {
  mode_ = Mode::kStatic;
  ramp_ = 1.0;  // solve_static sets its ramp after this
  compute_external(t);
  first_residual_norm_ = -1.0;
  increment_norm_ = -1.0;
  last_ = StepReport{};
}

Vec PlateSolver::solve_newton_increment() {
  ScopedTimer timer(timers_, "structure_solve");
  const KSPConvergedReason reason = solve_with(ksp_.get(), matrix_.get(), rhs_.get(), solution_.get());
  if (reason < 0)
    HALFETI_NUMERICAL_ERROR("structure: KSP solve failed (" << when() << "), " << ksp_failure(ksp_.get(), reason)
                                                                  << "; try -structure_pc_type lu");
  return solution_.get();
}

void PlateSolver::apply_increment(const double* du) {
  double largest = 0.0;
  for (int i = 0; i < dof_count(); ++i) {
    if (clamped_[i / 2]) continue;
    u_(i) += du[i];
    largest = std::max(largest, std::abs(du[i]));
  }
  if (!std::isfinite(largest)) HALFETI_NUMERICAL_ERROR("structure: Newton increment is not finite (NaN/Inf)");
  increment_norm_ = largest;
  last_.increment_norm = largest;
  // Q4-EAS element state after the increment (Simo & Armero 1992): alpha = alpha_solved + (d alpha / du) du_e,
  // the linearisation of the condensed enhanced equilibrium at the last full assembly.
  for (int e : partition_.owned_elements) {
    if (mesh_.element_type != ElementType::kQ4Eas) break;
    Eigen::Matrix<double, kQ4Dofs, 1> du_e;  // component-major
    for (int a = 0; a < kQ4Nodes; ++a) {
      const int n = mesh_.quads[e][a];
      for (int c = 0; c < 2; ++c) du_e(kQ4Nodes * c + a) = clamped_[n] ? 0.0 : du[2 * n + c];
    }
    alpha_[e] = alpha_solved_[e];
    alpha_[e].noalias() += alpha_update_[e] * du_e;
  }
  ++last_.newton_iterations;
}

void PlateSolver::apply_increment(Vec du, PetscInt offset) {
  if (size_ == 1) {
    const PetscScalar* values = nullptr;
    HALFETI_PETSC_CALL(VecGetArrayRead(du, &values));
    apply_increment(values + offset);
    HALFETI_PETSC_CALL(VecRestoreArrayRead(du, &values));
    return;
  }
  HALFETI_CHECK(offset == 0, "on several ranks apply_increment takes the structure's own layout (offset 0)");
  const Eigen::VectorXd increment = gather_in_node_order(du);
  apply_increment(increment.data());
}

Eigen::VectorXd PlateSolver::gather_in_node_order(Vec v) {
  Eigen::VectorXd out(dof_count());
  if (size_ == 1) {
    const PetscScalar* values = nullptr;
    HALFETI_PETSC_CALL(VecGetArrayRead(v, &values));
    std::copy(values, values + dof_count(), out.data());
    HALFETI_PETSC_CALL(VecRestoreArrayRead(v, &values));
    return out;
  }
  if (to_all_.get() == nullptr) HALFETI_PETSC_CALL(VecScatterCreateToAll(v, to_all_.out(), gathered_.out()));
  HALFETI_PETSC_CALL(VecScatterBegin(to_all_.get(), v, gathered_.get(), INSERT_VALUES, SCATTER_FORWARD));
  HALFETI_PETSC_CALL(VecScatterEnd(to_all_.get(), v, gathered_.get(), INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* values = nullptr;
  HALFETI_PETSC_CALL(VecGetArrayRead(gathered_.get(), &values));
  for (int n = 0; n < node_count(); ++n)
    for (int c = 0; c < 2; ++c) out(2 * n + c) = values[petsc_dof(n, c)];
  HALFETI_PETSC_CALL(VecRestoreArrayRead(gathered_.get(), &values));
  return out;
}

double PlateSolver::sum_over_ranks(double local) const {
  double total = local;
  if (size_ > 1) MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, comm_.get());
  return total;
}

bool PlateSolver::converged() const {
  const auto& nt = params_.newton;
  const bool residual_small = residual_norm_ <= std::max(nt.residual_atol, nt.residual_rtol * force_scale_);
  const bool increment_small =
      increment_norm_ >= 0.0 && increment_norm_ <= nt.increment_rtol * params_.geometry.height;
  return residual_small || increment_small;
}

void PlateSolver::end_step() {
  if (mode_ == Mode::kDynamic) {
    update_acceleration();
    v_ = v_n_ + dt_ * ((1.0 - params_.newmark.gamma) * a_n_ + params_.newmark.gamma * a_);
  }
  last_.residual_norm = residual_norm_;
}

// The plate-alone Newton loop shared by step() and solve_static(). After an increment the convergence test needs
// the residual only: it is computed without the tangent (a third of the element cost), and the full system is
// assembled only when another iteration follows. The residual is the same either way (the same element force
// code), so the iterates are those of assembling the full system every time (the split-API test checks this
// bit for bit).
void PlateSolver::newton_loop(const char* what) {
  const int max_iterations = params_.newton.max_iterations;
  assemble_newton_system();
  for (;;) {
    if (converged()) return;
    if (last_.newton_iterations >= max_iterations)
      HALFETI_NUMERICAL_ERROR("structure: Newton did not converge in "
                              << max_iterations << " iterations (" << what << ", " << when()
                              << "): ||r|| = " << residual_norm() << " N/m, last ||du||_inf = "
                              << last_.increment_norm << " m");
    apply_increment(solve_newton_increment());
    if (converged()) return;
    assemble_residual();
    if (converged()) return;
    assemble_newton_system();
  }
}

std::string PlateSolver::when() const {
  // The static start solves the tank at rest, before the motion starts (its loads are those of t = -1 s).
  if (mode_ == Mode::kStatic) return "in the static start, the tank at rest before t = 0";
  std::ostringstream os;
  os << "t = " << time_ << " s";
  return os.str();
}

StepReport PlateSolver::step(double t, double dt) {
  begin_step(t, dt);
  newton_loop("time step");
  end_step();
  return last_;
}

StepReport PlateSolver::solve_static(double t, int load_increments) {
  if (load_increments < 1)
    HALFETI_USER_ERROR("structure: load_increments " << load_increments << " must be >= 1");
  StepReport total;
  for (int k = 1; k <= load_increments; ++k) {
    begin_static(t);
    ramp_ = double(k) / load_increments;
    newton_loop("static solve");
    end_step();
    total.newton_iterations += last_.newton_iterations;
  }
  ramp_ = 1.0;
  total.residual_norm = last_.residual_norm;
  total.increment_norm = last_.increment_norm;
  return total;
}

double PlateSolver::strain_energy() const {
  double e = 0.0;
  for (int k : partition_.owned_elements) e += element_energy(k);
  return sum_over_ranks(e);
}

double PlateSolver::element_energy(int k) const {
  return mesh_.element_type == ElementType::kQ9 ? integrator_->energy(geometry_[k], element_displacement(k))
                                                : integrator4_->energy(geometry4_[k], quad_displacement(k), alpha_[k]);
}

double PlateSolver::gravity_potential_energy() const {
  // The nodal masses are M's row sums (compute_external): for the uniform field g, -u^T M g exactly. Every node is
  // on this rank (the plate's state is replicated), so no sum over ranks.
  double e = 0.0;
  for (int n = 0; n < node_count(); ++n) e -= mass_row_sum_(n) * params_.gravity.dot(u_.segment<2>(2 * n));
  return e;
}

double PlateSolver::kinetic_energy() const {
  double e = 0.0;
  for (int k : partition_.owned_elements) {
    const int* nodes = mesh_.element_nodes(k);
    const int nn = mesh_.nodes_per_element();
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b)
        e += 0.5 * (nn == kQ9Nodes ? mass_[k](a, b) : mass4_[k](a, b)) *
             v_.segment<2>(2 * nodes[a]).dot(v_.segment<2>(2 * nodes[b]));
  }
  return sum_over_ranks(e);
}

double PlateSolver::element_von_mises(int element) const {
  HALFETI_CHECK(element >= 0 && element < mesh_.element_count(), "no element " << element);
  double sum = 0.0;
  if (mesh_.element_type == ElementType::kQ4Eas) {
    for (const auto& s : integrator4_->cauchy_at_points(geometry4_[element], quad_displacement(element), alpha_[element]))
      sum += von_mises(s);
    return sum / 4.0;
  }
  for (const auto& s : integrator_->cauchy_at_points(geometry_[element], element_displacement(element)))
    sum += von_mises(s);
  return sum / 9.0;
}

void PlateSolver::element_fields(std::vector<double>& von_mises, std::vector<double>& energy_density) const {
  const int n = mesh_.element_count();
  std::vector<double> both(2 * static_cast<std::size_t>(n), 0.0);  // each element from its one owner, summed
  const double density = params_.material.density;
  for (int k : partition_.owned_elements) {
    const bool q4 = mesh_.element_type == ElementType::kQ4Eas;
    const double area = (q4 ? mass4_[k].sum() : mass_[k].sum()) / density;  // the scalar mass sums to rho A
    both[2 * k] = element_von_mises(k);
    both[2 * k + 1] = element_energy(k) / area;
  }
  if (size_ > 1) MPI_Allreduce(MPI_IN_PLACE, both.data(), 2 * n, MPI_DOUBLE, MPI_SUM, comm_.get());
  von_mises.resize(static_cast<std::size_t>(n));
  energy_density.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    von_mises[k] = both[2 * k];
    energy_density[k] = both[2 * k + 1];
  }
}

double PlateSolver::max_von_mises() const {
  double m = 0.0;
  for (int k : partition_.owned_elements) {
    if (mesh_.element_type == ElementType::kQ4Eas) {
      for (const auto& s : integrator4_->cauchy_at_points(geometry4_[k], quad_displacement(k), alpha_[k]))
        m = std::max(m, von_mises(s));
      continue;
    }
    for (const auto& s : integrator_->cauchy_at_points(geometry_[k], element_displacement(k)))
      m = std::max(m, von_mises(s));
  }
  double global = m;
  if (size_ > 1) MPI_Allreduce(&m, &global, 1, MPI_DOUBLE, MPI_MAX, comm_.get());
  return global;
}

}  // namespace halfeti::structure
