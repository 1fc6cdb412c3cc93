// A film of water on a vertical wall, released at rest with nothing under it, must fall at g: the wall is free
// slip and at rest, and the only force it can put on the film is normal to it. The wall ghosts' pressure used to
// be continued from the film particle with the whole body force, p_g = p_i + rho_i b.(r_g - r_i) (Adami et al.
// 2012): along a vertical wall that is a vertical pressure gradient rho g behind a film whose own pressure is
// about 0, and the ghosts held up part of its weight (in the shaken tank at dx = 1.5 mm the top of the wall film
// fell at 7.8 m/s^2; docs/sph.md "Wall films"). The ghosts' pressure is now continued along the wall with the
// particle's own gradient (eqs. 6, 9), bounded by rho |b|. The old continuation is run too, to show that the test
// tells them apart. Measured: the mean vertical velocity of the film after T = 0.04 s, a =
// -<v_y>(T) / T. Internal forces cancel pair by pair (eq. 4's symmetric form), so a - g is the wall's vertical
// force on the film per unit mass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfeti/sph/fluid.hpp"

using namespace halfeti::sph;

namespace {
// Fall acceleration of a film `columns` particles thick and 20 tall against the left wall, its bottom 0.10 m above
// the floor (it falls 7.8 mm in T, so it stays clear of the floor).
double film_fall_acceleration(int columns, WallGhostPressure continuation) {
  const double dx = 0.002, T = 0.04;
  FluidParams p;
  p.tank_length = 0.10;
  p.tank_height = 0.20;
  p.spacing = dx;
  p.sound_speed = 14.0;  // the paper's tank at the automatic c0 (eq. 10 for 0.10 m of water)
  p.water = {{0.0, 0.10, columns * dx, 0.10 + 20 * dx, 0.0}};
  p.wall_ghost_pressure = continuation;
  Fluid fluid(MPI_COMM_SELF, p, nullptr);
  while (fluid.time() < T) fluid.step();
  double vy = 0.0;
  for (std::size_t i = 0; i < fluid.owned_count(); ++i) vy += fluid.vy()[i];
  vy /= static_cast<double>(fluid.owned_count());
  return -vy / fluid.time();
}
}  // namespace

// Tolerance 1% of g (0.02% measured): the film's own acoustic oscillation (it starts with the hydrostatic
// pressure of a 40 mm column and falls freely, so that pressure relaxes to 0 in a few sound-crossing times) feeds
// the along-wall gradient for part of T; the held-up weight to be removed was 8-25% (the old continuation).
TEST(WallFilm, FallsAtGravity) {
  const double g = 9.81;
  for (int columns : {1, 2, 3}) {
    const double a_new = film_fall_acceleration(columns, WallGhostPressure::kTaylor);
    const double a_old = film_fall_acceleration(columns, WallGhostPressure::kBodyForce);
    std::printf(
        "film %d particle(s) thick: falls at %.3f m/s^2 (%.2f g); with the body-force continuation %.3f "
        "m/s^2 (%.2f g)\n",
        columns, a_new, a_new / g, a_old, a_old / g);
    EXPECT_NEAR(a_new, g, 0.01 * g) << columns << " column(s)";
    EXPECT_LT(a_old, 0.95 * g) << "the old continuation should hold the film up (" << columns
                               << " column(s))";
  }
}
