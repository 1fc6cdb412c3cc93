// Principle 5: a small sloshing box shaken sideways gives bitwise the same particles (gathered by global id) and
// probes on 1, 2, 3 and 4 ranks. Rank 0 recomputes the run alone on MPI_COMM_SELF as the reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "halfeti/parallel/ordered_reduce.hpp"
#include "halfeti/sph/fluid.hpp"

using namespace halfeti::sph;

namespace {
// A test-local ground motion (the excitation module's own is not needed here).
class Shake : public halfeti::excitation::GroundMotion {
 public:
  double acceleration(double t) const override { return 5.0 * std::sin(2.0 * M_PI * t / 0.1); }
  std::string describe() const override { return "test shake"; }
};

FluidParams box() {
  FluidParams p;
  p.tank_length = 0.30;
  p.tank_height = 0.20;
  p.spacing = 0.01;
  p.water = {{0.0, 0.0, 0.30, 0.10, 0.01}};
  p.peak_ground_acceleration = 5.0;
  p.rebalance_interval = 10;
  p.rebalance_threshold = 1.01;  // rebalance often, to exercise it
  return p;
}

struct Result {
  std::vector<std::int64_t> gid;
  std::vector<double> fields;  // x, y, vx, vy, rho per particle, sorted by gid
  std::vector<double> probes;
};

Result run(MPI_Comm comm, int steps) {
  Shake shake;
  Fluid fluid(comm, box(), &shake);
  for (int s = 0; s < steps; ++s) fluid.step();
  Result r;
  std::vector<double> f;
  std::vector<std::int64_t> g(fluid.gid().begin(), fluid.gid().begin() + fluid.owned_count());
  for (std::size_t i = 0; i < fluid.owned_count(); ++i)
    f.insert(f.end(), {fluid.x()[i], fluid.y()[i], fluid.vx()[i], fluid.vy()[i], fluid.rho()[i]});
  halfeti::parallel::gather_sorted(comm, g, f, 5, r.gid, r.fields);
  const auto u = fluid.velocity_at(0.1, 0.05);
  r.probes = {fluid.time(), fluid.pressure_at(0.05, 0.03), u[0], u[1], fluid.free_surface_elevation(0.01),
              fluid.total_mass(), fluid.kinetic_energy(), fluid.max_density_variation()};
  return r;
}
}  // namespace

TEST(FluidRanks, BitwiseIdenticalToOneRank) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int steps = 800;
  const Result distributed = run(MPI_COMM_WORLD, steps);
  int same = 1;
  if (rank == 0) {
    const Result serial = run(MPI_COMM_SELF, steps);
    EXPECT_EQ(serial.gid, distributed.gid);
    same = serial.gid == distributed.gid && serial.fields.size() == distributed.fields.size() &&
           std::memcmp(serial.fields.data(), distributed.fields.data(), serial.fields.size() * sizeof(double)) == 0 &&
           std::memcmp(serial.probes.data(), distributed.probes.data(), serial.probes.size() * sizeof(double)) == 0;
    std::size_t differ = 0;
    for (std::size_t k = 0; k < std::min(serial.fields.size(), distributed.fields.size()); ++k)
      differ += serial.fields[k] != distributed.fields[k];
    std::printf("%d rank(s): %zu particles, %zu field values differ from the 1-rank run; t = %.5f s, KE = %.6e\n",
                size, serial.gid.size(), differ, serial.probes[0], serial.probes[6]);
    for (std::size_t k = 0; k < serial.probes.size(); ++k)
      EXPECT_EQ(serial.probes[k], distributed.probes[k]) << "probe " << k;
    EXPECT_GT(serial.probes[6], 0.0);  // the box did move
  }
  MPI_Bcast(&same, 1, MPI_INT, 0, MPI_COMM_WORLD);
  EXPECT_TRUE(same);
}
