// The smooth-wall law of the wall (wall_friction.hpp) and the friction it puts on the first particle layer.
#include <gtest/gtest.h>

#include <cmath>

#include "halfeti/sph/wall_friction.hpp"

using namespace halfeti::sph;

namespace {
// u from u* by the law itself (the inverse of what friction_velocity solves).
double speed_from(const LawOfTheWall& law, double us, double y, double nu, double kappa = 0.41,
                  double E = 9.8) {
  const double yp = y * us / nu;
  return us * (yp <= law.crossover() ? yp : std::log(E * yp) / kappa);
}
}  // namespace

TEST(LawOfTheWall, SublayerAndLogLawMeetAtTheCrossover) {
  const LawOfTheWall law;
  const double yc = law.crossover();
  EXPECT_NEAR(yc, std::log(9.8 * yc) / 0.41, 1e-12);
  EXPECT_GT(yc, 11.0);  // 11.53 for kappa 0.41, E 9.8
  EXPECT_LT(yc, 12.0);
}

TEST(LawOfTheWall, FrictionVelocityInvertsTheLaw) {
  const LawOfTheWall law;
  const double nu = 1e-6;
  for (double y : {1e-4, 1e-3, 5e-3})
    for (double us : {1e-4, 1e-3, 1e-2, 0.05, 0.2}) {
      const double u = speed_from(law, us, y, nu);
      EXPECT_NEAR(law.friction_velocity(u, y, nu), us, 1e-11 * us) << "y " << y << ", u* " << us;
    }
  EXPECT_EQ(law.friction_velocity(0.0, 1e-3, nu), 0.0);
  // Continuous through the crossover: u* just below and above the speed where y+ = y+_c.
  const double y = 1e-3, us_c = law.crossover() * nu / y, u_c = us_c * law.crossover();
  EXPECT_NEAR(law.friction_velocity(u_c * (1 - 1e-9), y, nu), law.friction_velocity(u_c * (1 + 1e-9), y, nu),
              1e-7 * us_c);
}

TEST(LawOfTheWall, OtherConstants) {
  const LawOfTheWall law(0.40, 9.0);
  EXPECT_NEAR(law.crossover(), std::log(9.0 * law.crossover()) / 0.40, 1e-12);
  const double u = speed_from(law, 0.03, 2e-3, 1e-6, 0.40, 9.0);
  EXPECT_NEAR(law.friction_velocity(u, 2e-3, 1e-6), 0.03, 1e-12);
}

TEST(WallFriction, OpposesTheSlipOfTheFirstLayerOnly) {
  const double dx = 0.002, nu = 1e-6;
  const TankWalls tank{0.3, 0.2, false};
  // 0: sliding along the floor at dx/2; 1: the same but moving away from the floor (no slip to oppose);
  // 2: in the bulk; 3: in the lower left corner, sliding in x and y; 4: closer than dx/2 (taken at dx/2);
  // 5: at rest on the floor; 6: sliding down the right wall.
  const double x[] = {0.1, 0.1, 0.1, 0.5 * dx, 0.2, 0.15, 0.3 - 0.5 * dx};
  const double y[] = {0.5 * dx, 0.5 * dx, 0.05, 0.5 * dx, 0.1 * dx, 0.5 * dx, 0.1};
  const double vx[] = {1.5, 0.0, 1.0, -0.5, 1.5, 0.0, 0.0};
  const double vy[] = {0.0, 0.7, 0.0, 0.3, 0.0, 0.0, -0.8};
  double ax[7] = {}, ay[7] = {};
  add_wall_friction(x, y, vx, vy, 7, tank, dx, nu, ax, ay);
  const LawOfTheWall law;
  const auto drag = [&](double u) {
    const double s = law.friction_velocity(u, 0.5 * dx, nu);
    return s * s / dx;
  };
  EXPECT_NEAR(ax[0], -drag(1.5), 1e-14);
  EXPECT_EQ(ay[0], 0.0);
  EXPECT_EQ(ax[1], 0.0);
  EXPECT_EQ(ay[1], 0.0);
  EXPECT_EQ(ax[2], 0.0);
  EXPECT_EQ(ay[2], 0.0);
  EXPECT_NEAR(ax[3], drag(0.5), 1e-14);   // the floor drags its x slip
  EXPECT_NEAR(ay[3], -drag(0.3), 1e-14);  // the left wall its y slip
  EXPECT_NEAR(ax[4], -drag(1.5), 1e-14);
  EXPECT_EQ(ax[5], 0.0);
  EXPECT_NEAR(ay[6], drag(0.8), 1e-14);
  // Size, in the additive form u+ = ln(y+) / kappa + B, B = ln(E) / kappa = 5.57: at 1.5 m/s and y = 1 mm,
  // u* = 0.0906 m/s (y+ = 90.6, u+ = 16.56), tau_w = rho u*^2 = 8.2 Pa.
  const double us = law.friction_velocity(1.5, 0.5 * dx, nu), yp = 0.5 * dx * us / nu;
  EXPECT_NEAR(1.5 / us, std::log(yp) / 0.41 + std::log(9.8) / 0.41, 1e-10);
  EXPECT_NEAR(us, 0.0906, 0.0005);
}
