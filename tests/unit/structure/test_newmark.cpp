// Newmark's integrator alone (newmark.hpp), on closed forms: a constant acceleration integrated exactly; on the
// harmonic oscillator u'' + w^2 u = 0 the trapezoidal rule keeps the energy to round-off with the period
// lengthened by (w dt)^2 / 12 (Hughes 1987, The Finite Element Method, section 9.3), and gamma > 1/2 damps with
// the algorithmic damping ratio (gamma - 1/2) w dt / 2 at small w dt; the stability check of its parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "halfeti/core/error.hpp"
#include "halfeti/structure/newmark.hpp"

using halfeti::structure::Newmark;
using halfeti::structure::NewmarkParameters;

namespace {
struct Oscillator {
  std::vector<double> u, v;  // per step
};

// u'' + w^2 u = 0 from u = 1, v = 0: each step solves u_n+1 from a(u) + w^2 u = 0, a linear in u.
Oscillator oscillate(const NewmarkParameters& p, double w, double dt, int steps) {
  const Newmark nm(p);
  Eigen::VectorXd u(1), v(1), a(1), un(1), vn(1), an(1), zero = Eigen::VectorXd::Zero(1), a0(1);
  u << 1.0;
  v << 0.0;
  a << -w * w;
  Oscillator out;
  for (int s = 0; s < steps; ++s) {
    un = u, vn = v, an = a;
    nm.acceleration(zero, un, vn, an, dt, a0);  // a(u) = a0 + c u
    u(0) = -a0(0) / (nm.mass_coefficient(dt) + w * w);
    nm.acceleration(u, un, vn, an, dt, a);
    nm.velocity(vn, an, a, dt, v);
    out.u.push_back(u(0));
    out.v.push_back(v(0));
  }
  return out;
}

// Times of the downward zero crossings of u (linear interpolation), from step 0 at t = dt.
std::vector<double> crossings(const std::vector<double>& u, double dt) {
  std::vector<double> t;
  for (std::size_t i = 1; i < u.size(); ++i)
    if (u[i - 1] > 0.0 && u[i] <= 0.0) t.push_back(dt * (i + u[i - 1] / (u[i - 1] - u[i])));
  return t;
}
}  // namespace

TEST(Newmark, ConstantAccelerationIsExactForAnyParameters) {
  for (const NewmarkParameters p : {NewmarkParameters{0.25, 0.5}, NewmarkParameters{0.36, 0.7}}) {
    const Newmark nm(p);
    const double dt = 0.01, g = -9.81, v0 = 0.3, u0 = 0.1;
    Eigen::VectorXd un(1), vn(1), an(1), u(1), a(1), v(1);
    un << u0;
    vn << v0;
    an << g;
    u << u0 + v0 * dt + 0.5 * g * dt * dt;
    nm.acceleration(u, un, vn, an, dt, a);
    nm.velocity(vn, an, a, dt, v);
    EXPECT_NEAR(a(0), g, 1e-9 * std::abs(g));
    EXPECT_NEAR(v(0), v0 + g * dt, 1e-12);
    EXPECT_DOUBLE_EQ(nm.mass_coefficient(dt), 1.0 / (p.beta * dt * dt));
  }
}

TEST(Newmark, TrapezoidalRuleKeepsTheEnergyAndLengthensThePeriodAsKnown) {
  const double w = 2.0 * M_PI, dt = 0.02;  // period 1 s, 50 steps a period
  const auto o = oscillate({0.25, 0.5}, w, dt, 5000);
  for (std::size_t i = 0; i < o.u.size(); ++i)
    ASSERT_NEAR(0.5 * o.v[i] * o.v[i] + 0.5 * w * w * o.u[i] * o.u[i], 0.5 * w * w, 1e-10 * w * w)
        << "step " << i;
  const auto t = crossings(o.u, dt);
  ASSERT_GT(t.size(), 50u);
  const double period = (t.back() - t.front()) / (t.size() - 1);
  const double elongation = (period - 1.0) / 1.0, expected = (w * dt) * (w * dt) / 12.0;  // 1.3e-3
  EXPECT_NEAR(elongation, expected, 0.02 * expected);
}

TEST(Newmark, GammaAboveOneHalfDampsAtItsKnownRatio) {
  // gamma = 0.7, beta = (gamma + 1/2)^2 / 4 = 0.36: the coupled scenes' setting.
  const double w = 2.0 * M_PI, dt = 0.005;             // w dt = 0.031
  const auto o = oscillate({0.36, 0.7}, w, dt, 4000);  // 20 periods
  double peak_first = 0.0, peak_last = 0.0;
  for (int i = 0; i < 200; ++i) peak_first = std::max(peak_first, o.u[i]);
  for (int i = 3800; i < 4000; ++i) peak_last = std::max(peak_last, o.u[i]);
  // Amplitude after 19 periods: exp(-xi w 19 T) with xi = (gamma - 1/2) w dt / 2.
  const double xi = 0.2 * w * dt / 2.0;
  const double measured = -std::log(peak_last / peak_first) / (w * 19.0);
  EXPECT_NEAR(measured, xi, 0.05 * xi);
  // High frequencies (w dt = 10) are damped within a few steps; the trapezoidal rule keeps them.
  const auto stiff = oscillate({0.36, 0.7}, 1000.0, 0.01, 40);
  EXPECT_LT(std::abs(stiff.u.back()), 0.05);
  const auto kept = oscillate({0.25, 0.5}, 1000.0, 0.01, 40);
  EXPECT_GT(std::abs(kept.u.back()) + std::abs(kept.v.back()) / 1000.0, 0.99);
}

TEST(Newmark, ParametersOutsideUnconditionalStabilityAreRefused) {
  EXPECT_NO_THROW(halfeti::structure::validate(NewmarkParameters{0.25, 0.5}));
  EXPECT_NO_THROW(halfeti::structure::validate(NewmarkParameters{0.36, 0.7}));
  EXPECT_THROW(halfeti::structure::validate(NewmarkParameters{0.25, 0.7}), halfeti::UserError);  // < 0.36
  EXPECT_THROW(halfeti::structure::validate(NewmarkParameters{0.0, 0.5}), halfeti::UserError);
  EXPECT_THROW(halfeti::structure::validate(NewmarkParameters{0.3, 0.4}), halfeti::UserError);
}
