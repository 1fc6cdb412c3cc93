// Smoothing kernels in 2D as small pure functions (value and radial derivative), support radius 2h.
#pragma once

#include <cmath>

namespace halfeti::sph {

enum class KernelKind { kCubicSpline, kWendlandC2 };

struct Kernel {
  KernelKind kind = KernelKind::kCubicSpline;
  double h = 1.0;
  // Divides dW/dr: 1 for the textbook kernel; Fluid sets it to lattice_gradient_moment() so that the discrete
  // gradient of a linear field is exact on the initial square lattice (see docs/sph.md).
  double gradient_scale = 1.0;

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
  double derivative(double r) const { return raw_derivative(r) / gradient_scale; }

  double raw_derivative(double r) const {
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

// The kernel with its constants folded, for the neighbour search's hot loop: W(r) and F(r) = W'(r) / r at once.
class KernelEvaluator {
 public:
  explicit KernelEvaluator(const Kernel& k)
      : cubic_(k.kind == KernelKind::kCubicSpline),
        inv_h_(1.0 / k.h),
        w0_(cubic_ ? 10.0 / (7.0 * M_PI * k.h * k.h) : 7.0 / (4.0 * M_PI * k.h * k.h)),
        f0_(w0_ / (k.h * k.h * k.gradient_scale)) {}

  void operator()(double r, double& w, double& f) const {
    const double q = r * inv_h_;
    if (cubic_) {
      cubic(q, w, f);
    } else {
      const double a = 1.0 - 0.5 * q, a3 = a * a * a;
      w = w0_ * a3 * a * (2.0 * q + 1.0);
      f = -f0_ * 5.0 * a3;
    }
  }

  // W and F for n squared distances at once, r = sqrt(r2[m]): the same values as operator() on each, in a loop
  // the compiler turns into vector instructions (sqrt and division two, four or eight at a time).
  void batch(const double* r2, int n, double* w, double* f) const {
    if (cubic_) {
      for (int m = 0; m < n; ++m) cubic(std::sqrt(r2[m]) * inv_h_, w[m], f[m]);
    } else {
      for (int m = 0; m < n; ++m) operator()(std::sqrt(r2[m]), w[m], f[m]);
    }
  }

 private:
  // The cubic spline at q = r / h, both of its pieces.
  void cubic(double q, double& w, double& f) const {
    // Both pieces, then a select: in a disordered flow q < 1 is a coin toss for the branch predictor, and the
    // mispredictions cost more than the arithmetic (the same values as a branch would give, bit for bit).
    const double a = 2.0 - q;
    const double w_in = w0_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    const double f_in = f0_ * (-3.0 + 2.25 * q);  // (dW/dr) / r = (w0 / h^2) (-3 q + 2.25 q^2) / q
    const double w_out = w0_ * 0.25 * a * a * a;
    const double f_out = -f0_ * 0.75 * a * a / q;  // not used at q = 0 (inner piece)
    const bool inner = q < 1.0;
    w = inner ? w_in : w_out;
    f = inner ? f_in : f_out;
  }

  bool cubic_;
  double inv_h_, w0_, f0_;
};

// First moment of the kernel gradient on a square lattice of spacing dx: sum_j dx^2 x_j^2 |W'(r_j)| / r_j over
// the lattice points around the origin. It is 1 for the continuous integral; on a lattice it is not quite (1.010
// for the cubic spline at h = 1.33 dx), which shows up as a 1% error of the hydrostatic pressure.
inline double lattice_gradient_moment(const Kernel& k, double dx) {
  const int n = static_cast<int>(std::ceil(k.support() / dx)) + 1;
  double m = 0.0;
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      if (i == 0 && j == 0) continue;
      const double x = i * dx, y = j * dx, r = std::sqrt(x * x + y * y);
      m += dx * dx * x * x / r * -k.raw_derivative(r);
    }
  return m;
}

}  // namespace halfeti::sph
