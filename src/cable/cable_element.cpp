#include "halfeti/cable/cable_element.hpp"

#include <algorithm>

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

namespace {
// The flat layout of a cable's restart state (CatenarySolution's fields in order, then the element's own).
template <class Visit>
void visit_state(CatenarySolution& s, double& load, double& warm, Visit&& visit) {
  visit(s.end_tension.data(), 2);
  visit(&s.tension_start, 1);
  visit(&s.tension_end, 1);
  visit(&s.sag, 1);
  visit(&s.chord, 1);
  visit(s.flexibility.data(), 4);
  visit(s.stiffness.data(), 4);
  visit(s.nodal_force.data(), 4);
  visit(s.tangent.data(), 16);
  visit(&load, 1);
  visit(&warm, 1);
}
constexpr std::size_t kStateSize = 2 + 4 + 12 + 16 + 2 + 3;  // + state, carries_load, iterations
}  // namespace

void CableElement::save_state(std::vector<double>& state) const {
  CatenarySolution s = last_;
  double load = cable_.horizontal_load, warm = have_warm_start_ ? 1.0 : 0.0;
  visit_state(s, load, warm, [&](const double* p, int n) { state.insert(state.end(), p, p + n); });
  state.push_back(static_cast<double>(static_cast<int>(s.state)));
  state.push_back(s.carries_load ? 1.0 : 0.0);
  state.push_back(static_cast<double>(s.iterations));
}

std::size_t CableElement::restore_state(const double* state, std::size_t available) {
  if (available < kStateSize)
    HALFETI_USER_ERROR("restart: a cable's state needs " << kStateSize << " values, " << available
                                                         << " left");
  double load = 0.0, warm = 0.0;
  const double* p = state;
  visit_state(last_, load, warm, [&](double* q, int n) {
    std::copy(p, p + n, q);
    p += n;
  });
  last_.state = static_cast<CableState>(static_cast<int>(*p++));
  last_.carries_load = *p++ != 0.0;
  last_.iterations = static_cast<int>(*p++);
  cable_.horizontal_load = load;
  have_warm_start_ = warm != 0.0;
  return kStateSize;
}

}  // namespace halfeti::cable
