// Health monitors fail loudly with one message naming time, step, particle, place and cause; the Delta C hook
// (eq. 4) acts on exactly the particles it is set for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "halfeti/core/error.hpp"
#include "halfeti/sph/fluid.hpp"

using namespace halfeti::sph;

namespace {
FluidParams small_tank() {
  FluidParams p;
  p.tank_length = 0.10;
  p.tank_height = 0.10;
  p.spacing = 0.005;
  p.water = {{0.0, 0.0, 0.10, 0.04, 0.0}};
  return p;
}
}  // namespace

TEST(Health, ParticleOutsideTheTankIsFatalWithOneClearMessage) {
  FluidParams p = small_tank();
  p.water.push_back({0.10, 0.0, 0.12, 0.02, 0.0});  // a block poking through the right wall
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  try {
    fluid.step();
    FAIL() << "expected a NumericalError";
  } catch (const halfeti::NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("t = "), std::string::npos) << m;
    EXPECT_NE(m.find("step 1"), std::string::npos) << m;
    EXPECT_NE(m.find("left the tank through a wall"), std::string::npos) << m;
    ASSERT_FALSE(fluid.health_events().empty());
    EXPECT_TRUE(fluid.health_events().back().fatal);
    EXPECT_EQ(fluid.health_events().back().kind, "outside_tank");
  }
}

