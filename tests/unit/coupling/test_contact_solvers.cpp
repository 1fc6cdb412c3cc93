// Direct (MUMPS) against fieldsplit Schur solves of eq. 21 at the paper's size: the 2 x 60 Q9 plate (120
// elements) with a few hundred invaders in the SSOSD layer on both faces. Prints the timings quoted in
// docs/coupling.md; checks that every variant gives the same contact forces.
#include <gtest/gtest.h>
#include <petscsys.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "coupling_fixtures.hpp"
#include "halfeti/coupling/interface_exchange.hpp"

namespace hc = halfeti::coupling;
namespace hs = halfeti::structure;

namespace {

struct Variant {
  std::string name;
  hc::ContactSolver method;
  std::vector<std::pair<std::string, std::string>> options;  // without the prefix
};

// Invaders in three columns on each face, entering the layer of L = 0.1 mm (u 0.6 m/s, dt 1.6e-5 s, ratio
// 10).
std::vector<hc::ContactInvader> paper_invaders(const hs::PlateSolver& s, double layer) {
  std::vector<hc::ContactInvader> out;
  const auto surface = hc::ContactSystem::surface(s);
  const double half = 0.5 * s.parameters().geometry.thickness;
  for (int j = 0; j < 53; ++j)
    for (int side = 0; side < 2; ++side)
      for (int col = 0; col < 3; ++col) {
        const double sign = side == 0 ? 1.0 : -1.0;
        hc::ContactInvader inv;
        inv.predicted =
            Eigen::Vector2d(sign * (half + layer * (0.2 + 0.3 * col)), 0.0015 * (j + 0.5) + 1e-4 * col);
        inv.mass = hc::testing::kParticleMass;
        const auto c = hc::closest_segment(surface, inv.predicted);
        inv.segment = c.segment;
        inv.eta = c.projection.eta;
        inv.target_gap = layer * std::exp((c.projection.gap - layer) / layer);
        out.push_back(inv);
      }
  return out;
}

}  // namespace

