// An element that acts on a few nodes of the structure and enters its Newton system beside the solid elements:
// cables (and, in tests, springs). Defined in core so that structure/ and cable/ need not know each other; the
// application wires a cable to the plate nodes it is attached to.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace halfeti {

class NodalElement {
 public:
  virtual ~NodalElement() = default;

  // Structure node indices the element acts on (2 dofs each: x, y).
  virtual std::vector<int> nodes() const = 0;

  // Given the current positions of those nodes (in the order of nodes()), the element's internal force on them
  // (2n entries, x0 y0 x1 y1 ..., the force the nodes exert on the element, i.e. it enters the residual as F_int)
  // and its tangent d(force)/d(position) (2n x 2n, symmetric).
  virtual void evaluate(const std::vector<Eigen::Vector2d>& positions, Eigen::VectorXd& internal_force,
                        Eigen::MatrixXd& tangent) = 0;
};

}  // namespace halfeti
