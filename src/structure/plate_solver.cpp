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
  validate(p.newmark);
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

namespace {
const StructureParameters& validated(const StructureParameters& p) {
  validate(p);
  return p;
}

PlateElements make_family(const Material& material, const PlateMaterialParameters& m, const PlateMesh& mesh) {
  if (mesh.element_type == ElementType::kQ4Eas)
    return PlateElements(std::in_place_type<Q4EasFamily>, material, Q4EasOptions{m.hypothesis}, mesh,
                         m.density);
  return PlateElements(std::in_place_type<Q9Family>, material,
                       Q9Options{m.hypothesis, m.selective_reduced_integration}, mesh, m.density);
}

// The length of the restart's element state (Q4-EAS: the enhanced parameters of every element; Q9: none).
template <typename Family>
std::size_t element_state_size(const Family& family) {
  return static_cast<std::size_t>(family.count()) * Family::kStatePerElement;
}
}  // namespace

PlateSolver::PlateSolver(MPI_Comm comm, const StructureParameters& params,
                         const excitation::GroundMotion* ground)
    : comm_(comm),
      params_(validated(params)),
      ground_(ground),
      mesh_(make_plate_mesh(params_.geometry)),
      material_(make_material(params_.material.model, params_.material.youngs_modulus,
                              params_.material.poisson_ratio)),
      family_(make_family(*material_, params_.material, mesh_)),
      newmark_(params_.newmark) {
  rank_ = comm_.rank();
  size_ = comm_.size();
  partition_ = partition_plate(mesh_, comm_.get());

  const int n = node_count();
  clamped_.assign(n, false);
  for (int c : mesh_.clamped_nodes) clamped_[c] = true;
  // Nodal masses (the consistent mass's row sums), for the body forces.
  mass_row_sum_ = Eigen::VectorXd::Zero(n);
  with_family([&](const auto& family) {
    using Family = std::decay_t<decltype(family)>;
    for (int e = 0; e < family.count(); ++e) {
      const Eigen::Matrix<double, Family::kNodes, 1> rows = family.mass(e).rowwise().sum();
      for (int a = 0; a < Family::kNodes; ++a) mass_row_sum_(family.nodes(e)[a]) += rows(a);
    }
  });
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
  HALFETI_PETSC_CALL(
      PetscOptionsHasName(nullptr, "structure_", "-pc_factor_mat_ordering_type", &ordering_given));
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
  with_family([](auto& family) { family.reset_state(); });
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
  for (const Eigen::VectorXd* v : {&u_, &v_, &a_}) out.insert(out.end(), v->data(), v->data() + n);
  // Each element's state (Q4-EAS: its enhanced parameters) lives on the rank that owns it: a sum over ranks of
  // zeros elsewhere is exact.
  std::vector<double> elements = with_family([&](const auto& family) {
    constexpr int k = std::decay_t<decltype(family)>::kStatePerElement;
    std::vector<double> state(element_state_size(family), 0.0);
    if (k > 0)
      for (int e : partition_.owned_elements) family.save_state(e, &state[static_cast<std::size_t>(e) * k]);
    return state;
  });
  if (size_ > 1 && !elements.empty())
    MPI_Allreduce(MPI_IN_PLACE, elements.data(), static_cast<int>(elements.size()), MPI_DOUBLE, MPI_SUM,
                  comm_.get());
  out.insert(out.end(), elements.begin(), elements.end());
  return out;
}

void PlateSolver::restore_state(const std::vector<double>& state) {
  const auto n = static_cast<std::size_t>(dof_count());
  const std::size_t element_state = with_family([](const auto& f) { return element_state_size(f); });
  if (state.size() != 3 * n + element_state)
    HALFETI_USER_ERROR("restart: the plate's state has "
                       << state.size() << " values, this scene's plate needs " << 3 * n + element_state);
  // The matrix pattern first: its pass evaluates the elements and the nodal elements (a cable's warm start), which
  // the caller restores after this.
  prepare_matrix();
  const double* p = state.data();
  for (Eigen::VectorXd* v : {&u_, &v_, &a_}) {
    std::copy(p, p + n, v->data());
    p += n;
  }
  with_family([&](auto& family) {
    constexpr int k = std::decay_t<decltype(family)>::kStatePerElement;
    for (int e = 0; k > 0 && e < family.count(); ++e)
      family.restore_state(e, p + static_cast<std::size_t>(e) * k);
  });
}

