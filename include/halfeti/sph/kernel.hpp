// Smoothing kernels in 2D as small pure functions (value and radial derivative), support radius 2h.
#pragma once

#include <cmath>

namespace halfeti::sph {

enum class KernelKind { kCubicSpline, kWendlandC2 };

struct Kernel {
  KernelKind kind = KernelKind::kCubicSpline;
  double h = 1.0;

  double support() const { return 2.0 * h; }

  // W(r): integrates to 1 over the plane.
  double value(double r) const {
    const double q = r / h;
    if (kind == KernelKind::kCubicSpline) {
      const double s = 10.0 / (7.0 * M_PI * h * h);  // Monaghan's cubic spline, 2D normalisation
      if (q < 1.0) return s * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
      if (q < 2.0) return s * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
      return 0.0;
    }
    const double s = 7.0 / (4.0 * M_PI * h * h);  // Wendland C2 with support 2h (Dehnen & Aly 2012)
    if (q >= 2.0) return 0.0;
    const double a = 1.0 - 0.5 * q;
    return s * a * a * a * a * (2.0 * q + 1.0);
  }

  // dW/dr (<= 0). The gradient with respect to r_i of W(|r_i - r_j|) is dW/dr * (r_i - r_j) / r.
  double derivative(double r) const {
    const double q = r / h;
    if (kind == KernelKind::kCubicSpline) {
      const double s = 10.0 / (7.0 * M_PI * h * h * h);
      if (q < 1.0) return s * (-3.0 * q + 2.25 * q * q);
      if (q < 2.0) return -s * 0.75 * (2.0 - q) * (2.0 - q);
      return 0.0;
    }
    const double s = 7.0 / (4.0 * M_PI * h * h * h);
    if (q >= 2.0) return 0.0;
    const double a = 1.0 - 0.5 * q;
    return -s * 5.0 * q * a * a * a;
  }
};

}  // namespace halfeti::sph
