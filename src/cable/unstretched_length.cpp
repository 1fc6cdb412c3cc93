// Unstretched length for a prescribed end tension: the inverse problem of the design tool
// (`--tension-stress`).
#include <algorithm>
#include <cmath>

#include "halfeti/cable/catenary.hpp"
#include "halfeti/core/error.hpp"

namespace halfeti::cable {

double unstretched_length_for_end_tension(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                                          double axial_stiffness, double weight_per_length,
                                          double end_tension) {
  const double chord = (end2 - end1).norm();
  if (!(end_tension > 0.0))
    HALFETI_USER_ERROR("the prescribed cable tension must be positive, got " << end_tension);
  if (!(chord > 0.0)) HALFETI_USER_ERROR("the cable ends coincide: no unstretched length gives a tension");
  CableProperties cable;
  cable.axial_stiffness = axial_stiffness;
  cable.weight_per_length = weight_per_length;
  Eigen::Vector2d warm = Eigen::Vector2d::Zero();
  bool have_warm = false;
  // Tension at end 2 minus the target, as a function of log(L0).
  auto excess = [&](double log_l0) {
    cable.unstretched_length = std::exp(log_l0);
    const CatenarySolution s = solve_catenary(end1, end2, cable, have_warm ? &warm : nullptr);
    warm = s.end_tension;
    have_warm = true;
    return s.tension_end - end_tension;
  };
  // The taut branch: the tension falls from +infinity (L0 -> 0) as L0 grows, down to a minimum for a heavy
  // cable. Bracket the root on that branch, starting from an elastic bar.
  double lo = std::log(chord / (1.0 + end_tension / axial_stiffness));
  double f_lo = excess(lo);
  while (f_lo < 0.0) {
    lo -= 0.1;
    f_lo = excess(lo);
  }
  double hi = lo;
  double f_hi = f_lo;
  double before = lo;  // the sample before `hi`
  for (int k = 0; f_hi > 0.0; ++k) {
    const double next = hi + 0.02 * (1 << std::min(k, 10));
    const double f_next = excess(next);
    if (f_next > f_hi || k > 200) {
      // Past the minimum of the end tension, still above the target: locate the minimum (golden section on
      // [before, next]) and go on from it if it reaches the target.
      double a = before, b = next;
      const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
      double c = b - ratio * (b - a), d = a + ratio * (b - a);
      double fc = excess(c), fd = excess(d);
      for (int it = 0; it < 100 && b - a > 1e-10 && std::min(fc, fd) > 0.0; ++it) {
        if (fc < fd) {
          b = d;
          d = c;
          fd = fc;
          c = b - ratio * (b - a);
          fc = excess(c);
        } else {
          a = c;
          c = d;
          fc = fd;
          d = a + ratio * (b - a);
          fd = excess(d);
        }
      }
      const double f_min = std::min(fc, fd);
      if (f_min > 0.0)
        HALFETI_USER_ERROR("no unstretched length gives an end tension of "
                           << end_tension << " N: the cable's own weight keeps it at or above "
                           << f_min + end_tension << " N for this span");
      hi = fc < fd ? c : d;
      f_hi = f_min;
      break;
    }
    before = hi;
    hi = next;
    f_hi = f_next;
  }
  // Illinois false position on [lo, hi].
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    const double f_mid = excess(mid);
    if (f_mid == 0.0) return std::exp(mid);
    if ((f_mid > 0.0) == (f_lo > 0.0)) {
      lo = mid;
      f_lo = f_mid;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = mid;
      f_hi = f_mid;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
    if (std::fabs(f_mid) <= 1e-13 * end_tension) return std::exp(mid);
  }
  return std::exp(0.5 * (lo + hi));
}

}  // namespace halfeti::cable
