// Shared set-ups of the structure tests: the paper's plate as a cantilever, its beam-theory references, and a
// ground motion of our own (the excitation module's are tested there).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "halfeti/excitation/ground_motion.hpp"
#include "halfeti/structure/plate_solver.hpp"

namespace halfeti::structure::testing {

inline StructureParameters paper_plate(int across, int along, double nu = 0.45,
                                       ElementType element = ElementType::kQ9) {
  StructureParameters p;
  p.geometry.cells_across = across;
  p.geometry.cells_along = along;
  p.geometry.element = element;
  p.material.poisson_ratio = nu;
  p.gravity = Eigen::Vector2d::Zero();
  return p;
}

// Bending stiffness per unit depth in plane strain, E' I with E' = E / (1 - nu^2), I = t^3 / 12.
inline double bending_stiffness(const StructureParameters& p) {
  const double e = p.material.youngs_modulus, nu = p.material.poisson_ratio, t = p.geometry.thickness;
  const double modulus = p.material.hypothesis == PlaneHypothesis::kPlaneStrain ? e / (1 - nu * nu) : e;
  return modulus * t * t * t / 12.0;
}

// Euler-Bernoulli tip deflection under a tip load P: P L^3 / (3 E'I).
inline double euler_bernoulli_tip(const StructureParameters& p, double load) {
  const double l = p.geometry.height;
  return load * l * l * l / (3.0 * bending_stiffness(p));
}

// First cantilever frequency [Hz]: 1.875^2 sqrt(E'I / (rho A L^4)) / (2 pi), with 1.8751 the root of
// 1 + cos(b) cosh(b) = 0.
inline double first_frequency(const StructureParameters& p) {
  const double b = 1.87510407, l = p.geometry.height;
  const double rho_a = p.material.density * p.geometry.thickness;
  return b * b * std::sqrt(bending_stiffness(p) / (rho_a * l * l * l * l)) / (2.0 * M_PI);
}

// A linear spring from one plate node to a fixed anchor: the simplest NodalElement.
class AnchorSpring final : public NodalElement {
 public:
  AnchorSpring(int node, Eigen::Vector2d anchor, double stiffness)
      : node_(node), anchor_(anchor), k_(stiffness) {}
  std::vector<int> nodes() const override { return {node_}; }
  void evaluate(const std::vector<Eigen::Vector2d>& x, Eigen::VectorXd& f, Eigen::MatrixXd& k) override {
    f = k_ * (x[0] - anchor_);
    k = k_ * Eigen::Matrix2d::Identity();
  }

 private:
  int node_;
  Eigen::Vector2d anchor_;
  double k_;
};

class ConstantGroundMotion final : public excitation::GroundMotion {
 public:
  explicit ConstantGroundMotion(double a) : a_(a) {}
  double acceleration(double) const override { return a_; }
  std::string describe() const override { return "constant (test)"; }

 private:
  double a_;
};

}  // namespace halfeti::structure::testing
