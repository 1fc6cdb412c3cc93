// Linear sloshing (validation ladder step 3): free decay of a small first-mode surface in a 0.30 m tank with
// 0.10 m of water. The frequency of the elevation at the left wall must be within 2% of
// f1 = sqrt(g k tanh(k d)) / (2 pi), k = pi / L (1.425 Hz).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfeti/sph/fluid.hpp"

using namespace halfeti::sph;

TEST(Sloshing, FirstModeFrequency) {
  const double L = 0.30, d = 0.10, A = 0.005;
  FluidParams p;
  p.tank_length = L;
  p.tank_height = 0.30;
  p.spacing = 0.004;
  p.water = {{0.0, 0.0, L, d, A}};
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  const double k = M_PI / L, f_theory = std::sqrt(p.gravity * k * std::tanh(k * d)) / (2.0 * M_PI);
  // Elevation at the left wall, sampled every step; upward zero crossings of (eta - d), linearly interpolated.
  std::vector<double> crossings;
  double t_prev = 0.0, e_prev = fluid.free_surface_elevation(0.5 * p.spacing) - d;
  while (fluid.time() < 3.2 && crossings.size() < 5) {
    fluid.step();
    const double e = fluid.free_surface_elevation(0.5 * p.spacing) - d;
    if (e_prev < 0.0 && e >= 0.0) crossings.push_back(t_prev + (fluid.time() - t_prev) * (-e_prev) / (e - e_prev));
    t_prev = fluid.time();
    e_prev = e;
  }
  ASSERT_GE(crossings.size(), 3u) << "the surface did not oscillate";
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double f = 1.0 / period, err = (f - f_theory) / f_theory;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("f1 = %.4f Hz from %zu periods (theory %.4f Hz), error %+.2f%%; %ld particles, %ld steps\n", f,
                crossings.size() - 1, f_theory, 100 * err, fluid.global_count(), fluid.step_count());
  EXPECT_LT(std::abs(err), 0.02);
}
