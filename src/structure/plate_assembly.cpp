// Global assembly of the Newton system of the plate: solid elements, inertia, nodal elements (cables), loads.
#include <algorithm>
#include <set>
#include <sstream>

#include "halfeti/core/collective.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/structure/plate_solver.hpp"

namespace halfeti::structure {

std::vector<std::vector<int>> PlateSolver::node_adjacency() const {
  std::vector<std::set<int>> adj(node_count());
  auto couple = [&adj](const auto& nodes) {
    for (int a : nodes)
      for (int b : nodes) adj[a].insert(b);
  };
  for (const auto& e : mesh_.elements) couple(e);
  for (const auto& e : mesh_.quads) couple(e);
  for (const NodalElement* ne : nodal_elements_) couple(ne->nodes());
  std::vector<std::vector<int>> out(node_count());
  for (int n = 0; n < node_count(); ++n) out[n].assign(adj[n].begin(), adj[n].end());
  return out;
}

void PlateSolver::build_matrix() {
  // Preallocated from the mesh graph (plus nodal elements), block size 2 = dofs per node.
  // Block rows are this rank's nodes in PETSc order; a coupling is "diagonal" when both nodes are owned here.
  const auto adjacency = node_adjacency();
  const int owned = partition_.owned_blocks;
  // Counts of blocks per block row: in the owned columns, elsewhere, and on or right of the diagonal (for the
  // symmetric SBAIJ formats, which store the upper triangle only).
  std::vector<PetscInt> blocks_per_row(owned, 0), off_diagonal(owned, 0), upper(owned, 0),
      upper_off(owned, 0);
  for (int n = 0; n < node_count(); ++n) {
    if (partition_.node_rank[n] != rank_) continue;
    const int row = partition_.petsc_node[n] - partition_.first_block;
    for (int m : adjacency[n]) {
      const bool here = partition_.node_rank[m] == rank_;
      ++(here ? blocks_per_row[row] : off_diagonal[row]);
      if (partition_.petsc_node[m] >= partition_.petsc_node[n]) ++(here ? upper[row] : upper_off[row]);
    }
  }
  const PetscInt n = dof_count(), n_local = 2 * owned;
  HALFETI_PETSC_CALL(MatCreate(comm_.get(), matrix_.out()));
  HALFETI_PETSC_CALL(MatSetSizes(matrix_.get(), n_local, n_local, n, n));
  HALFETI_PETSC_CALL(MatSetBlockSize(matrix_.get(), 2));
  // Symmetric storage (upper triangle) when the factorisation is a Cholesky one, AIJ otherwise;
  // -structure_mat_type overrides.
  PC pc = nullptr;
  HALFETI_PETSC_CALL(KSPGetPC(ksp_.get(), &pc));
  PetscBool cholesky = PETSC_FALSE;
  HALFETI_PETSC_CALL(
      PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(pc), &cholesky, PCCHOLESKY, PCICC, ""));
  HALFETI_PETSC_CALL(MatSetType(matrix_.get(), cholesky ? MATSBAIJ : MATAIJ));
  HALFETI_PETSC_CALL(MatSetOptionsPrefix(matrix_.get(), "structure_"));
  HALFETI_PETSC_CALL(MatSetFromOptions(matrix_.get()));
  HALFETI_PETSC_CALL(MatXAIJSetPreallocation(matrix_.get(), 2, blocks_per_row.data(), off_diagonal.data(),
                                             upper.data(), upper_off.data()));
  HALFETI_PETSC_CALL(MatSetOption(matrix_.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscBool symmetric_storage = PETSC_FALSE;
  HALFETI_PETSC_CALL(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(matrix_.get()),
                                               &symmetric_storage, MATSEQSBAIJ, MATMPISBAIJ, ""));
  // K_eff is symmetric: the SBAIJ formats keep the upper triangle, the lower one is dropped on insertion.
  if (symmetric_storage)
    HALFETI_PETSC_CALL(MatSetOption(matrix_.get(), MAT_IGNORE_LOWER_TRIANGULAR, PETSC_TRUE));
  HALFETI_PETSC_CALL(MatCreateVecs(matrix_.get(), solution_.out(), rhs_.out()));
  matrix_dirty_ = false;
}

void PlateSolver::compute_external(double t) {
  time_ = t;
  // Gravity and the tank frame's inertial force -a_g(t) (DESIGN, "The tank frame"), lumped through M's row
  // sums: for a uniform acceleration field b, the consistent nodal force M b equals (row sum of M) b exactly.
  Eigen::Vector2d body = params_.gravity;
  if (ground_ != nullptr) body.x() -= ground_->acceleration(t);
  for (int n = 0; n < node_count(); ++n) body_forces_.segment<2>(2 * n) = mass_row_sum_(n) * body;
}

void PlateSolver::update_acceleration() {
  newmark_.acceleration(u_, u_n_, v_n_, a_n_, dt_, a_);
}

template <typename Family, typename ElementSink>
void PlateSolver::element_terms(Family& family, ElementSink& element_sink, bool with_matrix,
                                bool with_tangent, double mass_coefficient, bool inertia_in_residual,
                                std::string& failure) {
  constexpr int nn = Family::kNodes;
  typename Family::Vector force;
  typename Family::Matrix
      element_matrix;  // component-major: row/column nn i + a = component i of local node a
  Eigen::Matrix<double, nn, 2> element_acceleration;
  for (int e : partition_.owned_elements) {
    const auto& nodes = family.nodes(e);
    const typename Family::Coordinates displacement = family.displacement(e, u_);
    try {
      family.evaluate(e, displacement, with_matrix, with_tangent, force, element_matrix);
    } catch (const NumericalError& error) {
      const Eigen::Vector2d centre = family.centre(e, [&](int n) { return position(n); });
      std::ostringstream what;
      what << error.what() << " in element " << e << " at (" << centre.x() << ", " << centre.y() << ") m, "
           << when() << "; hint: smaller dt, or check the loads";
      failure = what.str();
      break;
    }
    const auto& m = family.mass(e);
    if (with_matrix && mass_coefficient != 0.0) {
      element_matrix.template block<nn, nn>(0, 0) += mass_coefficient * m;
      element_matrix.template block<nn, nn>(nn, nn) += mass_coefficient * m;
    }
    if (inertia_in_residual) {
      for (int b = 0; b < nn; ++b) element_acceleration.row(b) = a_.segment<2>(2 * nodes[b]).transpose();
      const Eigen::Matrix<double, nn, 2> inertia = m.lazyProduct(element_acceleration);
      for (int a = 0; a < nn; ++a)
        residual_.segment<2>(2 * nodes[a]) -= force.template segment<2>(2 * a) + inertia.row(a).transpose();
    } else {
      for (int a = 0; a < nn; ++a) residual_.segment<2>(2 * nodes[a]) -= force.template segment<2>(2 * a);
    }
    if (with_matrix) element_sink(e, element_matrix.data());
  }
}

template <typename ElementSink, typename NodalSink>
void PlateSolver::compute_newton_terms(ElementSink&& element_sink, NodalSink&& nodal_sink, bool with_matrix) {
  const bool inertia_in_residual = mode_ == Mode::kDynamic;
  const double stiffness_coefficient = mode_ == Mode::kInitialAcceleration ? 0.0 : 1.0;
  const double mass_coefficient = mode_ == Mode::kDynamic               ? newmark_.mass_coefficient(dt_)
                                  : mode_ == Mode::kInitialAcceleration ? 1.0
                                                                        : 0.0;
  if (inertia_in_residual) update_acceleration();
  // External loads enter once (rank 0); each rank subtracts its own elements; the sum is formed below.
  if (rank_ == 0)
    residual_ = ramp_ * (load_factor_ * prescribed_loads_ + external_forces_ + body_forces_);
  else
    residual_.setZero();

  // A numerical failure (an inverted point, a cable that cannot be solved) is raised on every rank together
  // (below), so that no rank is left waiting in the residual's reduction.
  std::string failure;
  with_family([&](auto& family) {
    element_terms(family, element_sink, with_matrix, stiffness_coefficient != 0.0, mass_coefficient,
                  inertia_in_residual, failure);
  });

  // Nodal elements (cables): their force is internal (enters as F), their tangent adds to K. Rank 0 evaluates
  // them all (a cable is a handful of operations).
  for (NodalElement* ne : nodal_elements_) {
    if (rank_ != 0 || !failure.empty()) break;
    const std::vector<int> nodes = ne->nodes();
    std::vector<Eigen::Vector2d> positions;
    for (int n : nodes) positions.push_back(mesh_.nodes[n] + u_.segment<2>(2 * n));
    Eigen::VectorXd ne_force;
    Eigen::MatrixXd ne_tangent;
    try {
      ne->evaluate(positions, ne_force, ne_tangent);
    } catch (const NumericalError& error) {
      failure = error.what();
      break;
    }
    const int k = 2 * static_cast<int>(nodes.size());
    HALFETI_CHECK(ne_force.size() == k && ne_tangent.rows() == k && ne_tangent.cols() == k,
                  "nodal element returned force/tangent of the wrong size");
    std::vector<int> dofs(k);
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      residual_.segment<2>(2 * nodes[a]) -= ne_force.segment<2>(2 * a);
      for (int c = 0; c < 2; ++c) dofs[2 * a + c] = clamped_[nodes[a]] ? -1 : 2 * nodes[a] + c;
    }
    if (!with_matrix) continue;
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> values =
        stiffness_coefficient * ne_tangent;
    nodal_sink(dofs, values.data());
  }
  // The first failing rank's message, on every rank.
  if (size_ > 1) failure = first_problem(comm_.get(), !failure.empty(), rank_, failure);
  if (!failure.empty()) throw NumericalError(failure);
  if (size_ > 1) {
    // Reduce to rank 0 and broadcast, so that every rank holds bitwise the same residual and takes the same
    // Newton decisions.
    Eigen::VectorXd total(dof_count());
    MPI_Reduce(residual_.data(), total.data(), dof_count(), MPI_DOUBLE, MPI_SUM, 0, comm_.get());
    if (rank_ == 0) residual_ = total;
    MPI_Bcast(residual_.data(), dof_count(), MPI_DOUBLE, 0, comm_.get());
  }
  for (int n : mesh_.clamped_nodes) residual_.segment<2>(2 * n).setZero();
  residual_norm_ = residual_.norm();
  if (first_residual_norm_ < 0.0) first_residual_norm_ = residual_norm_;
  // Force scale of the residual test: the larger of the applied loads R and the forces that balance them,
  // F + M a = R - r (free rows). A tiny first residual (a good predictor) then does not demand a residual far
  // below round-off of the forces themselves.
  Eigen::VectorXd applied = ramp_ * (load_factor_ * prescribed_loads_ + external_forces_ + body_forces_);
  for (int n : mesh_.clamped_nodes) applied.segment<2>(2 * n).setZero();
  force_scale_ = std::max({first_residual_norm_, applied.norm(), (applied - residual_).norm()});
}

