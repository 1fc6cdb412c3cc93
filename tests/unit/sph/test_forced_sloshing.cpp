// Forced sloshing against linear potential theory: the paper's tank (0.30 m, 0.10 m of water) under a small
// one-cycle cosine pulse, a_g = 0.5 cos(2 pi t / 0.6) m/s^2. This checks the tank frame's body force -a_g (its size,
// sign and timing) on the water, the part of the coupled runs that every response starts from.
//
// Reference: tests/support/linear_sloshing.hpp (modal solution, 101 odd modes). The wall elevations are split
// into the part odd about the tank's centre, (eta_left - eta_right) / 2, which carries the linear (and third-order)
// response, and the even part, (eta_left + eta_right) / 2, which linear theory says is zero: it is the
// second-order set-down/set-up of the crests and troughs, of relative size k eta ~ 0.1 here. The elevation probe
// (top particle within dx of x, plus dx/2) has the same offset at both walls, so it cancels in the odd part.
// Bounds, over the pulse (0 <= t <= T, before the second-order build-up of the free oscillation that follows):
//  * odd part against linear theory: RMS at most 3 % of the linear peak and the peak within 3 % (third-order
//    terms are (k eta)^2 ~ 1 %; numerical dissipation over one period is of that order too);
//  * even part: at most 2 k eta_peak^2 (twice the second-order estimate).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "halfeti/excitation/ground_motion.hpp"
#include "halfeti/io/metrics.hpp"
#include "halfeti/sph/fluid.hpp"
#include "linear_sloshing.hpp"
#include "paper_tank.hpp"

using namespace halfeti::sph;

TEST(ForcedSloshing, WallElevationFollowsLinearTheoryUnderASmallPulse) {
  const double L = halfeti::test::kPaperTankLength, d = halfeti::test::kPaperWaterDepth, A = 0.5, T = 0.6;
  const FluidParams p = halfeti::test::paper_tank_water(0.003, A);
  const auto motion = halfeti::excitation::make_cosine_pulse(A, T, 0.0);
  Fluid fluid(MPI_COMM_WORLD, p, motion.get());
  const halfeti::test::LinearSloshing theory{L, d, p.gravity};
  const double xl = 0.5 * p.spacing, xr = L - 0.5 * p.spacing;  // the probes' columns, as the sloshing test's

  // The odd part of the two walls' elevations (the first mode's), its even part, and linear theory's odd part, at
  // every step; compared through the metrics' one home (io/metrics.hpp).
  halfeti::io::Curve odd, even, lin;
  while (fluid.time() < T) {
    fluid.step();
    const double t = fluid.time();
    const double el = fluid.free_surface_elevation(xl) - d, er = fluid.free_surface_elevation(xr) - d;
    for (auto* c : {&odd, &even, &lin}) c->t.push_back(t);
    odd.v.push_back(0.5 * (el - er));
    even.v.push_back(0.5 * (el + er));
    lin.v.push_back(
        0.5 * (theory.cosine_pulse_elevation(xl, t, A, T) - theory.cosine_pulse_elevation(xr, t, A, T)));
  }
  const double peak_lin = halfeti::io::peak(lin, {}, true).value,
               peak_sph = halfeti::io::peak(odd, {}, true).value;
  const double peak_even = halfeti::io::peak(even, {}, true).value;
  const double rms = halfeti::io::rms_error(odd, lin) / peak_lin, peak_err = (peak_sph - peak_lin) / peak_lin;
  const double k = M_PI / L, even_bound = 2.0 * k * peak_lin * peak_lin;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf(
        "forced sloshing, %ld particles, %ld steps: odd part peak %.3f mm (linear %.3f mm, %+.2f%%), RMS "
        "%.2f%% of the linear peak; even part peak %.3f mm (bound %.3f mm)\n",
        fluid.global_count(), fluid.step_count(), 1e3 * peak_sph, 1e3 * peak_lin, 100 * peak_err, 100 * rms,
        1e3 * peak_even, 1e3 * even_bound);
  EXPECT_LT(rms, 0.03);
  EXPECT_LT(std::abs(peak_err), 0.03);
  EXPECT_LT(peak_even, even_bound);
}

// The reference itself: its static response is the tilt a_g (L/2 - xi) / g of a steadily accelerated tank, its
// two branches (during and after the pulse) join at t = T, and it starts from rest.
TEST(ForcedSloshing, ReferenceHasTheStaticTiltAndJoinsItsBranches) {
  const halfeti::test::LinearSloshing theory;
  const double a = 0.5, L = theory.length;
  for (double xi : {0.0, 0.05, 0.1, 0.2, 0.3}) {
    const double tilt = a * (0.5 * L - xi) / theory.gravity;
    EXPECT_NEAR(theory.static_elevation(xi, a), tilt, 2e-3 * a * L / theory.gravity)  // truncated at n = 101
        << "xi = " << xi;
  }
  const double T = 0.6, eps = 1e-10;  // the fastest mode moves ~0.1 m/s: 1e-11 m across 2 eps
  EXPECT_NEAR(theory.cosine_pulse_elevation(0.0, 0.0, a, T), 0.0, 1e-15);
  EXPECT_NEAR(theory.cosine_pulse_elevation(0.0, T - eps, a, T),
              theory.cosine_pulse_elevation(0.0, T + eps, a, T), 1e-9);
}