std::string PlateSolver::summary() const {
  const auto& g = params_.geometry;
  const auto& m = params_.material;
  std::ostringstream os;
  os << "structure: plate " << g.height << " m x " << g.thickness << " m, " << g.cells_across << " x "
     << g.cells_along << " " << with_family([](const auto& f) { return f.kName; }) << " ("
     << mesh_.element_count() << " elements, " << dof_count() << " dofs), " << to_string(m.model)
     << " E = " << m.youngs_modulus << " Pa, nu = " << m.poisson_ratio << ", rho = " << m.density
     << " kg/m^3, " << to_string(m.hypothesis) << " per unit depth, "
     << with_family([](const auto& f) { return f.integration(); })
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
  HALFETI_CHECK(u.size() == dof_count(),
                "plate predictor of " << u.size() << " values for " << dof_count() << " dofs");
  next_predictor_ = u;
  // The clamped rows keep their prescribed (zero) displacement.
  for (int node = 0; node < node_count(); ++node)
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
    HALFETI_NUMERICAL_ERROR("structure: KSP solve failed (" << when() << "), "
                                                            << ksp_failure(ksp_.get(), reason)
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
  // The elements' own state after the increment (Q4-EAS: the enhanced parameters).
  with_family([&](auto& family) {
    using Family = std::decay_t<decltype(family)>;
    if (Family::kStatePerElement == 0) return;
    constexpr int nn = Family::kNodes;
    Eigen::Matrix<double, 2 * nn, 1> du_e;  // component-major
    for (int e : partition_.owned_elements) {
      for (int a = 0; a < nn; ++a) {
        const int n = family.nodes(e)[a];
        for (int c = 0; c < 2; ++c) du_e(nn * c + a) = clamped_[n] ? 0.0 : du[2 * n + c];
      }
      family.apply_increment(e, du_e);
    }
  });
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
    newmark_.velocity(v_n_, a_n_, a_, dt_, v_);
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
                              << "): ||r|| = " << residual_norm()
                              << " N/m, last ||du||_inf = " << last_.increment_norm << " m");
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
  return with_family([&](const auto& family) { return family.energy(k, family.displacement(k, u_)); });
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
  with_family([&](const auto& family) {
    constexpr int nn = std::decay_t<decltype(family)>::kNodes;
    for (int k : partition_.owned_elements) {
      const auto& nodes = family.nodes(k);
      for (int a = 0; a < nn; ++a)
        for (int b = 0; b < nn; ++b)
          e += 0.5 * family.mass(k)(a, b) * v_.segment<2>(2 * nodes[a]).dot(v_.segment<2>(2 * nodes[b]));
    }
  });
  return sum_over_ranks(e);
}

double PlateSolver::element_von_mises(int element) const {
  HALFETI_CHECK(element >= 0 && element < mesh_.element_count(), "no element " << element);
  return with_family([&](const auto& family) {
    double sum = 0.0;
    const auto points = family.cauchy_at_points(element, family.displacement(element, u_));
    for (const auto& s : points) sum += von_mises(s);
    return sum / static_cast<double>(points.size());
  });
}

void PlateSolver::element_fields(std::vector<double>& von_mises, std::vector<double>& energy_density) const {
  const int n = mesh_.element_count();
  std::vector<double> both(2 * static_cast<std::size_t>(n), 0.0);  // each element from its one owner, summed
  const double density = params_.material.density;
  for (int k : partition_.owned_elements) {
    const double area =
        with_family([&](const auto& f) { return f.mass(k).sum(); }) / density;  // sums to rho A
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
  with_family([&](const auto& family) {
    for (int k : partition_.owned_elements)
      for (const auto& s : family.cauchy_at_points(k, family.displacement(k, u_)))
        m = std::max(m, von_mises(s));
  });
  double global = m;
  if (size_ > 1) MPI_Allreduce(&m, &global, 1, MPI_DOUBLE, MPI_MAX, comm_.get());
  return global;
}

}  // namespace halfeti::structure