void PlateSolver::add_newton_system(Mat matrix, Vec rhs, PetscInt offset) {
  ScopedTimer timer(timers_, "structure_assembly");
  PetscInt block_size = 1;
  HALFETI_PETSC_CALL(MatGetBlockSize(matrix, &block_size));
  const bool blocked = block_size == 2 && offset % 2 == 0;
  const int nn = mesh_.nodes_per_element(), nd = 2 * nn;
  double interleaved[2 * kMaxElementNodes * 2 * kMaxElementNodes];  // row-major nd x nd
  auto element_sink = [&](int e, const double* component_major) {   // column-major nd x nd, row nn i + a
    const int* nodes = mesh_.element_nodes(e);
    for (int b = 0; b < nn; ++b)
      for (int a = 0; a < nn; ++a)
        for (int i = 0; i < 2; ++i)
          for (int k = 0; k < 2; ++k)
            interleaved[(2 * a + i) * nd + 2 * b + k] = component_major[(nn * k + b) * nd + nn * i + a];
    const double* values = interleaved;
    PetscInt rows[2 * kMaxElementNodes];
    // Negative indices make PETSc skip the clamped rows and columns.
    const auto& to_petsc = partition_.petsc_node;
    if (blocked) {
      for (int a = 0; a < nn; ++a) rows[a] = clamped_[nodes[a]] ? -1 : to_petsc[nodes[a]] + offset / 2;
      HALFETI_PETSC_CALL(MatSetValuesBlocked(matrix, nn, rows, nn, rows, values, ADD_VALUES));
    } else {
      for (int a = 0; a < nn; ++a)
        for (int c = 0; c < 2; ++c)
          rows[2 * a + c] = clamped_[nodes[a]] ? -1 : 2 * to_petsc[nodes[a]] + c + offset;
      HALFETI_PETSC_CALL(MatSetValues(matrix, nd, rows, nd, rows, values, ADD_VALUES));
    }
  };
  auto nodal_sink = [&](const std::vector<int>& dofs, const double* values) {
    std::vector<PetscInt> idx(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i)
      idx[i] = dofs[i] < 0 ? -1 : petsc_dof(dofs[i] / 2, dofs[i] % 2) + offset;
    const PetscInt k = static_cast<PetscInt>(idx.size());
    HALFETI_PETSC_CALL(MatSetValues(matrix, k, idx.data(), k, idx.data(), values, ADD_VALUES));
  };
  compute_newton_terms(element_sink, nodal_sink);
  for (int n : mesh_.clamped_nodes)
    for (int c = 0; c < 2; ++c) {
      if (partition_.node_rank[n] != rank_) continue;
      const PetscInt row = petsc_dof(n, c) + offset;
      HALFETI_PETSC_CALL(MatSetValue(matrix, row, row, 1.0, ADD_VALUES));
    }
  if (rhs != nullptr) {
    std::vector<PetscInt> idx;
    std::vector<double> values;
    for (int n = 0; n < node_count(); ++n)
      if (partition_.node_rank[n] == rank_)
        for (int c = 0; c < 2; ++c)
          idx.push_back(petsc_dof(n, c) + offset), values.push_back(residual_(2 * n + c));
    HALFETI_PETSC_CALL(
        VecSetValues(rhs, static_cast<PetscInt>(idx.size()), idx.data(), values.data(), ADD_VALUES));
  }
}

