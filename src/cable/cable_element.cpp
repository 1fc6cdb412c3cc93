#include "halfeti/cable/cable_element.hpp"

#include "halfeti/core/error.hpp"

namespace halfeti::cable {

CableElement::CableElement(const Eigen::Vector2d& anchor, int node, const CableProperties& cable)
    : cable_(cable), anchored_(true), anchor_(anchor), nodes_{node} {
  HALFETI_CHECK(node >= 0, "cable node index " << node << " is negative");
}

CableElement::CableElement(int node1, int node2, const CableProperties& cable)
    : cable_(cable), anchored_(false), nodes_{node1, node2} {
  HALFETI_CHECK(node1 >= 0 && node2 >= 0 && node1 != node2,
                "cable needs two distinct node indices, got " << node1 << " and " << node2);
}

std::vector<int> CableElement::nodes() const {
  return nodes_;
}

void CableElement::evaluate(const std::vector<Eigen::Vector2d>& positions, Eigen::VectorXd& internal_force,
                            Eigen::MatrixXd& tangent) {
  HALFETI_CHECK(positions.size() == nodes_.size(),
                "cable element got " << positions.size() << " positions for " << nodes_.size() << " nodes");
  const Eigen::Vector2d end1 = anchored_ ? anchor_ : positions[0];
  const Eigen::Vector2d end2 = anchored_ ? positions[0] : positions[1];
  const Eigen::Vector2d warm = last_.end_tension;
  last_ = solve_catenary(end1, end2, cable_, have_warm_start_ ? &warm : nullptr);
  have_warm_start_ = last_.carries_load;
  // The residual takes the force the nodes exert on the cable: minus the cable's pull on the nodes.
  if (anchored_) {
    internal_force = -last_.nodal_force.tail<2>();
    tangent = last_.tangent.bottomRightCorner<2, 2>();
  } else {
    internal_force = -last_.nodal_force;
    tangent = last_.tangent;
  }
}

}  // namespace halfeti::cable
