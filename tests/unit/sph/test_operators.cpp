// Neighbour search against brute force, canonical order, renormalised gradient exactness and the still lattice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "halfeti/sph/delta_sph.hpp"
#include "halfeti/sph/equation_of_state.hpp"

using namespace halfeti::sph;

TEST(NeighbourSearch, MatchesBruteForceInCanonicalOrder) {
  const Kernel k{KernelKind::kCubicSpline, 0.0133};
  const auto grid = halfeti::parallel::CellGrid::covering(0, 0, 0.3, 0.2, k.support());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(0, 0.3), uy(0, 0.2);
  const int n = 800;
  std::vector<double> x(n), y(n);
  std::vector<std::int64_t> gid(n);
  for (int i = 0; i < n; ++i) {
    x[i] = ux(rng);
    y[i] = uy(rng);
    gid[i] = (i * 7919) % n;  // ids unrelated to storage order
  }
  NeighbourSearch search(grid, k);
  FluidPairList pairs;
  search.fluid_pairs(x.data(), y.data(), gid.data(), n, n, pairs);
  const KernelEvaluator eval(k);
  double closest = std::numeric_limits<double>::infinity();
  int closest_i = -1;
  for (int i = 0; i < n; ++i) {
    std::set<int> brute, found;
    for (int j = 0; j < n; ++j)
      if (j != i && std::hypot(x[j] - x[i], y[j] - y[i]) < k.support()) brute.insert(j);
    std::vector<std::pair<int, std::int64_t>> order;
    for_each_neighbour(pairs, i, [&](int j, int q) {
      found.insert(j);
      // W and F at the pair's distance (to rounding: the search evaluates them in vector registers)
      const double ex = x[j] - x[i], ey = y[j] - y[i], r = std::sqrt(ex * ex + ey * ey);
      double w, f;
      eval(r, w, f);
      EXPECT_NEAR(pairs.w[q], w, 1e-12 * std::abs(w));
      EXPECT_NEAR(pairs.f[q], f, 1e-12 * std::abs(f));
      if (r < closest) {
        closest = r;
        closest_i = i;
      }
      order.push_back({grid.cell_of(x[j], y[j]), gid[j]});
    });
    EXPECT_EQ(brute, found);
    EXPECT_TRUE(std::is_sorted(order.begin(), order.end()));  // global cell order, then global id
  }
  EXPECT_EQ(search.min_distance(), closest);  // and the first particle that has a neighbour there
  EXPECT_EQ(search.closest_particle(), closest_i);
}

TEST(NeighbourSearch, BarrierDropsCrossingPairs) {
  const Kernel k{KernelKind::kCubicSpline, 0.0133};
  const auto grid = halfeti::parallel::CellGrid::covering(0, 0, 0.1, 0.1, k.support());
  std::vector<double> x{0.045, 0.055}, y{0.05, 0.05};
  std::vector<std::int64_t> gid{0, 1};
  NeighbourSearch search(grid, k);
  FluidPairList pairs;
  search.fluid_pairs(x.data(), y.data(), gid.data(), 2, 2, pairs);
  EXPECT_EQ(pairs.size(), 2u);
  search.set_barriers(barriers_from_polyline({0.05, 0.0, 0.05, 0.04, 0.05, 0.1}));
  search.fluid_pairs(x.data(), y.data(), gid.data(), 2, 2, pairs);
  EXPECT_EQ(pairs.size(), 0u);
}

namespace {
struct Lattice {
  std::vector<double> x, y, vx, vy, rho, m, p;
  std::vector<std::int64_t> gid;
  FluidPairList pairs;
};
Lattice make_lattice(const Kernel& k, double dx, int nx, int ny, double grad_x, double grad_y) {
  Lattice l;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx, rho = 1000.0 + grad_x * x + grad_y * y;
      l.x.push_back(x);
      l.y.push_back(y);
      l.vx.push_back(0.0);
      l.vy.push_back(0.0);
      l.rho.push_back(rho);
      l.m.push_back(rho * dx * dx);
      l.p.push_back(pressure_from_density(rho, 1000.0, 10.0));
      l.gid.push_back(static_cast<std::int64_t>(l.gid.size()));
    }
  const auto grid =
      halfeti::parallel::CellGrid::covering(-0.01, -0.01, nx * dx + 0.01, ny * dx + 0.01, k.support());
  NeighbourSearch search(grid, k);
  const int n = static_cast<int>(l.x.size());
  search.fluid_pairs(l.x.data(), l.y.data(), l.gid.data(), n, n, l.pairs);
  return l;
}
}  // namespace

