#include "halfeti/structure/element_family.hpp"

namespace halfeti::structure {

namespace {
// An element's rows of a field with 2 values per node (reference positions, displacements), in its node
// order.
template <typename Coordinates, std::size_t N, typename Row>
Coordinates element_rows(const std::array<int, N>& nodes, Row&& row) {
  Coordinates out;
  for (std::size_t a = 0; a < N; ++a) out.row(static_cast<Eigen::Index>(a)) = row(nodes[a]).transpose();
  return out;
}
}  // namespace

Q9Family::Q9Family(const Material& material, const Q9Options& options, const PlateMesh& mesh, double density)
    : integrator_(material, options), mesh_(&mesh) {
  for (const auto& e : mesh.elements) {
    const auto x = element_rows<Q9Coordinates>(e, [&](int n) { return mesh.nodes[n]; });
    geometry_.push_back(HyperelasticQ9::reference_geometry(x));
    mass_.push_back(HyperelasticQ9::scalar_mass(geometry_.back(), density));
  }
}

Q9Family::Coordinates Q9Family::displacement(int e, const Eigen::VectorXd& u) const {
  return element_rows<Coordinates>(nodes(e), [&](int n) { return u.segment<2>(2 * n); });
}

void Q9Family::evaluate(int e, const Coordinates& u, bool with_matrix, bool with_tangent, Vector& force,
                        Matrix& matrix) {
  if (with_matrix && with_tangent) {
    integrator_.internal_force_and_tangent_component_major(geometry_[e], u, force, matrix);
  } else {
    integrator_.internal_force(geometry_[e], u, force);
    matrix.setZero();
  }
}

Q4EasFamily::Q4EasFamily(const Material& material, const Q4EasOptions& options, const PlateMesh& mesh,
                         double density)
    : integrator_(material, options), mesh_(&mesh) {
  for (const auto& e : mesh.quads) {
    const auto x = element_rows<Q4Coordinates>(e, [&](int n) { return mesh.nodes[n]; });
    geometry_.push_back(HyperelasticQ4Eas::reference_geometry(x));
    mass_.push_back(HyperelasticQ4Eas::scalar_mass(geometry_.back(), density));
  }
  alpha_.assign(mesh.quads.size(), EasParameters::Zero());
  alpha_update_.assign(mesh.quads.size(), EasUpdate::Zero());
  alpha_solved_ = alpha_;
}

Q4EasFamily::Coordinates Q4EasFamily::displacement(int e, const Eigen::VectorXd& u) const {
  return element_rows<Coordinates>(nodes(e), [&](int n) { return u.segment<2>(2 * n); });
}

void Q4EasFamily::evaluate(int e, const Coordinates& u, bool with_matrix, bool with_tangent, Vector& force,
                           Matrix& matrix) {
  // alpha is solved from the element's start value alpha_[e], which only apply_increment() changes, so a
  // residual-only check before an assembly (step()) or none (the coupling's loop) gives the same bits.
  EasParameters alpha = alpha_[e];
  if (with_matrix && with_tangent) {
    integrator_.internal_force_and_tangent_component_major(geometry_[e], u, alpha, force, matrix,
                                                           &alpha_update_[e]);
    alpha_solved_[e] = alpha;
  } else {
    integrator_.internal_force(geometry_[e], u, alpha, force);
    if (with_matrix) {
      matrix.setZero();
      alpha_solved_[e] = alpha;
      alpha_update_[e].setZero();
    }
  }
}

void Q4EasFamily::apply_increment(int e, const Eigen::Matrix<double, 2 * kNodes, 1>& du) {
  // The linearisation of the condensed enhanced equilibrium at the last evaluation with the matrix (Simo &
  // Armero 1992): alpha = alpha_solved + (d alpha / du) du_e.
  alpha_[e] = alpha_solved_[e];
  alpha_[e].noalias() += alpha_update_[e] * du;
}

void Q4EasFamily::reset_state() {  // the enhanced parameters are re-solved from zero at the next evaluation
  for (auto& alpha : alpha_) alpha.setZero();
  for (auto& alpha : alpha_solved_) alpha.setZero();
  for (auto& update : alpha_update_) update.setZero();
}

void Q4EasFamily::save_state(int e, double* out) const {
  for (int m = 0; m < kEasModes; ++m) out[m] = alpha_[e](m);
}

void Q4EasFamily::restore_state(int e, const double* in) {
  for (int m = 0; m < kEasModes; ++m) alpha_[e](m) = in[m];
  alpha_solved_[e] = alpha_[e];
}

}  // namespace halfeti::structure
