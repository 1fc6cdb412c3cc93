// The four-node quadrilateral with enhanced assumed strain for finite deformations (Q1/E4), total Lagrangian,
// per unit depth: the element integrator layer of the `q4_eas` option (docs/structure.md, "Element: Q4 with
// enhanced assumed strain").
//
// Formulation (Simo & Armero 1992, "Geometrically non-linear enhanced strain mixed methods and the method of
// incompatible modes", IJNME 33, 1413-1449): the displacement gradient of the bilinear field is enriched by an
// element-internal field of four parameters alpha,
//   F = I + Grad u + H~(alpha),   H~_iJ = (j0 / j(xi)) sum_beta M_i,beta(alpha, xi) (J0^-1)_beta,J,
//   M = [alpha_x,xi xi   alpha_x,eta eta]
//       [alpha_y,xi xi   alpha_y,eta eta],
// J0 = dX/dxi and j0 = det J0 at the element centre, j = det J at the point. These are Wilson's incompatible
// modes (1 - xi^2, 1 - eta^2 per component) with their Jacobian frozen at the centre and scaled by j0 / j, which
// makes int H~ dA = 0 exactly under 2x2 Gauss (xi, eta odd): the element passes the patch test. The modes supply
// the linear-in-xi shear and the Poisson terms that the bilinear field lacks in bending (no shear locking) and
// relax the volumetric constraint to one per element in effect (no volumetric locking at nu -> 0.5).
// Because the four modes span every spatial direction (H~ -> R H~ is alpha -> R alpha), F stays objective as
// written. Pre-multiplying the modes by the centre's F0 (F = I + Grad u + F0 H~(alpha)) spans the same space for
// any invertible F0 (F0 H~(alpha) = H~(alpha') with alpha' = F0 alpha per mode vector), so after the condensation
// both give the same force and tangent; only the parametrisation of alpha differs.
//
// alpha is condensed per element: the enhanced equilibrium h(u, alpha) = dPi/dalpha = 0 is solved by a local
// Newton iteration from a start value, and the element returns the condensed force and the consistent condensed
// tangent
//   K* = K_uu - K_ua K_aa^-1 K_au   (= d f_u(u, alpha(u)) / du),
// together with d alpha / du = -K_aa^-1 K_au, which the solver uses to update alpha after each Newton increment
// (the element state; it only seeds the next local solve, so the residual is a function of u alone up to the
// local tolerance). Quadrature: 2x2 Gauss for everything.
//
// Local node numbering is tensor order: node a = i + 2 j at (xi, eta) = (2 i - 1, 2 j - 1).
// alpha order: [x-xi, x-eta, y-xi, y-eta] (component i, mode m at 2 i + m).
#pragma once

#include <Eigen/Dense>
#include <array>

#include "halfeti/structure/material.hpp"

namespace halfeti::structure {

constexpr int kQ4Nodes = 4;
constexpr int kQ4Dofs = 8;
constexpr int kEasModes = 4;
using Q4Coordinates = Eigen::Matrix<double, kQ4Nodes, 2>;  // row a = (x, y) (or displacement) of node a
using Q4Vector = Eigen::Matrix<double, kQ4Dofs, 1>;        // x0 y0 x1 y1 ...
using Q4Matrix = Eigen::Matrix<double, kQ4Dofs, kQ4Dofs>;
using EasParameters = Eigen::Matrix<double, kEasModes, 1>;
// d alpha / du with u in component-major order (column 4 i + a = component i of node a).
using EasUpdate = Eigen::Matrix<double, kEasModes, kQ4Dofs>;

// One 2x2 Gauss point: shape values, gradients of the 4 nodal shapes (rows 0-3) and of the 2 enhanced modes
// (row 4: (j0/j) xi (J0^-1) row xi; row 5: (j0/j) eta (J0^-1) row eta), weight * det J.
struct Q4EasPoint {
  Eigen::Matrix<double, kQ4Nodes, 1> shape;
  Eigen::Matrix<double, 6, 2> gradient;
  double weight = 0.0;
};

struct Q4EasGeometry {
  std::array<Q4EasPoint, 4> points;
  double area = 0.0;
  double size = 0.0;  // sqrt(area): the length scale of the local tolerance
  // L_ab = sum w g_a . g_b over the 6 gradients: the u-independent mu part of the Neo-Hookean tangent.
  Eigen::Matrix<double, 6, 6> laplacian = Eigen::Matrix<double, 6, 6>::Zero();
};

struct Q4EasOptions {
  PlaneHypothesis hypothesis = PlaneHypothesis::kPlaneStrain;
  // Neo-Hookean in plane strain uses a closed-form point kernel; false forces the general material path
  // (tests compare the two).
  bool specialised_kernel = true;
};

class HyperelasticQ4Eas {
 public:
  HyperelasticQ4Eas(const Material& material, Q4EasOptions options);

