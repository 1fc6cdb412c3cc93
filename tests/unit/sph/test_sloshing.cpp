// Linear sloshing (validation ladder step 3): free decay of a small first-mode surface in a 0.30 m tank with
// 0.10 m of water. The frequency of the elevation at the left wall must be within 2% of
// f1 = sqrt(g k tanh(k d)) / (2 pi), k = pi / L (1.425 Hz).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfeti/io/metrics.hpp"
#include "halfeti/sph/fluid.hpp"
#include "scene_fluid.hpp"

using namespace halfeti::sph;

TEST(Sloshing, FirstModeFrequency) {
  // inputs/validation/sloshing.yaml (amplitude 3 mm) at dx 3 mm: one spacing of amplitude (at dx 4 mm, 0.75 dx, the
  // crossings read +3.7 %: docs/studies.md, sloshing).
  const FluidParams p =
      halfeti::test::scene_fluid_params("inputs/validation/sloshing.yaml", {"fluid.spacing=0.003"});
  ASSERT_EQ(p.water.size(), 1u);
  const double L = p.tank_length, d = p.water[0].y1;
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  const double k = M_PI / L, f_theory = std::sqrt(p.gravity * k * std::tanh(k * d)) / (2.0 * M_PI);
  // Elevation at the left wall, sampled every step, over 3.2 s (four periods and more); the frequency from the
  // upward crossings of the still depth d (io/metrics.hpp).
  halfeti::io::Curve eta{{0.0}, {fluid.free_surface_elevation(0.5 * p.spacing)}};
  while (fluid.time() < 3.2) {
    fluid.step();
    eta.t.push_back(fluid.time());
    eta.v.push_back(fluid.free_surface_elevation(0.5 * p.spacing));
  }
  const double period = 1.0 / halfeti::io::crossing_frequency(eta, {}, d);
  const double f = 1.0 / period, err = (f - f_theory) / f_theory;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("f1 = %.4f Hz (theory %.4f Hz), error %+.2f%%; %ld particles, %ld steps\n", f, f_theory,
                100 * err, fluid.global_count(), fluid.step_count());
  EXPECT_LT(std::abs(err), 0.02);
}

TEST(Sloshing, FirstModeFrequencyWithTheWendlandKernelAtTwentyParticlesOverTheDepth) {
  // Issue #20 item 3 (docs/sph.md, "The sloshing frequency's bias"): at d / dx = 20 the scene's cubic spline with
  // h = 1.33 dx reads the first mode 1.7-2.2 % high (amplitude 10-5 mm), the Wendland C2 kernel with h = 2 dx
  // within 1 %. The mode's amplitude from the whole interpolated surface (surface_mode), every 5 ms over 3 s; the
  // frequency from its upward crossings of the mean after 0.1 s; bound 1 % (the issue's).
  const FluidParams p = halfeti::test::scene_fluid_params(
      "inputs/validation/sloshing.yaml",
      {"fluid.spacing=0.005", "fluid.kernel=wendland_c2", "fluid.smoothing_ratio=2.0",
       "fluid.water.0.surface_amplitude=0.01"});
  const double L = p.tank_length, d = p.water[0].y1;
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  const double k = M_PI / L, f_theory = std::sqrt(p.gravity * k * std::tanh(k * d)) / (2.0 * M_PI);
  halfeti::io::Curve mode{{0.0}, {fluid.surface_mode(1, 32)}};
  double next = 0.005;
  while (fluid.time() < 3.0) {
    fluid.step();
    if (fluid.time() >= next) {
      mode.t.push_back(fluid.time());
      mode.v.push_back(fluid.surface_mode(1, 32));
      next += 0.005;
    }
  }
  const double f = halfeti::io::crossing_frequency(mode, {0.1, 3.0});
  const double err = (f - f_theory) / f_theory;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("Wendland C2, h = 2 dx, d / dx = 20: f1 = %.4f Hz (theory %.4f Hz), error %+.2f%%\n", f,
                f_theory, 100 * err);
  EXPECT_LT(std::abs(err), 0.01);
}