TEST(DensityGradient, RenormalisedGradientExactForLinearFieldEvenAtCorners) {
  const double dx = 0.005;
  const Kernel k{KernelKind::kCubicSpline, 1.33 * dx};
  auto l = make_lattice(k, dx, 12, 12, 30.0, -100.0);
  std::vector<double> vol(l.x.size());
  for (std::size_t i = 0; i < vol.size(); ++i) vol[i] = l.m[i] / l.rho[i];
  const int n = static_cast<int>(l.x.size());
  const ParticleView pv{l.x.data(), l.y.data(), l.vx.data(), l.vy.data(), l.rho.data(),
                        l.m.data(), l.p.data(), vol.data(),  n,           n};
  std::vector<double> g;
  density_gradient(pv, l.pairs, g);
  for (std::size_t i = 0; i < l.x.size(); ++i) {
    EXPECT_NEAR(g[2 * i], 30.0, 1e-8);
    EXPECT_NEAR(g[2 * i + 1], -100.0, 1e-8);
  }
  // The delta term (eqs. 3, 5) then vanishes for a linear density: hydrostatics is not diffused.
  RateConstants c{};
  c.delta = 0.1;
  c.h = k.h;
  c.c0 = 10.0;
  c.rho0 = 1000.0;
  Rates r;
  continuity_rates(pv, l.pairs, PairList::none(static_cast<int>(l.x.size())), WallGhosts{}, g, c, r);
  for (double d : r.drho) EXPECT_NEAR(d, 0.0, 1e-9);
}

TEST(FreeSurfaceMark, MarronesEigenvalueInsideOnAnEdgeAtACornerAndAlone) {
  // The moment matrix B = sum V grad W (x) r is the identity's kernel estimate: inside the water its smallest
  // eigenvalue is 1 up to the lattice's quadrature (the cubic spline at h = 1.33 dx sums its second moment within
  // a few per cent), on a straight edge half of it (the missing half-plane), alone nothing. A block's corner
  // particle sits half a spacing inside the block's outline (its own row and column are full), so it reads more
  // than the continuum's quarter-plane (0.25 - 1/(2 pi) = 0.09) but less than an edge. Marrone et al. (2010) mark
  // the free surface at 0.2: the water's own edges and corners are not marked, a particle the water has left is.
  const double dx = 0.005;
  const Kernel k{KernelKind::kCubicSpline, 1.33 * dx};
  auto l = make_lattice(k, dx, 12, 12, 0.0, 0.0);
  std::vector<double> vol(l.x.size());
  for (std::size_t i = 0; i < vol.size(); ++i) vol[i] = l.m[i] / l.rho[i];
  const int n = static_cast<int>(l.x.size());
  const ParticleView pv{l.x.data(), l.y.data(), l.vx.data(), l.vy.data(), l.rho.data(),
                        l.m.data(), l.p.data(), vol.data(),  n,           n};
  const PairList none = PairList::none(n);  // no tank walls here
  const WallGhosts no_walls;
  const double inside = moment_min_eigenvalue(pv, l.pairs, none, no_walls, 6 * 12 + 6);
  const double edge = moment_min_eigenvalue(pv, l.pairs, none, no_walls, 6 * 12 + 0);
  const double corner = moment_min_eigenvalue(pv, l.pairs, none, no_walls, 0);
  EXPECT_NEAR(inside, 1.0, 0.03);
  EXPECT_NEAR(edge, 0.5, 0.1);
  EXPECT_GT(corner, 0.25 - 1.0 / (2.0 * M_PI));
  EXPECT_LT(corner, edge - 0.1);
  EXPECT_GT(corner, kFreeSurfaceEigenvalue);
  // The tank walls' ghosts count as water (their pressure continues the particle's): a left wall's ghost rows at
  // x = -(m + 1/2) dx make the left edge an inside particle again, and the corner about an edge particle.
  WallGhosts walls;
  for (int m = 0; m < 3; ++m)
    for (int j = -3; j < 15; ++j) {
      walls.x.push_back(-(m + 0.5) * dx);
      walls.y.push_back((j + 0.5) * dx);
      walls.volume.push_back(dx * dx);
    }
  PairList ghost_pairs;
  ghost_pairs.start.push_back(0);
  const KernelEvaluator eval(k);
  for (int i = 0; i < n; ++i) {
    for (std::size_t g = 0; g < walls.size(); ++g) {
      const double ex = walls.x[g] - l.x[i], ey = walls.y[g] - l.y[i], r = std::hypot(ex, ey);
      if (r < k.support()) ghost_pairs.push(static_cast<int>(g), ex, ey, r, eval);
    }
    ghost_pairs.start.push_back(static_cast<int>(ghost_pairs.size()));
  }
  EXPECT_NEAR(moment_min_eigenvalue(pv, l.pairs, ghost_pairs, walls, 6 * 12 + 0), inside, 1e-9);
  EXPECT_NEAR(moment_min_eigenvalue(pv, l.pairs, ghost_pairs, walls, 0), edge,
              0.1);  // the ghosts reach below
  // A particle alone, and one whose only neighbour is 2.1 dx away (the separated particle of docs/coupling.md,
  // section 19): marked.
  std::vector<double> vol2{dx * dx, dx * dx};
  auto view = [&](const Lattice& m, int count) {
    return ParticleView{m.x.data(), m.y.data(), m.vx.data(), m.vy.data(), m.rho.data(),
                        m.m.data(), m.p.data(), vol2.data(), count,       count};
  };
  const auto pair = make_lattice(k, 2.1 * dx, 2, 1, 0.0, 0.0);
  EXPECT_LT(moment_min_eigenvalue(view(pair, 2), pair.pairs, PairList::none(2), no_walls, 0),
            kFreeSurfaceEigenvalue);
  const auto lone = make_lattice(k, dx, 1, 1, 0.0, 0.0);
  EXPECT_EQ(moment_min_eigenvalue(view(lone, 1), lone.pairs, PairList::none(1), no_walls, 0), 0.0);
}