TEST(Health, WaterThrownOverTheOpenTopIsRemovedAndCounted) {
  // A block of 2 x 4 particles above the tank's 0.10 m top: it leaves the run at the first step, not as an error;
  // the mass still in the tank plus the spilled mass is the initial mass (to round-off), one warning says so.
  FluidParams p = small_tank();
  p.water.push_back({0.04, 0.10, 0.06, 0.11, 0.0});
  // A new partition at every step (any imbalance): on 2 ranks the spilling step also moves particles between
  // ranks, so the migration must carry only the particles left.
  p.rebalance_interval = 1;
  p.rebalance_threshold = 1.0;
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  const double initial = fluid.total_mass();
  const long count = fluid.global_count();
  ASSERT_NO_THROW(fluid.step());
  EXPECT_EQ(fluid.global_count(), count - 8);
  EXPECT_GT(fluid.spilled_mass(), 0.0);
  EXPECT_NEAR(fluid.total_mass() + fluid.spilled_mass(), initial, 1e-12 * initial);
  // The ranks hold exactly the particles left, each once, also after the next step's migration.
  for (int s = 0; s < 2; ++s) {
    long held = static_cast<long>(fluid.owned_count());
    MPI_Allreduce(MPI_IN_PLACE, &held, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(held, count - 8) << "after step " << s + 1;
    ASSERT_NO_THROW(fluid.step());
  }
  ASSERT_FALSE(fluid.health_events().empty());
  EXPECT_EQ(fluid.health_events().front().kind, "spilled");
  EXPECT_FALSE(fluid.health_events().front().fatal);
  EXPECT_NE(fluid.health_events().front().message.find("8 particle(s) left over the tank's open top"),
            std::string::npos)
      << fluid.health_events().front().message;
}

TEST(Health, BlowUpIsReportedNotWritten) {
  FluidParams p = small_tank();
  p.sound_speed = 0.3;  // far too slow: the column collapses and the monitors must say so
  p.max_dt = 5e-3;
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  bool thrown = false;
  try {
    for (int s = 0; s < 2000 && fluid.time() < 2.0; ++s) fluid.step();
  } catch (const halfeti::NumericalError&) {
    thrown = true;
  }
  // Either a fatal error or at least the density warning, never silent garbage.
  bool warned = false;
  for (const auto& e : fluid.health_events()) warned |= e.kind == "density_variation";
  EXPECT_TRUE(thrown || warned);
  EXPECT_TRUE(warned);
}

TEST(Hooks, TwoParticlesMovedOntoOnePointKeepFiniteRates) {
  // The contact's relocation (eq. 22) can put two deep invaders on the same point of the surface; the delta term's
  // r_ji / r^2 must not turn that into NaN. Each rank moves its second owned particle onto its first.
  Fluid fluid(MPI_COMM_WORLD, small_tank(), nullptr);
  fluid.compute_forces();
  fluid.predict();
  const std::size_t n = fluid.owned_count();
  std::vector<double> dx(n, 0.0), dy(n, 0.0), dv(n, 0.0), drho(n, 0.0);
  ASSERT_GE(n, 2u);
  dx[1] = fluid.x()[0] - fluid.x()[1];
  dy[1] = fluid.y()[0] - fluid.y()[1];
  fluid.apply_corrections({1}, dx.data(), dy.data(), dv.data(), dv.data(), drho.data());
  fluid.finish();
  for (int s = 0; s < 3; ++s) fluid.step();
  for (std::size_t i = 0; i < fluid.owned_count(); ++i) ASSERT_TRUE(std::isfinite(fluid.rho()[i])) << i;
}

TEST(Hooks, CorrectionsDoNotPushParticlesIntoTheTankWalls) {
  // A correction that would carry a particle through the floor or a side wall (the contact at the plate's foot)
  // stops at the nearer of its predicted distance and dx/2; a particle that ends within one spacing of a wall
  // keeps no velocity correction into it (the wall takes that impulse), a correction along the wall or away from
  // it is kept. A correction inside the tank is applied as given.
  const FluidParams p = small_tank();
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  fluid.compute_forces();
  fluid.predict();
  const std::size_t n = fluid.owned_count();
  ASSERT_GE(n, 4u);
  std::vector<double> dx(n, 0.0), dy(n, 0.0), dvx(n, 0.0), dvy(n, 0.0), drho(n, 0.0);
  const double x0 = fluid.x()[0], y0 = fluid.y()[0], x1 = fluid.x()[1], y2 = fluid.y()[2], y3 = fluid.y()[3];
  const double vx0 = fluid.vx()[0], vy0 = fluid.vy()[0], vx1 = fluid.vx()[1], vy2 = fluid.vy()[2];
  const double vy3 = fluid.vy()[3];
  dy[0] = -(y0 + 0.01);                                          // through the floor
  const double along = x0 < 0.5 * p.tank_length ? 1e-4 : -1e-4;  // along the floor, towards the middle
  dx[0] = along;
  dvx[0] = along > 0 ? 0.3 : -0.3;  // along the floor, away from the nearer side wall
  dvy[0] = -2.0;
  dx[1] = p.tank_length - x1 + 0.01;  // through the right wall
  dvx[1] = 1.0;
  dy[2] = 1e-4;  // inside, moving up
  dvy[2] = 0.5;
  dvy[3] = -0.5;  // down: dropped only if it ends within one spacing of the floor
  fluid.apply_corrections({0, 1, 2, 3}, dx.data(), dy.data(), dvx.data(), dvy.data(), drho.data());
  EXPECT_DOUBLE_EQ(fluid.y()[0], std::min(y0, 0.5 * p.spacing));
  EXPECT_DOUBLE_EQ(fluid.x()[0], x0 + along);
  EXPECT_DOUBLE_EQ(fluid.vy()[0], vy0);
  EXPECT_DOUBLE_EQ(fluid.vx()[0], vx0 + dvx[0]);
  EXPECT_DOUBLE_EQ(fluid.x()[1], p.tank_length - std::min(p.tank_length - x1, 0.5 * p.spacing));
  EXPECT_DOUBLE_EQ(fluid.vx()[1], vx1);
  EXPECT_DOUBLE_EQ(fluid.y()[2], y2 + 1e-4);
  EXPECT_DOUBLE_EQ(fluid.vy()[2], vy2 + 0.5);
  EXPECT_DOUBLE_EQ(fluid.vy()[3], y3 < p.spacing ? vy3 : vy3 - 0.5);
  fluid.finish();
}

TEST(Hooks, ExtraAccelerationActsOnTheChosenParticle) {
  const FluidParams p = small_tank();
  Fluid a(MPI_COMM_WORLD, p, nullptr), b(MPI_COMM_WORLD, p, nullptr);
  a.compute_forces();
  b.compute_forces();
  const std::int64_t chosen = 7;
  for (std::size_t i = 0; i < b.owned_count(); ++i)
    if (b.gid()[i] == chosen) b.extra_acceleration_y()[i] = 100.0;
  const double dt = a.dt();
  a.advance();
  b.advance();
  for (std::size_t i = 0; i < a.owned_count(); ++i) {
    ASSERT_EQ(a.gid()[i], b.gid()[i]);
    const double dv = b.vy()[i] - a.vy()[i];
    if (a.gid()[i] == chosen)
      EXPECT_NEAR(dv, 100.0 * dt, 1e-12);
    else
      EXPECT_EQ(dv, 0.0);
  }
}
