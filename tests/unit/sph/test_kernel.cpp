// Kernels: normalisation (integral and lattice sum), derivative against finite differences, compact support.
#include <gtest/gtest.h>

#include <cmath>

#include "halfeti/sph/kernel.hpp"

using namespace halfeti::sph;

namespace {
double integral(const Kernel& k) {
  // Radial quadrature of 2 pi r W(r) over [0, 2h] (midpoint rule, fine).
  const int n = 200000;
  const double dr = k.support() / n;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    s += 2.0 * M_PI * r * k.value(r) * dr;
  }
  return s;
}
double lattice_sum(const Kernel& k, double dx) {
  double s = 0.0;
  for (int j = -10; j <= 10; ++j)
    for (int i = -10; i <= 10; ++i) s += dx * dx * k.value(std::hypot(i * dx, j * dx));
  return s;
}
}  // namespace

TEST(Kernel, IntegratesToOne) {
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    const Kernel k{kind, 0.0133};
    EXPECT_NEAR(integral(k), 1.0, 1e-6);
  }
}

TEST(Kernel, LatticeSumNearOne) {
  const double dx = 0.01;
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    const Kernel k{kind, 1.33 * dx};
    EXPECT_NEAR(lattice_sum(k, dx), 1.0, 0.01);
  }
}

TEST(Kernel, DerivativeMatchesFiniteDifference) {
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    const Kernel k{kind, 0.02};
    for (double q = 0.05; q < 1.99; q += 0.07) {
      const double r = q * k.h, e = 1e-7 * k.h;
      const double fd = (k.value(r + e) - k.value(r - e)) / (2 * e);
      EXPECT_NEAR(k.derivative(r), fd, 1e-6 * std::abs(k.value(0.0)) / k.h) << "q = " << q;
    }
  }
}

TEST(Kernel, CompactSupportAndContinuity) {
  const Kernel k{KernelKind::kCubicSpline, 0.01};
  EXPECT_EQ(k.value(k.support()), 0.0);
  EXPECT_EQ(k.derivative(k.support() * 1.01), 0.0);
  EXPECT_NEAR(k.value(k.h * (1 - 1e-12)), k.value(k.h * (1 + 1e-12)), 1e-6);  // joined at q = 1
  EXPECT_LT(k.derivative(0.5 * k.h), 0.0);
}

TEST(Kernel, LatticeGradientMomentNearOne) {
  // The discrete first moment of grad W on the lattice; the fluid divides the gradient by it.
  const double dx = 0.001;
  const Kernel k{KernelKind::kCubicSpline, 1.33 * dx};
  const double m = lattice_gradient_moment(k, dx);
  EXPECT_NEAR(m, 1.0, 0.02);
  EXPECT_NE(m, 1.0);
}
