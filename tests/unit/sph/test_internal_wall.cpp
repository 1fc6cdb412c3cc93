// A rigid internal wall (a line of wall particles between two end points) holds two still water levels apart:
// nobody crosses it, and each side stays hydrostatic.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfeti/sph/fluid.hpp"

using namespace halfeti::sph;

TEST(InternalWall, SeparatesTwoStillWaterLevels) {
  FluidParams p;
  p.tank_length = 0.30;
  p.tank_height = 0.20;
  p.spacing = 0.005;
  p.internal_walls = {{0.15, 0.0, 0.15, 0.20}};
  p.water = {{0.0, 0.0, 0.15, 0.10, 0.0}, {0.15, 0.0, 0.30, 0.05, 0.0}};
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  while (fluid.time() < 0.5) fluid.step();
  int crossed = 0;
  for (std::size_t i = 0; i < fluid.owned_count(); ++i) {
    const bool left_block = fluid.gid()[i] < 30 * 20;  // ids of the first block come first
    crossed += left_block != (fluid.x()[i] < 0.15);
  }
  MPI_Allreduce(MPI_IN_PLACE, &crossed, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(crossed, 0);
  const double rg = p.density * p.gravity;
  const double left = fluid.pressure_at(0.075, 0.02), right = fluid.pressure_at(0.225, 0.02);
  std::printf("left p = %.1f Pa (hydrostatic %.1f), right p = %.1f Pa (hydrostatic %.1f), KE %.2e J/m\n",
              left, rg * 0.08, right, rg * 0.03, fluid.kinetic_energy());
  EXPECT_NEAR(left, rg * 0.08, 0.02 * rg * 0.08);
  EXPECT_NEAR(right, rg * 0.03, 0.02 * rg * 0.03);
}