  // Throws UserError if the reference element is inverted or degenerate.
  static Q4EasGeometry reference_geometry(const Q4Coordinates& reference);

  // Strain energy at nodal displacements u with alpha solved from `alpha_start` [J per m depth].
  double energy(const Q4EasGeometry& g, const Q4Coordinates& u, EasParameters alpha_start) const;
  // Condensed internal force; alpha: start value in, solved value out.
  void internal_force(const Q4EasGeometry& g, const Q4Coordinates& u, EasParameters& alpha,
                      Q4Vector& force) const;
  // Condensed force and consistent condensed tangent in component-major order (row/column 4 i + a); `update`
  // (if not null) receives d alpha / du.
  void internal_force_and_tangent_component_major(const Q4EasGeometry& g, const Q4Coordinates& u,
                                                  EasParameters& alpha, Q4Vector& force,
                                                  Q4Matrix& component_major, EasUpdate* update) const;
  // The same tangent interleaved (x0 y0 x1 y1 ...).
  void internal_force_and_tangent(const Q4EasGeometry& g, const Q4Coordinates& u, EasParameters& alpha,
                                  Q4Vector& force, Q4Matrix& tangent) const;
  // Consistent mass as a 4x4 scalar matrix: M_ab = rho int N_a N_b dA.
  static Eigen::Matrix<double, kQ4Nodes, kQ4Nodes> scalar_mass(const Q4EasGeometry& g, double density);
  // Cauchy stress (Voigt [11, 22, 12, 33]) at the 4 points, alpha solved from `alpha_start`.
  std::array<Eigen::Vector4d, 4> cauchy_at_points(const Q4EasGeometry& g, const Q4Coordinates& u,
                                                  EasParameters alpha_start) const;

  const Q4EasOptions& options() const { return options_; }
  // Local Newton iterations of the last solve (for tests and the benchmark).
  int last_local_iterations() const { return last_local_iterations_; }

 private:
  using Extended = Eigen::Matrix<double, 6, 2>;     // 4 nodal displacements + 2 mode vectors
  using Tangent12 = Eigen::Matrix<double, 12, 12>;  // component-major over the 6 "nodes": 6 i + a
  // Force (6 x 2) and tangent of the uncondensed element at U. kFull: every row of the tangent; otherwise the
  // alpha rows (a = 4, 5) only.
  template <bool kFull>
  void evaluate(const Q4EasGeometry& g, const Extended& U, Extended& force, Tangent12& k) const;
  // Local Newton on h = 0 from alpha; returns the condensation pieces at the last evaluated alpha.
  template <bool kFull>
  void solve_local(const Q4EasGeometry& g, const Q4Coordinates& u, EasParameters& alpha, Extended& force,
                   Tangent12& k, Eigen::Matrix4d& kaa_inverse, EasParameters& correction) const;

  const Material& material_;
  Q4EasOptions options_;
  bool closed_form_ = false;
  mutable int last_local_iterations_ = 0;
};

void q4_shape(double xi, double eta, Eigen::Matrix<double, kQ4Nodes, 1>& n,
              Eigen::Matrix<double, kQ4Nodes, 2>& dn_dxi);

}  // namespace halfeti::structure