TEST(ContactSolvers, MumpsAgainstFieldSplitAtThePapersSize) {
  const std::vector<Variant> variants = {
      {"condensed onto the plate, its LU (default)", hc::ContactSolver::kCondensed, {}},
      {"saddle point, MUMPS LU", hc::ContactSolver::kSaddlePoint, {}},
      {"saddle point, fieldsplit Schur full, selfp; A00 LU, S gmres+lu(Sp)",
       hc::ContactSolver::kSaddlePoint,
       {{"ksp_type", "fgmres"},
        {"ksp_rtol", "1e-12"},
        {"pc_type", "fieldsplit"},
        {"pc_fieldsplit_type", "schur"},
        {"pc_fieldsplit_schur_fact_type", "full"},
        {"pc_fieldsplit_schur_precondition", "selfp"},
        {"fieldsplit_primal_ksp_type", "preonly"},
        {"fieldsplit_primal_pc_type", "lu"},
        {"fieldsplit_contact_ksp_type", "gmres"},
        {"fieldsplit_contact_ksp_rtol", "1e-12"},
        {"fieldsplit_contact_pc_type", "lu"}}},
      {"saddle point, fieldsplit Schur upper, selfp; A00 LU, S preonly lu(Sp)",
       hc::ContactSolver::kSaddlePoint,
       {{"ksp_type", "fgmres"},
        {"ksp_rtol", "1e-12"},
        {"pc_type", "fieldsplit"},
        {"pc_fieldsplit_type", "schur"},
        {"pc_fieldsplit_schur_fact_type", "upper"},
        {"pc_fieldsplit_schur_precondition", "selfp"},
        {"fieldsplit_primal_ksp_type", "preonly"},
        {"fieldsplit_primal_pc_type", "lu"},
        {"fieldsplit_contact_ksp_type", "preonly"},
        {"fieldsplit_contact_pc_type", "lu"}}},
  };
  const double dt = 1.6e-5, layer = 10 * 0.6 * dt;
  const int steps = 5;
  std::vector<Eigen::VectorXd> results;
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const std::string prefix = "bench" + std::to_string(v) + "_";
    for (const auto& [k, value] : variants[v].options)
      PetscOptionsSetValue(nullptr, ("-" + prefix + k).c_str(), value.c_str());
    hs::PlateSolver s(PETSC_COMM_SELF, hc::testing::plate(2, 60));
    hc::ContactSystem sys(s, hc::ContactConstraint::kTied, prefix, variants[v].method);
    const auto inv = paper_invaders(s, layer);
    int iterations = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int n = 0; n < steps; ++n) {
      s.begin_step(n * dt, dt);
      const auto report = sys.solve(inv, dt, (n + 1) * dt);
      iterations += report.iterations;
      if (n == 0 && std::getenv("HALFETI_DEBUG")) {
        for (std::size_t k = 0; k < report.residual_history.size(); ++k)
          std::printf(" (%.3e %.3e)", report.residual_history[k], report.gap_history[k]);
        std::printf("\n");
      }
      s.end_step();
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "  %-62s %zu invaders, %d dofs: %.2f ms/step, solve %.2f ms/iteration, assembly %.2f ms/iteration "
        "(%d Newton iterations in %d steps, setup %.2f ms/step)\n",
        variants[v].name.c_str(), inv.size(), s.dof_count(), 1e3 * total / steps,
        1e3 * sys.timers().seconds("solve") / iterations, 1e3 * sys.timers().seconds("assembly") / iterations,
        iterations, steps, 1e3 * sys.timers().seconds("setup") / steps);
    Eigen::VectorXd f(2 * inv.size());
    for (std::size_t i = 0; i < inv.size(); ++i) f.segment<2>(2 * i) = sys.forces()[i];
    results.push_back(f);  // the contact forces: the plate, pushed from both faces, hardly moves
  }
  // Plate alone for scale: its own LU (RCM) solve.
  {
    hs::PlateSolver s(PETSC_COMM_SELF, hc::testing::plate(2, 60));
    s.add_point_load(s.mesh().node("top_right"), Eigen::Vector2d(0.1, 0.0));
    const auto start = std::chrono::steady_clock::now();
    int iterations = 0;
    for (int n = 0; n < steps; ++n) iterations += s.step(n * dt, dt).newton_iterations;
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("  %-62s %.2f ms/step (%d iterations)\n", "plate alone, its own LU", 1e3 * total / steps,
                iterations);
  }
  PetscOptionsClear(nullptr);
  for (std::size_t v = 1; v < results.size(); ++v)
    EXPECT_LT((results[v] - results[0]).lpNorm<Eigen::Infinity>(),
              1e-6 * results[0].lpNorm<Eigen::Infinity>());
}

TEST(ContactSolvers, InterfaceSearchCost) {
  // The paper's tank (30 x 10 cm of water, 13,333 particles at 1.5 mm) around the plate bent by 3 cm at its
  // tip.
  hs::PlateSolver s(PETSC_COMM_SELF, hc::testing::plate(2, 60));
  hc::SurfacePolyline surface = hc::ContactSystem::surface(s);
  for (auto& p : surface.points) p.x() += 0.03 * (p.y() / 0.08) * (p.y() / 0.08);
  std::vector<std::int64_t> gid;
  std::vector<double> x, y, v, m;
  for (int j = 0; j < 66; ++j)
    for (int i = 0; i < 200; ++i) {
      gid.push_back(static_cast<std::int64_t>(gid.size()));
      x.push_back(-0.15 + 0.0015 * (i + 0.5));
      y.push_back(0.0015 * (j + 0.5));
      v.push_back(0.0);
      m.push_back(hc::testing::kParticleMass);
    }
  hc::InterfaceParticles particles{gid.size(), gid.data(), x.data(), y.data(),
                                   v.data(),   v.data(),   m.data(), nullptr};
  const double layer = 1e-4;
  std::size_t found = 0;
  const int repeats = 20;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r)
    found = hc::find_local_invaders(particles, surface, layer, 0.003, 0).size();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;
  std::printf("  search: %zu particles, %d segments, bent plate: %.3f ms per step, %zu candidates\n",
              gid.size(), surface.segment_count(), 1e3 * seconds, found);
  EXPECT_GT(found, 0u);
}
