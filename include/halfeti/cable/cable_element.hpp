// The catenary cable as a nodal element of the structure's Newton system
// (include/halfeti/core/nodal_element.hpp).
#pragma once

#include <vector>

#include "halfeti/cable/catenary.hpp"
#include "halfeti/core/nodal_element.hpp"

namespace halfeti::cable {

class CableElement : public halfeti::NodalElement {
 public:
  // A cable from an anchor fixed in space (end 1, s0 = 0) to one structure node (end 2).
  CableElement(const Eigen::Vector2d& anchor, int node, const CableProperties& cable);
  // A cable between two structure nodes; node1 is end 1 (s0 = 0).
  CableElement(int node1, int node2, const CableProperties& cable);

  std::vector<int> nodes() const override;

  // Internal force: the force the nodes exert on the cable (minus the cable's pull on them), and its tangent
  // [K -K; -K K] (or K alone for an anchored cable). The converged end tension is kept as the next first
  // guess.
  void evaluate(const std::vector<Eigen::Vector2d>& positions, Eigen::VectorXd& internal_force,
                Eigen::MatrixXd& tangent) override;

  // The tank frame's inertial load (-m a_g per unit length) changes between steps; gravity stays in `cable`.
  void set_horizontal_load(double load_per_length) { cable_.horizontal_load = load_per_length; }

  const CableProperties& properties() const { return cable_; }
  bool anchored() const { return anchored_; }
  const Eigen::Vector2d& anchor() const { return anchor_; }
  // State of the last evaluation (tensions, sag, slack/taut) for probes and health checks.
  const CatenarySolution& last_solution() const { return last_; }

  // A restart's state: the last solution (what probes read, and the next first guess) and the tank frame's load,
  // as doubles appended to / read from `state` (restore returns the values it used).
  void save_state(std::vector<double>& state) const;
  std::size_t restore_state(const double* state, std::size_t available);

 private:
  CableProperties cable_;
  bool anchored_;
  Eigen::Vector2d anchor_ = Eigen::Vector2d::Zero();
  std::vector<int> nodes_;
  CatenarySolution last_;
  bool have_warm_start_ = false;
};

}  // namespace halfeti::cable