TEST(DeltaSph, ArtificialViscosityDissipates) {
  // Two approaching particles: the viscous term must decelerate them (eqs. 4, 8).
  const double dx = 0.01;
  const Kernel k{KernelKind::kCubicSpline, 1.33 * dx};
  std::vector<double> x{0.0, dx}, y{0.0, 0.0}, vx{1.0, -1.0}, vy{0.0, 0.0}, rho{1000, 1000}, m{0.1, 0.1},
      p{0.0, 0.0};
  std::vector<std::int64_t> gid{0, 1};
  const auto grid = halfeti::parallel::CellGrid::covering(-0.05, -0.05, 0.05, 0.05, k.support());
  NeighbourSearch search(grid, k);
  FluidPairList pairs;
  search.fluid_pairs(x.data(), y.data(), gid.data(), 2, 2, pairs);
  std::vector<double> vol{m[0] / rho[0], m[1] / rho[1]};
  const ParticleView pv{x.data(), y.data(), vx.data(),  vy.data(), rho.data(),
                        m.data(), p.data(), vol.data(), 2,         2};
  RateConstants c{};
  c.alpha = 0.02;
  c.h = k.h;
  c.c0 = 10.0;
  c.rho0 = 1000.0;
  Rates r;
  momentum_rates(pv, pairs, PairList::none(2), WallParticles{}, PairList::none(2), WallGhosts{}, {}, c, r);
  EXPECT_LT(r.ax[0] * vx[0], 0.0);
  EXPECT_LT(r.ax[1] * vx[1], 0.0);
  EXPECT_DOUBLE_EQ(r.ax[0], -r.ax[1]);
}

TEST(Kernel, EvaluatorMatchesKernel) {
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    Kernel k{kind, 0.002};
    k.gradient_scale = 1.01;
    const KernelEvaluator eval(k);
    for (double r = 0.0001; r < k.support(); r += 0.00007) {
      double w, f;
      eval(r, w, f);
      EXPECT_NEAR(w, k.value(r), 1e-12 * k.value(0.0));
      EXPECT_NEAR(f, k.derivative(r) / r, 1e-9 * std::abs(k.derivative(k.h) / k.h));
    }
  }
}

// The pair search's vectorised loop must give exactly what one evaluation gives (the sums over pairs, and so the
// results, must not depend on how the kernel was evaluated), on both pieces, at the joint q = 1 and at r = 0.
TEST(Kernel, BatchIsBitwiseTheSingleEvaluation) {
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    Kernel k{kind, 0.002};
    k.gradient_scale = 1.01;
    const KernelEvaluator eval(k);
    std::vector<double> r2;
    for (double r = 0.0; r < k.support(); r += 0.0000313) r2.push_back(r * r);
    r2.push_back(k.h * k.h);
    r2.push_back(std::nextafter(k.h, 0.0) * std::nextafter(k.h, 0.0));
    const int n = static_cast<int>(r2.size());
    std::vector<double> w(n), f(n);
    eval.batch(r2.data(), n, w.data(), f.data());
    for (int m = 0; m < n; ++m) {
      double ws, fs;
      eval(std::sqrt(r2[m]), ws, fs);
      EXPECT_EQ(w[m], ws) << "r2 = " << r2[m];
      EXPECT_EQ(f[m], fs) << "r2 = " << r2[m];
    }
  }
}
