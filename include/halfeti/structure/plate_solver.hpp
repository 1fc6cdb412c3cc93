// The rubber plate in time: Newmark time integration with Newton iterations on PETSc (the global assembly
// layer).
//
// Sign convention of one Newton iteration (eq. 21 without the contact rows):
//   K_eff du = r,   K_eff = K_solid + K_nodal + c0 M,   r = R - F - M a,
// with R the external loads at t + dt, F the internal forces (solid elements and NodalElements such as
// cables), a the Newmark acceleration of the current iterate and c0 = 1 / (beta dt^2). The clamped base rows
// are identity with a zero right-hand side. The coupling adds its contact rows and columns (eq. 21) by having
// add_newton_system() write K_eff and r into a larger matrix of its own at an offset, solving that, and
// handing the displacement part of the solution back to apply_increment():
//
//   solver.begin_step(t, dt);
//   for (;;) {
//     assemble (solver.assemble_newton_system(), or add_newton_system(A, b, offset) + contact rows);
//     if (solver.converged()) break;          // residual test
//     solve; solver.apply_increment(du);
//     if (solver.converged()) break;          // increment test
//   }
//   solver.end_step();
//
// step(t, dt) is that loop with the plate alone (its check after an increment assembles the residual only, which
// gives the same residual bits, so the same iterates).
//
// Ranks: the structure runs on its own communicator. With more than one rank the elements are split by METIS,
// the matrix is MPIAIJ in PETSc's numbering petsc_dof() (rows by owner rank) and solved with MUMPS; the state
// (u, v, a), the residual and all probes stay replicated on every rank (the plate has ~1e3 dofs), so every
// rank takes the same Newton decisions. On one rank PETSc's numbering is the node numbering.
#pragma once

#include <mpi.h>
#include <petscksp.h>

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "halfeti/core/communicator.hpp"
#include "halfeti/core/nodal_element.hpp"
#include "halfeti/core/petsc_owner.hpp"
#include "halfeti/core/timers.hpp"
#include "halfeti/excitation/ground_motion.hpp"
#include "halfeti/structure/element_family.hpp"
#include "halfeti/structure/material.hpp"
#include "halfeti/structure/newmark.hpp"
#include "halfeti/structure/plate_mesh.hpp"
#include "halfeti/structure/plate_partition.hpp"

namespace halfeti::structure {

struct PlateMaterialParameters {
  MaterialModel model = MaterialModel::kNeoHookean;
  double youngs_modulus = 10.0e6;  // Pa, > 0 (paper: 10 MPa)
  double poisson_ratio = 0.45;     // (-1, 0.5); rubber 0.45-0.49 (not stated by the paper)
  double density = 1150.0;         // kg/m^3, > 0 (not stated by the paper; natural rubber 1100-1200)
  PlaneHypothesis hypothesis = PlaneHypothesis::kPlaneStrain;
  bool selective_reduced_integration =
      true;  // 2x2 Gauss on the lambda part (plane strain), see q9_element.hpp
};

struct NewtonParameters {
  int max_iterations = 25;        // >= 1
  double residual_rtol = 1e-6;    // ||r|| / max(||r_first||, ||R||, ||F + M a||) of the iteration, (0, 1)
  double residual_atol = 1e-12;   // N/m, >= 0
  double increment_rtol = 1e-10;  // ||du||_inf / plate height, > 0
};

struct StructureParameters {
  PlateGeometry geometry;
  PlateMaterialParameters material;
  NewmarkParameters newmark;
  NewtonParameters newton;
  Eigen::Vector2d gravity{0.0, -9.81};  // m/s^2, tank frame
};

void validate(const StructureParameters& p);  // UserError naming the parameter and its range

struct StepReport {
  int newton_iterations = 0;
  double residual_norm = 0.0;   // N/m, at the last assembly
  double increment_norm = 0.0;  // m, inf-norm of the last increment
};

class PlateSolver {
 public:
  // comm: the structure's communicator (duplicated). ground may be null (no tank motion); it must outlive
  // this.
  PlateSolver(MPI_Comm comm, const StructureParameters& params,
              const excitation::GroundMotion* ground = nullptr);
  ~PlateSolver();
  PlateSolver(const PlateSolver&) = delete;
  PlateSolver& operator=(const PlateSolver&) = delete;

  const PlateMesh& mesh() const { return mesh_; }
  const StructureParameters& parameters() const { return params_; }
  int node_count() const { return static_cast<int>(mesh_.nodes.size()); }
  int dof_count() const { return 2 * node_count(); }
  static int dof(int node, int component) { return 2 * node + component; }
  // Row of (node, component) in the PETSc matrix and vectors (equals dof() on one rank).
  PetscInt petsc_dof(int node, int component) const { return 2 * partition_.petsc_node[node] + component; }
  const PlatePartition& partition() const { return partition_; }
  bool is_clamped(int node) const { return clamped_[node]; }

