// The plate's element families behind one interface, so that the assembly, the energies and the stresses are
// written once (plate_assembly.cpp, plate_solver.cpp) for Q9 and Q4-EAS alike.
//
// A family holds what its elements need for the whole run: the reference geometry and the scalar consistent mass of
// each element, and the elements' own state (Q4-EAS: the enhanced parameters, Simo & Armero 1992; Q9: none). Each
// family provides, with its element's fixed-size types (so the arithmetic is that of the element's own code):
//   kNodes, Coordinates, Vector, Matrix, Mass        the element's sizes
//   nodes(e)                                         its mesh nodes (tensor order)
//   displacement(e, u)                               its nodal displacements out of the plate's u (2 per node)
//   evaluate(e, u, with_matrix, with_tangent, f, K)  internal force; with the matrix, the tangent (component-major,
//                                                    row/column kNodes i + a) or, without the tangent, zero
//   mass(e)                                          scalar consistent mass (kNodes x kNodes), rho int N_a N_b dA
//   energy(e, u)                                     strain energy [J/m]
//   cauchy_at_points(e, u)                           Cauchy stress (Voigt 11, 22, 12, 33) at the integration points
//   centre(e, position)                              a point of the element, for messages
//   apply_increment(e, du_e)                         the element state after a Newton increment (component-major)
//   integration()                                    the integration's name, for the run log
//   kStatePerElement, reset_state(), save_state(e, out), restore_state(e, in)   a restart's element state
// Every method throws NumericalError where the element does (an inverted point).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <variant>
#include <vector>

#include "halfeti/structure/material.hpp"
#include "halfeti/structure/plate_mesh.hpp"
#include "halfeti/structure/q4_eas_element.hpp"
#include "halfeti/structure/q9_element.hpp"

namespace halfeti::structure {

// Nine-node quadrilateral, selective reduced integration optional (q9_element.hpp).
class Q9Family {
 public:
  static constexpr int kNodes = kQ9Nodes;
  using Coordinates = Q9Coordinates;
  using Vector = Q9Vector;
  using Matrix = Q9Matrix;
  using Mass = Eigen::Matrix<double, kNodes, kNodes>;
  static constexpr const char* kName = "Q9";

  Q9Family(const Material& material, const Q9Options& options, const PlateMesh& mesh, double density);

  int count() const { return static_cast<int>(geometry_.size()); }
  const std::array<int, kNodes>& nodes(int e) const { return mesh_->elements[e]; }
  Coordinates displacement(int e, const Eigen::VectorXd& u) const;
  void evaluate(int e, const Coordinates& u, bool with_matrix, bool with_tangent, Vector& force,
                Matrix& matrix);
  const Mass& mass(int e) const { return mass_[e]; }
  double energy(int e, const Coordinates& u) const { return integrator_.energy(geometry_[e], u); }
  std::array<Eigen::Vector4d, kNodes> cauchy_at_points(int e, const Coordinates& u) const {
    return integrator_.cauchy_at_points(geometry_[e], u);
  }
  template <typename Position>
  Eigen::Vector2d centre(int e, Position&& position) const {
    return position(nodes(e)[4]);  // the centre node
  }
  void apply_increment(int, const Eigen::Matrix<double, 2 * kNodes, 1>&) {}  // no element state
  void reset_state() {}
  const char* integration() const {
    return integrator_.options().selective_reduced_integration ? "selective reduced" : "full";
  }
  void save_state(int, double*) const {}
  void restore_state(int, const double*) {}
  static constexpr int kStatePerElement = 0;

 private:
  HyperelasticQ9 integrator_;
  const PlateMesh* mesh_;
  std::vector<Q9Geometry> geometry_;
  std::vector<Mass> mass_;
};

// Four-node quadrilateral with 4 enhanced strain modes condensed per element (q4_eas_element.hpp). Its state:
// alpha_, the start of every local solve of the enhanced parameters, changed only by apply_increment() to
// alpha_solved_ + (d alpha / du) du (both from the last evaluation with the matrix), so the iterates do not depend
// on which evaluations (residual-only or full) came in between.
class Q4EasFamily {
 public:
  static constexpr int kNodes = kQ4Nodes;
  using Coordinates = Q4Coordinates;
  using Vector = Q4Vector;
  using Matrix = Q4Matrix;
  using Mass = Eigen::Matrix<double, kNodes, kNodes>;
  static constexpr const char* kName = "Q4-EAS";
  static constexpr int kStatePerElement = kEasModes;

  Q4EasFamily(const Material& material, const Q4EasOptions& options, const PlateMesh& mesh, double density);

  int count() const { return static_cast<int>(geometry_.size()); }
  const std::array<int, kNodes>& nodes(int e) const { return mesh_->quads[e]; }
  Coordinates displacement(int e, const Eigen::VectorXd& u) const;
  void evaluate(int e, const Coordinates& u, bool with_matrix, bool with_tangent, Vector& force,
                Matrix& matrix);
  const Mass& mass(int e) const { return mass_[e]; }
  double energy(int e, const Coordinates& u) const { return integrator_.energy(geometry_[e], u, alpha_[e]); }
  std::array<Eigen::Vector4d, kNodes> cauchy_at_points(int e, const Coordinates& u) const {
    return integrator_.cauchy_at_points(geometry_[e], u, alpha_[e]);
  }
  template <typename Position>
  Eigen::Vector2d centre(int e, Position&& position) const {
    const auto& n = nodes(e);
    return 0.25 * (position(n[0]) + position(n[1]) + position(n[2]) + position(n[3]));
  }
  void apply_increment(int e, const Eigen::Matrix<double, 2 * kNodes, 1>& du);
  void reset_state();
  const char* integration() const { return "2x2 (enhanced strain)"; }
  void save_state(int e, double* out) const;
  void restore_state(int e, const double* in);

 private:
  HyperelasticQ4Eas integrator_;
  const PlateMesh* mesh_;
  std::vector<Q4EasGeometry> geometry_;
  std::vector<Mass> mass_;
  std::vector<EasParameters> alpha_, alpha_solved_;
  std::vector<EasUpdate> alpha_update_;
};

// The plate's elements: one family, chosen by the mesh's element type.
using PlateElements = std::variant<Q9Family, Q4EasFamily>;
// Nodes of the largest element (buffers sized once for any family).
constexpr int kMaxElementNodes = std::max(Q9Family::kNodes, Q4EasFamily::kNodes);

}  // namespace halfeti::structure
