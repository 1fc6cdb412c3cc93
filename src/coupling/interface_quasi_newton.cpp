// IQN-ILS (Degroote et al. 2009, section 3): from the iterations i = 0..k of one time step, with residuals
// r_i = H(x_i) - x_i and outputs y_i = H(x_i), the columns V = [r_k - r_i] and W = [y_k - y_i] (i < k) model how
// the output changes with the residual, W = J V. The least-squares coefficients c of min ||V c + r_k|| give the
// change that drives the residual to zero in the secant model, and the next input is x_k+1 = y_k + W c.
#include "halfeti/coupling/interface_quasi_newton.hpp"

#include "halfeti/core/error.hpp"

namespace halfeti::coupling {

void InterfaceQuasiNewton::start() {
  residuals_.clear();
  outputs_.clear();
}

double InterfaceQuasiNewton::residual_ratio(const Eigen::VectorXd& x, const Eigen::VectorXd& hx) {
  const double scale = hx.norm();
  const double r = (hx - x).norm();
  return scale > 0.0 ? r / scale : (r > 0.0 ? r : 0.0);
}

Eigen::VectorXd InterfaceQuasiNewton::next(const Eigen::VectorXd& x, const Eigen::VectorXd& hx) {
  HALFETI_CHECK(x.size() == hx.size(), "interface quasi-Newton: input and output of different sizes");
  const Eigen::VectorXd r = hx - x;
  const double w = options_.relaxation;
  if (options_.method == InterfaceAcceleration::kRelaxation) return x + w * r;
  residuals_.push_back(r);
  outputs_.push_back(hx);
  const int k = static_cast<int>(residuals_.size()) - 1;
  // At most as many columns as unknowns: more cannot be independent.
  const int first = std::max(0, k - static_cast<int>(x.size()));
  const int m = k - first;
  if (m == 0) return x + w * r;  // no secant pair yet: a relaxed fixed-point step
  Eigen::MatrixXd V(x.size(), m), W(x.size(), m);
  for (int j = 0; j < m; ++j) {
    const int i = k - 1 - j;  // newest first
    V.col(j) = r - residuals_[static_cast<std::size_t>(i)];
    W.col(j) = hx - outputs_[static_cast<std::size_t>(i)];
  }
  // Column-pivoted QR: columns that have become (nearly) dependent get no weight, instead of a blown-up one.
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(V);
  qr.setThreshold(1e-10);
  const Eigen::VectorXd c = qr.solve(-r);
  return hx + W * c;
}

}  // namespace halfeti::coupling