  // ---- loads (R of eq. 21), all per unit depth ----
  void add_nodal_element(NodalElement* element);  // not owned; its force/tangent enter every Newton iteration
  void add_point_load(int node, const Eigen::Vector2d& force);  // N/m, dead load
  void add_edge_load(const std::string& edge_set,
                     const Eigen::Vector2d& traction);            // Pa, dead load on "top"...
  void clear_loads();                                             // point and edge loads
  void set_load_factor(double factor) { load_factor_ = factor; }  // scales point and edge loads
  // Nodal forces [N/m], 2 per node, set by the caller before each step (contact / fluid forces). On several
  // ranks rank 0's copy is the one used.
  Eigen::VectorXd& external_forces() { return external_forces_; }

  // ---- state ----
  void set_state(const Eigen::VectorXd& displacement, const Eigen::VectorXd& velocity);
  // With the acceleration too (restart from a checkpoint without recomputing a0).
  void set_state(const Eigen::VectorXd& displacement, const Eigen::VectorXd& velocity,
                 const Eigen::VectorXd& acceleration);
  void initialise_acceleration(double t);  // solves M a0 = R(t) - F(u0)
  // A restart's whole state, flattened: u, v, a and the Q4-EAS elements' enhanced parameters (the start values of
  // the next step's local solves). Collective over the structure's ranks (each holds its own elements'
  // parameters); every rank returns the same vector. restore_state() takes it back on any structure rank count.
  std::vector<double> save_state() const;
  // Restore the nodal elements' own state (cables) after this: it builds the matrix pattern, whose pass evaluates
  // them.
  void restore_state(const std::vector<double>& state);
  const Eigen::VectorXd& displacement() const { return u_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  const Eigen::VectorXd& acceleration() const { return a_; }

  // ---- whole steps ----
  StepReport step(double t, double dt);                    // Newmark from t to t + dt
  StepReport solve_static(double t, int load_increments);  // equilibrium, loads ramped 1/n ... n/n

  // ---- one Newton iteration in public pieces (for the contact coupling, eq. 21) ----
  void begin_step(double t, double dt);  // dynamic: predictor, loads at t + dt
  // The next begin_step()'s first Newton iterate instead of u_n (once): a repeat of a step from its saved start (the
  // converged plate-water exchange) starts from the last attempt's displacement. dof_count() entries.
  void set_next_predictor(const Eigen::VectorXd& u);
  void begin_static(double t);    // no inertia
  void assemble_newton_system();  // into newton_matrix() / newton_residual()
  // Adds K_eff and r at rows/columns offset + petsc_dof() of a caller's matrix and vector (ADD_VALUES, no
  // MatAssembly). Clamped rows get 1 on the diagonal. Preallocate with node_adjacency(). Collective: each
  // rank adds its own elements and the residual of the rows it owns.
  void add_newton_system(Mat matrix, Vec rhs, PetscInt offset);
  Mat newton_matrix() const { return matrix_.get(); }
  Vec newton_residual() const { return rhs_.get(); }
  double residual_norm() const { return residual_norm_; }
  Vec solve_newton_increment();                  // KSP on the owned system; throws NumericalError on failure
  KSP newton_ksp() const { return ksp_.get(); }  // the plate's KSP (options prefix -structure_), for timing
  void apply_increment(const double* du);        // dof_count() entries; clamped entries ignored
  // On one rank any Vec (entries offset + petsc_dof()); on several, the Vec of solve_newton_increment() or
  // one with the same layout (offset 0): it is gathered to every rank.
  void apply_increment(Vec du, PetscInt offset = 0);
  bool converged() const;
  void end_step();  // commits u, v, a of t + dt
  // Nodes coupled to each node (itself included) by solid and nodal elements.
  std::vector<std::vector<int>> node_adjacency() const;

  // ---- probes ----
  Eigen::Vector2d displacement(int node) const { return u_.segment<2>(2 * node); }
  Eigen::Vector2d position(int node) const { return mesh_.nodes[node] + displacement(node); }
  Eigen::Vector2d velocity(int node) const { return v_.segment<2>(2 * node); }
  double strain_energy() const;   // J/m, solid elements
  double kinetic_energy() const;  // J/m, 1/2 v^T M v
  double gravity_potential_energy()
      const;  // J/m, -sum_n m_n g . u_n: gravity's work undone since the reference
  double element_von_mises(int element) const;  // Pa, mean over the element's 3x3 (Q4: 2x2) points (Cauchy)
  double max_von_mises() const;                 // Pa, max over all points
  // Collective over the plate's ranks: for every element (on every rank), the mean von Mises stress over its points
  // [Pa] and its strain energy per reference area, the strain energy density [J/m^3].
  void element_fields(std::vector<double>& von_mises, std::vector<double>& energy_density) const;
  PhaseTimers& timers() { return timers_; }
  // One line for the run log: mesh, dofs, material, hypothesis, integration, Newmark, ranks, per unit depth.
  std::string summary() const;
  const StepReport& last_step() const { return last_; }

 private:
  enum class Mode { kDynamic, kStatic, kInitialAcceleration };
  Eigen::VectorXd next_predictor_;  // empty: u_n
  void build_matrix();
  void prepare_matrix();  // builds the pattern and the scatter map when nodal elements changed it
  void build_scatter_map();
  // Computes residual_ and hands each element's effective matrix (component-major, column-major, 2 n x 2 n for
  // n nodes per element) to element_sink(e, values) and each nodal element's (dofs, row-major values) to nodal_sink; shared by both assembly paths.
  // with_matrix false: the residual and its norms only (element forces without tangents, no sinks called).
  template <typename ElementSink, typename NodalSink>
  void compute_newton_terms(ElementSink&& element_sink, NodalSink&& nodal_sink, bool with_matrix = true);
  // The residual of the current iterate and its norms, without the matrix (newton_residual() is not updated):
  // the convergence check after an increment in step() and solve_static().
  void assemble_residual();
  // The plate-alone Newton loop of step() and solve_static().
  void newton_loop(const char* what);
  void compute_external(double t);
  double element_energy(int e) const;  // J/m, the element's strain energy
  // The solid elements' terms of one assembly (compute_newton_terms), written once over the element families.
  template <typename Family, typename ElementSink>
  void element_terms(Family& family, ElementSink& element_sink, bool with_matrix, bool with_tangent,
                     double mass_coefficient, bool inertia_in_residual, std::string& failure);
  // Calls f(family) with the plate's element family (Q9Family or Q4EasFamily).
  template <typename F>
  decltype(auto) with_family(F&& f) {
    return std::visit(std::forward<F>(f), family_);
  }
  template <typename F>
  decltype(auto) with_family(F&& f) const {
    return std::visit(std::forward<F>(f), family_);
  }
  void update_acceleration();
  Eigen::VectorXd gather_in_node_order(Vec v);  // a distributed Vec of the owned layout, on every rank
  double sum_over_ranks(double local) const;

  Communicator comm_;
  StructureParameters params_;
  const excitation::GroundMotion* ground_;
  PlateMesh mesh_;
  std::unique_ptr<Material> material_;
  // The solid elements (element_family.hpp): geometry, mass and element state of the mesh's element type.
  PlateElements family_;
  Newmark newmark_;
  Eigen::VectorXd mass_row_sum_;  // per node, for body forces
  std::vector<bool> clamped_;
  std::vector<NodalElement*> nodal_elements_;
  PlatePartition partition_;
  int rank_ = 0, size_ = 1;

  Eigen::VectorXd prescribed_loads_, external_forces_, body_forces_, residual_;
  Eigen::VectorXd u_, v_, a_, u_n_, v_n_, a_n_;
  Mode mode_ = Mode::kStatic;
  double time_ = 0.0;        // of the state being solved for (t + dt in a step), for error messages
  std::string when() const;  // "t = ... s", or the static start's words, for error messages
  double dt_ = 0.0, load_factor_ = 1.0, ramp_ = 1.0;
  double residual_norm_ = 0.0, first_residual_norm_ = -1.0, increment_norm_ = -1.0, force_scale_ = 0.0;
  StepReport last_;

  OwnedMat matrix_;
  OwnedVec rhs_, solution_;
  OwnedKsp ksp_;
  OwnedVec gathered_;
  PetscOwner<VecScatter, VecScatterDestroy> to_all_;
  bool matrix_dirty_ = true;
  // (entry of the element's component-major matrix, position in the value array) for every stored entry of
  // every element, SeqAIJ or SeqSBAIJ (upper triangle), so the owned matrix is filled without PETSc's per-entry
  // search (which cost ~40% of an iteration); empty for other matrix types. Element e's entries start at
  // element_scatter_start_[e].
  std::vector<std::pair<int, PetscInt>> element_scatter_;
  std::vector<std::size_t> element_scatter_start_;
  std::vector<PetscInt> clamped_diagonal_;
  bool symmetric_storage_ = false;  // the owned matrix is SeqSBAIJ
  PhaseTimers timers_;
};

}  // namespace halfeti::structure
