// The viscous decay of a standing wave (docs/sph.md, "Laminar viscosity"): the first sloshing mode of
// inputs/validation/sloshing.yaml released in a fluid of kinematic viscosity nu decays, by linear theory, at
// 2 nu k^2 in amplitude (Lamb 1932, section 348: the bulk's dissipation of an irrotational wave; the tank's walls and
// floor are free slip, so there are no boundary layers), k = pi / L: 0.219 1/s for nu = 1e-3 m^2/s. The scheme's own
// damping is measured by the same run without viscosity and taken off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "halfeti/sph/fluid.hpp"
#include "scene_fluid.hpp"

using namespace halfeti::sph;

namespace {
constexpr double kNu = 1e-3;      // m^2/s, large enough for the decay to stand well above the scheme's own
constexpr double kEndTime = 4.0;  // s, about six periods
constexpr double kFitFrom = 0.4;  // s, after the release's first transient

// Amplitude decay rate of the first mode: a straight-line fit of log|a| at the mode's extremes from kFitFrom on.
double decay_rate(const std::vector<std::string>& overrides) {
  const FluidParams p = halfeti::test::scene_fluid_params("inputs/validation/sloshing.yaml", overrides);
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  std::vector<double> t{0.0}, a{fluid.surface_mode(1, 32)};
  double next = 0.002;
  while (fluid.time() < kEndTime) {
    fluid.step();
    if (fluid.time() >= next) {
      t.push_back(fluid.time());
      a.push_back(std::abs(fluid.surface_mode(1, 32)));
      next += 0.002;
    }
  }
  double st = 0, sy = 0, stt = 0, sty = 0;
  int n = 0;
  for (std::size_t i = 1; i + 1 < a.size(); ++i)
    if (t[i] >= kFitFrom && a[i] >= a[i - 1] && a[i] > a[i + 1] && a[i] > 0.2 * a[0]) {
      const double y = std::log(a[i]);
      st += t[i];
      sy += y;
      stt += t[i] * t[i];
      sty += t[i] * y;
      ++n;
    }
  EXPECT_GE(n, 8) << "too few extremes of the mode to fit its decay";
  return -(n * sty - st * sy) / (n * stt - st * st);
}
}  // namespace

TEST(ViscousDecay, StandingWaveDecaysAtTheRateTheViscositySets) {
  // c0 held at the value eq. 10 gives this scene (14.2157 m/s) so that alpha below is the stated nu
  const std::vector<std::string> base{"fluid.spacing=0.003", "fluid.sound_speed=14.2157"};
  const FluidParams p = halfeti::test::scene_fluid_params("inputs/validation/sloshing.yaml", base);
  const double k = M_PI / p.tank_length, theory = 2.0 * kNu * k * k;
  const double h = p.h_over_dx * p.spacing;
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> o = base;
    o.insert(o.end(), extra.begin(), extra.end());
    return o;
  };
  const double scheme = decay_rate(with({"fluid.alpha=0"}));
  // eq. 8 as a viscosity: alpha = 8 nu / (h c0) in 2D (Monaghan 2005)
  const double eq8 =
      decay_rate(with({"fluid.alpha=" + std::to_string(8.0 * kNu / (h * p.sound_speed))})) - scheme;
  const double morris =
      decay_rate(with({"fluid.alpha=0", "fluid.laminar_viscosity=" + std::to_string(kNu)})) - scheme;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf(
        "decay of the first mode: the scheme's own %.4f 1/s; added by nu = %g m^2/s: eq. 8 %.4f, laminar "
        "(Morris) %.4f, theory 2 nu k^2 = %.4f 1/s (%.0f %% and %.0f %% of it)\n",
        scheme, kNu, eq8, morris, theory, 100 * eq8 / theory, 100 * morris / theory);
  // Eq. 8's form dissipates at the rate nu sets, to 10 % (the lattice's quadrature of the term, 0.88-1 of nu, and
  // the fit over six periods; measured 101 %).
  EXPECT_NEAR(eq8, theory, 0.10 * theory);
  // Morris's form dissipates, but too little beside a free surface, where the kernel is truncated (Colagrossi et al.
  // 2011, Phys. Rev. E 84, 026705); measured 43 %. The bounds hold the finding: a change that made it consistent
  // there would fail the upper one, and should move docs/sph.md and this bound with it.
  EXPECT_GT(morris, 0.25 * theory);
  EXPECT_LT(morris, 0.60 * theory);
}
