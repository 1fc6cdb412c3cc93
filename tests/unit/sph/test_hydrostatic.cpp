// Hydrostatic tank (validation ladder step 1), inputs/validation/hydrostatic.yaml at a coarse spacing: still water
// must stay still.
// HALFETI_HYDROSTATIC_DX=0.0015 runs the paper's resolution (the figure in docs/sph.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "halfeti/sph/fluid.hpp"
#include "scene_fluid.hpp"

using namespace halfeti::sph;

TEST(Hydrostatic, PressureFollowsRhoGDepthAfterOneSecond) {
  // inputs/validation/hydrostatic.yaml at dx 5 mm (the scene's 1.5 mm with HALFETI_HYDROSTATIC_DX=0.0015).
  const char* dx = std::getenv("HALFETI_HYDROSTATIC_DX");
  const FluidParams p = halfeti::test::scene_fluid_params(
      "inputs/validation/hydrostatic.yaml", {std::string("fluid.spacing=") + (dx ? dx : "0.005")});
  ASSERT_EQ(p.tank_length, 0.30);
  ASSERT_EQ(p.water.size(), 1u);
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  const double m0 = fluid.total_mass();
  const long n0 = fluid.global_count();
  while (fluid.time() < 1.0) fluid.step();
  const double g = p.gravity, rho0 = p.density, d = 0.10;
  for (double y : {0.005, 0.025, 0.05}) {
    const double expected = rho0 * g * (d - y);
    const double got = fluid.pressure_at(0.15, y);
    std::printf("y = %.3f m: p = %.2f Pa, rho g (d - y) = %.2f Pa, error %.3f%%\n", y, got, expected,
                100.0 * (got - expected) / expected);
    EXPECT_NEAR(got, expected, 0.01 * expected) << "at y = " << y;
  }
  std::printf("steps %ld, max density variation %.4f%%, kinetic energy %.3e J/m\n", fluid.step_count(),
              100.0 * fluid.max_density_variation(), fluid.kinetic_energy());
  EXPECT_LT(fluid.max_density_variation(), 0.01);
  // The kernel-interpolated surface level: the still surface d (the top particles' centres + dx/2), in mid-tank
  // and beside either wall (the walls mirror the water), within a quarter spacing (the water's compression under
  // its weight lowers the top by rho g d / (rho0 c0^2) d, about 0.1 % of d here), as the top-particle elevation.
  for (double x : {0.15, 0.001, 0.299}) {
    const double level = fluid.surface_level(x), top = fluid.free_surface_elevation(x);
    std::printf("x = %.3f m: surface level %.5f m, top particle + dx/2 %.5f m (still depth %.3f m)\n", x,
                level, top, d);
    EXPECT_NEAR(level, d, 0.25 * p.spacing) << "at x = " << x;
  }
  EXPECT_DOUBLE_EQ(fluid.total_mass(), m0);
  long n = static_cast<long>(fluid.owned_count());
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(n, n0);
}

TEST(Hydrostatic, TheSurfaceLevelIgnoresSprayAboveTheBulk) {
  // A lump of water (4 x 2 particles) 10 cm above the surface, as a run-up jet's spray: the top-particle elevation
  // follows it, the kernel-interpolated level stays at the bulk's surface.
  FluidParams p;
  p.tank_length = 0.30;
  p.tank_height = 0.40;
  p.spacing = 0.005;
  p.water = {{0.0, 0.0, 0.30, 0.10, 0.0}, {0.14, 0.20, 0.16, 0.21, 0.0}};
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  EXPECT_NEAR(fluid.free_surface_elevation(0.15), 0.21, 1e-9);
  EXPECT_NEAR(fluid.surface_level(0.15), 0.10, 0.25 * p.spacing);
  EXPECT_NEAR(fluid.surface_level(0.05), 0.10, 0.25 * p.spacing);
}

TEST(Hydrostatic, TheSurfaceModeReadsTheInitialCosine) {
  // Water released from a first-mode surface A cos(pi x / L) (A = 2 dx, the lattice rounding each column's top to
  // its spacing): the mode-1 amplitude reads A, the mode-2 amplitude 0, each within a quarter spacing (the
  // interpolated level's error at a flat surface, above); a surface of -A reads -A (the sign is the mode's phase).
  for (double a : {0.01, -0.01}) {
    FluidParams p;
    p.tank_length = 0.30;
    p.tank_height = 0.40;
    p.spacing = 0.005;
    p.water = {{0.0, 0.0, 0.30, 0.10, a}};
    Fluid fluid(MPI_COMM_WORLD, p, nullptr);
    const double m1 = fluid.surface_mode(1, 32), m2 = fluid.surface_mode(2, 32);
    std::printf("A = %+.3f m: mode 1 %+.5f m, mode 2 %+.5f m\n", a, m1, m2);
    EXPECT_NEAR(m1, a, 0.25 * p.spacing);
    EXPECT_NEAR(m2, 0.0, 0.25 * p.spacing);
  }
}
