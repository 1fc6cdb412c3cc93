// Speed (DESIGN principle 3): the paper's tank, 0.30 x 0.40 m, 0.10 m of water at dx = 1.5 mm (~13,400
// particles), 0.1 s of small horizontal excitation. Prints ns per particle-step and the phase timers; run it at 1
// and 2 ranks. Checks only that it ran and stayed healthy (figures go to docs/sph.md).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "halfeti/sph/fluid.hpp"

using namespace halfeti::sph;

namespace {
class SmallShake : public halfeti::excitation::GroundMotion {
 public:
  double acceleration(double t) const override { return 0.5 * std::sin(2.0 * M_PI * 1.4 * t); }
  std::string describe() const override { return "0.5 m/s2 sine at 1.4 Hz"; }
};
}  // namespace

TEST(Speed, PaperTankTenthOfASecond) {
  FluidParams p;
  p.tank_length = 0.30;
  p.tank_height = 0.40;
  p.spacing = 0.0015;
  p.water = {{0.0, 0.0, 0.30, 0.10, 0.0}};
  p.peak_ground_acceleration = 0.5;
  SmallShake shake;
  Fluid fluid(MPI_COMM_WORLD, p, &shake);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Barrier(MPI_COMM_WORLD);
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  while (fluid.time() < 0.1) fluid.step();
  MPI_Barrier(MPI_COMM_WORLD);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double particle_steps = static_cast<double>(fluid.global_count()) * fluid.step_count();
  const double ns = 1e9 * wall / particle_steps;
  // CPU time summed over ranks / ranks: what the wall time would be on an idle machine (the test machine is shared).
  double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  MPI_Allreduce(MPI_IN_PLACE, &cpu, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf(
        "%d rank(s): %ld particles, %ld steps, %.2f s wall, %.1f ns per particle-step (max CPU per rank "
        "%.2f s: %.1f ns)\n",
        size, fluid.global_count(), fluid.step_count(), wall, ns, cpu, 1e9 * cpu / particle_steps);
    for (const auto& [phase, s] : fluid.timers().all()) std::printf("  %-17s %7.3f s\n", phase.c_str(), s);
  }
  EXPECT_LT(fluid.max_density_variation(), 0.01);
}
