// Micro-benchmarks of the inner loops (Google Benchmark): the plate's element force and tangent (Q9 against
// Q4-EAS, through the element family interface), one cable element's evaluation (the catenary solve), and the
// water's pair search on a square lattice. Built with -DHALFETI_ENABLE_BENCHMARKS=ON:
//   build/benchmarks/halfeti_bench --benchmark_min_time=0.5
// Each prints its time per call; the pair search also its pairs per second.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "halfeti/cable/cable_element.hpp"
#include "halfeti/parallel/cell_grid.hpp"
#include "halfeti/sph/kernel.hpp"
#include "halfeti/sph/neighbour_list.hpp"
#include "halfeti/structure/element_family.hpp"

using namespace halfeti;

namespace {
template <typename Family>
void element_force_and_tangent(benchmark::State& state, structure::ElementType type) {
  structure::PlateGeometry g;  // the paper's plate: 0.08 x 0.003 m
  g.cells_across = 2;
  g.cells_along = 60;
  g.element = type;
  const structure::PlateMesh mesh = structure::make_plate_mesh(g);
  const auto material = structure::make_material(structure::MaterialModel::kNeoHookean, 1e7, 0.45);
  Family family = [&] {
    if constexpr (std::is_same_v<Family, structure::Q9Family>)
      return structure::Q9Family(*material, {structure::PlaneHypothesis::kPlaneStrain, true}, mesh, 1150.0);
    else
      return structure::Q4EasFamily(*material, {structure::PlaneHypothesis::kPlaneStrain}, mesh, 1150.0);
  }();
  typename Family::Coordinates u;
  for (int a = 0; a < Family::kNodes; ++a) u.row(a) << 1e-4 * a, -2e-5 * a;  // a bent element
  typename Family::Vector f;
  typename Family::Matrix k;
  const bool tangent = state.range(0) != 0;
  for (auto _ : state) {
    family.evaluate(3, u, tangent, tangent, f, k);
    benchmark::DoNotOptimize(f.data());
    benchmark::DoNotOptimize(k.data());
  }
  state.SetLabel(std::string(Family::kName) + (tangent ? " force + tangent" : " force"));
}

void BM_Q9Element(benchmark::State& s) {
  element_force_and_tangent<structure::Q9Family>(s, structure::ElementType::kQ9);
}
void BM_Q4EasElement(benchmark::State& s) {
  element_force_and_tangent<structure::Q4EasFamily>(s, structure::ElementType::kQ4Eas);
}
BENCHMARK(BM_Q9Element)->Arg(0)->Arg(1);
BENCHMARK(BM_Q4EasElement)->Arg(0)->Arg(1);

void BM_CableElement(benchmark::State& state) {
  // The paper's cable: 16.2 cm unstretched, EA of a 4 mm^2 section at 1.14 MPa, submerged weight; taut.
  cable::CableProperties p;
  p.unstretched_length = 0.162;
  p.axial_stiffness = 1.14e6 * 4e-6;
  p.weight_per_length = (1150.0 - 1000.0) * 4e-6 * 9.81;
  cable::CableElement element(Eigen::Vector2d(0.0, 0.01), 0, p);
  std::vector<Eigen::Vector2d> positions{Eigen::Vector2d(0.1485, 0.08)};
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  double dx = 0.0;
  for (auto _ : state) {
    positions[0].x() = 0.1485 + 1e-5 * std::sin(dx += 0.1);  // a new state each call: no warm start is exact
    element.evaluate(positions, force, tangent);
    benchmark::DoNotOptimize(force.data());
  }
}
BENCHMARK(BM_CableElement);

void BM_PairSearch(benchmark::State& state) {
  // A block of water on a square lattice, dx = 1.5 mm, h = 1.33 dx (the paper scenes' ratio), side n particles.
  const int n = static_cast<int>(state.range(0));
  const double dx = 0.0015;
  sph::Kernel kernel;
  kernel.h = 1.33 * dx;
  const parallel::CellGrid grid =
      parallel::CellGrid::covering(-dx, -dx, n * dx + dx, n * dx + dx, kernel.support());
  std::vector<double> x, y;
  std::vector<std::int64_t> gid;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> jitter(-0.05 * dx, 0.05 * dx);
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      x.push_back((ix + 0.5) * dx + jitter(rng));
      y.push_back((iy + 0.5) * dx + jitter(rng));
    }
  // In cell order, as the fluid keeps its particles.
  std::vector<int> order(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const int ca = grid.cell_of(x[a], y[a]), cb = grid.cell_of(x[b], y[b]);
    return ca != cb ? ca < cb : a < b;
  });
  std::vector<double> xs, ys;
  for (int i : order) xs.push_back(x[i]), ys.push_back(y[i]), gid.push_back(i);
  sph::NeighbourSearch search(grid, kernel);
  sph::FluidPairList pairs;
  const int count = static_cast<int>(xs.size());
  for (auto _ : state) {
    search.fluid_pairs(xs.data(), ys.data(), gid.data(), count, count, pairs);
    benchmark::DoNotOptimize(pairs.j.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.j.size());
  state.counters["pairs_per_second"] = benchmark::Counter(
      static_cast<double>(pairs.j.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["ns_per_particle"] =
      benchmark::Counter(static_cast<double>(count) * state.iterations(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PairSearch)->Arg(50)->Arg(115)->Unit(benchmark::kMicrosecond);  // 2,500 and 13,225 particles
}  // namespace

BENCHMARK_MAIN();
