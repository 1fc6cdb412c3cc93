// The biquadratic nine-node quadrilateral (Q9), total Lagrangian, per unit depth: the element integrator
// layer.
//
// Why Q9: its displacement field holds x^2, y^2 and x y terms in every element, so the exact pure-bending
// field (u_x ~ x y, u_y ~ x^2 + nu' y^2) is in the space and a plate bent with one or two elements through
// its thickness does not shear-lock. Near incompressibility (rubber, nu -> 0.49) the bulk (lambda) part of
// the energy is integrated with 2x2 Gauss points and the shear (mu) part with 3x3 (selective reduced
// integration, Hughes 1987, sec. 4.5): 4 volumetric constraints per element instead of 9, which lifts
// volumetric locking while the fully integrated shear part keeps the element free of spurious zero-energy
// modes. Both parts come from one energy, so the tangent stays the exact derivative of the residual (Newton
// converges quadratically).
//
// Local node numbering is tensor order: node a = i + 3 j at (xi_i, eta_j), xi_i in {-1, 0, 1}.
//
// The integrator takes nodal *displacements* u, not positions: F = I + sum_a u_a (x) dN_a/dX. Built from
// positions (x ~ 0.1 m against strains of 1e-6), F would carry round-off of ~1e-14 that puts a floor of ~1e-8
// N/m under the residual and costs a Newton iteration per step.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "halfeti/structure/material.hpp"

namespace halfeti::structure {

constexpr int kQ9Nodes = 9;
constexpr int kQ9Dofs = 18;
using Q9Coordinates = Eigen::Matrix<double, kQ9Nodes, 2>;  // row a = (x, y) (or displacement) of node a
using Q9Vector = Eigen::Matrix<double, kQ9Dofs, 1>;        // x0 y0 x1 y1 ...
using Q9Matrix = Eigen::Matrix<double, kQ9Dofs, kQ9Dofs>;

// Reference-configuration data at one quadrature point: shape values, gradients dN/dX and weight * det J.
struct Q9Point {
  Eigen::Matrix<double, kQ9Nodes, 1> shape;
  Eigen::Matrix<double, kQ9Nodes, 2> gradient;
  double weight = 0.0;
};

// Everything an element needs from its reference geometry, computed once (total Lagrangian).
struct Q9Geometry {
  std::array<Q9Point, 9> full;     // 3x3 Gauss
  std::array<Q9Point, 4> reduced;  // 2x2 Gauss (bulk part under selective reduced integration)
  double area = 0.0;
  // L_ab = sum over the 3x3 points of w dN_a/dX . dN_b/dX: the part of the Neo-Hookean tangent that does not
  // depend on the deformation (mu L in each displacement component), summed once.
  Eigen::Matrix<double, kQ9Nodes, kQ9Nodes> laplacian = Eigen::Matrix<double, kQ9Nodes, kQ9Nodes>::Zero();
};

struct Q9Options {
  PlaneHypothesis hypothesis = PlaneHypothesis::kPlaneStrain;
  bool selective_reduced_integration = true;  // applies in plane strain only
  // Neo-Hookean in plane strain (the default) uses a closed-form kernel (see q9_element.cpp); false forces the
  // general material path everywhere (tests compare the two).
  bool specialised_kernel = true;
};

class HyperelasticQ9 {
 public:
  HyperelasticQ9(const Material& material, Q9Options options);

  // Throws UserError if the reference element is inverted or degenerate.
  static Q9Geometry reference_geometry(const Q9Coordinates& reference);

  // Strain energy of the element at nodal displacements u [J per m depth].
  double energy(const Q9Geometry& g, const Q9Coordinates& u) const;
  // Internal force f_int = dEnergy/du.
  void internal_force(const Q9Geometry& g, const Q9Coordinates& u, Q9Vector& force) const;
  // f_int and its tangent K = df_int/du (material + geometric stiffness).
  void internal_force_and_tangent(const Q9Geometry& g, const Q9Coordinates& u, Q9Vector& force,
                                  Q9Matrix& tangent) const;
  // The same tangent in component-major order: row/column 9 i + a is component i of node a (all four 9x9
  // blocks filled). The assembly reads this form directly.
  void internal_force_and_tangent_component_major(const Q9Geometry& g, const Q9Coordinates& u,
                                                  Q9Vector& force, Q9Matrix& component_major) const;
  // Consistent mass as a 9x9 scalar matrix (the same for x and y): M_ab = rho int N_a N_b dA.
  static Eigen::Matrix<double, kQ9Nodes, kQ9Nodes> scalar_mass(const Q9Geometry& g, double density);
  // Cauchy stress (Voigt [11, 22, 12, 33]) at each 3x3 point, for probes.
  std::array<Eigen::Vector4d, 9> cauchy_at_points(const Q9Geometry& g, const Q9Coordinates& u) const;

  const Q9Options& options() const { return options_; }

 private:
  bool split() const;
  // Closed-form Neo-Hookean plane-strain point loop (fills force and the component-major tangent).
  template <bool kTangent>
  void neo_hookean_plane_strain(const Q9Geometry& g, const Q9Coordinates& u, Q9Vector& force,
                                Q9Matrix* component_major) const;
  template <bool kTangent>
  void accumulate(const Q9Point& p, const Q9Coordinates& u, EnergyPart part, Q9Vector& force,
                  Q9Matrix* tangent) const;

  const Material& material_;
  Q9Options options_;
  bool closed_form_ = false;  // neo_hookean_plane_strain() applies
};

// Q9 shape functions and their derivatives on the reference square.
void q9_shape(double xi, double eta, Eigen::Matrix<double, kQ9Nodes, 1>& n,
              Eigen::Matrix<double, kQ9Nodes, 2>& dn_dxi);

}  // namespace halfeti::structure