void PlateSolver::build_scatter_map() {
  element_scatter_.clear();
  element_scatter_start_.clear();
  clamped_diagonal_.clear();
  symmetric_storage_ = false;
  PetscBool is_seqaij = PETSC_FALSE, is_seqsbaij = PETSC_FALSE;
  HALFETI_PETSC_CALL(
      PetscObjectTypeCompare(reinterpret_cast<PetscObject>(matrix_.get()), MATSEQAIJ, &is_seqaij));
  HALFETI_PETSC_CALL(
      PetscObjectTypeCompare(reinterpret_cast<PetscObject>(matrix_.get()), MATSEQSBAIJ, &is_seqsbaij));
  if (!is_seqaij && !is_seqsbaij) return;
  symmetric_storage_ = is_seqsbaij;
  // Fix the pattern with one pass of the general path, then look every entry up once.
  mode_ = Mode::kStatic;
  HALFETI_PETSC_CALL(MatZeroEntries(matrix_.get()));
  add_newton_system(matrix_.get(), nullptr, 0);
  HALFETI_PETSC_CALL(MatAssemblyBegin(matrix_.get(), MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(MatAssemblyEnd(matrix_.get(), MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(MatSetOption(matrix_.get(), MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));
  // SeqAIJ: scalar rows. SeqSBAIJ: block rows of the upper triangle, each 2x2 block stored column by column.
  PetscInt n = 0;
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscBool done = PETSC_FALSE;
  const PetscBool blocks = symmetric_storage_ ? PETSC_TRUE : PETSC_FALSE;
  HALFETI_PETSC_CALL(MatGetRowIJ(matrix_.get(), 0, PETSC_FALSE, blocks, &n, &ia, &ja, &done));
  HALFETI_CHECK(done, "MatGetRowIJ did not return the matrix structure");
  auto find = [&](PetscInt row, PetscInt col) {
    const PetscInt* hit = std::lower_bound(ja + ia[row], ja + ia[row + 1], col);
    HALFETI_CHECK(hit != ja + ia[row + 1] && *hit == col,
                  "entry (" << row << ", " << col << ") not in pattern");
    return static_cast<PetscInt>(hit - ja);
  };
  // Position of (row, col) in the value array; -1 for the lower triangle of symmetric storage.
  auto position = [&](PetscInt row, PetscInt col) -> PetscInt {
    if (!symmetric_storage_) return find(row, col);
    const PetscInt block_row = row / 2, block_col = col / 2;
    if (block_col < block_row) return -1;
    return 4 * find(block_row, block_col) + 2 * (col % 2) + row % 2;
  };
  // In the storage order of the element's component-major, column-major matrix (entry c * 18 + r, with
  // r = 9 i + a the row of component i of local node a); clamped rows and columns and the lower triangle of
  // symmetric storage are left out.
  const int nn = mesh_.nodes_per_element(), nd = 2 * nn;
  element_scatter_.reserve(static_cast<std::size_t>(mesh_.element_count()) * nd * nd);
  element_scatter_start_.push_back(0);
  for (int e = 0; e < mesh_.element_count(); ++e) {
    const int* nodes = mesh_.element_nodes(e);
    for (int c = 0; c < nd; ++c)
      for (int r = 0; r < nd; ++r) {
        const int rn = nodes[r % nn], cn = nodes[c % nn];
        if (clamped_[rn] || clamped_[cn]) continue;
        const PetscInt where = position(2 * rn + r / nn, 2 * cn + c / nn);
        if (where >= 0) element_scatter_.push_back({c * nd + r, where});
      }
    element_scatter_start_.push_back(element_scatter_.size());
  }
  for (int node : mesh_.clamped_nodes)
    for (int c = 0; c < 2; ++c) clamped_diagonal_.push_back(position(2 * node + c, 2 * node + c));
  HALFETI_PETSC_CALL(MatRestoreRowIJ(matrix_.get(), 0, PETSC_FALSE, blocks, &n, &ia, &ja, &done));
}

void PlateSolver::prepare_matrix() {
  if (!matrix_dirty_) return;
  // The pattern pass assembles once in static mode: keep the step's mode and Newton bookkeeping intact.
  const Mode mode = mode_;
  const double first = first_residual_norm_;
  build_matrix();
  build_scatter_map();
  mode_ = mode;
  first_residual_norm_ = first;
}

void PlateSolver::assemble_newton_system() {
  prepare_matrix();
  Mat a = matrix_.get();
  if (element_scatter_.empty()) {
    HALFETI_PETSC_CALL(MatZeroEntries(a));
    HALFETI_PETSC_CALL(VecSet(rhs_.get(), 0.0));
    add_newton_system(a, rhs_.get(), 0);
  } else {
    ScopedTimer timer(timers_, "structure_assembly");
    PetscScalar* values = nullptr;
    HALFETI_PETSC_CALL(MatZeroEntries(a));
    if (symmetric_storage_)
      HALFETI_PETSC_CALL(MatSeqSBAIJGetArray(a, &values));
    else
      HALFETI_PETSC_CALL(MatSeqAIJGetArray(a, &values));
    auto element_sink = [&](int e, const double* m) {
      const auto* end = element_scatter_.data() + element_scatter_start_[e + 1];
      for (const auto* entry = element_scatter_.data() + element_scatter_start_[e]; entry != end; ++entry)
        values[entry->second] += m[entry->first];
    };
    std::vector<std::pair<std::vector<PetscInt>, std::vector<double>>> nodal;
    auto nodal_sink = [&](const std::vector<int>& dofs, const double* m) {
      nodal.emplace_back(std::vector<PetscInt>(dofs.begin(), dofs.end()),
                         std::vector<double>(m, m + dofs.size() * dofs.size()));
    };
    compute_newton_terms(element_sink, nodal_sink);
    for (PetscInt d : clamped_diagonal_) values[d] = 1.0;
    if (symmetric_storage_)
      HALFETI_PETSC_CALL(MatSeqSBAIJRestoreArray(a, &values));
    else
      HALFETI_PETSC_CALL(MatSeqAIJRestoreArray(a, &values));
    for (const auto& [idx, m] : nodal) {
      const PetscInt k = static_cast<PetscInt>(idx.size());
      HALFETI_PETSC_CALL(MatSetValues(a, k, idx.data(), k, idx.data(), m.data(), ADD_VALUES));
    }
    PetscScalar* rhs = nullptr;
    HALFETI_PETSC_CALL(VecGetArray(rhs_.get(), &rhs));
    std::copy(residual_.data(), residual_.data() + dof_count(), rhs);
    HALFETI_PETSC_CALL(VecRestoreArray(rhs_.get(), &rhs));
  }
  ScopedTimer timer(timers_, "structure_assembly");
  HALFETI_PETSC_CALL(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY));
  HALFETI_PETSC_CALL(VecAssemblyBegin(rhs_.get()));
  HALFETI_PETSC_CALL(VecAssemblyEnd(rhs_.get()));
}

void PlateSolver::assemble_residual() {
  ScopedTimer timer(timers_, "structure_assembly");
  compute_newton_terms([](int, const double*) {}, [](const std::vector<int>&, const double*) {}, false);
}

}  // namespace halfeti::structure
