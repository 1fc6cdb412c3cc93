// The saddle-point system of eq. 21 with the plate: invaders pressed against it end on the surface (or at
// their SSOSD gap), forces on particles and plate cancel, Newton converges quadratically, the plate's
// response equals the same force as a point load, and the fieldsplit solver gives the direct solver's answer.
#include <gtest/gtest.h>
#include <petscsys.h>

#include <cstdio>

#include "coupling_fixtures.hpp"
#include "halfeti/core/nodal_element.hpp"
#include "halfeti/coupling/contact_kinematics.hpp"

namespace hc = halfeti::coupling;
namespace hs = halfeti::structure;
using hc::testing::plate;

namespace {

// A linear spring from a plate node to an anchor: stands for a cable (a NodalElement entering K_eff and F).
class TipSpring final : public halfeti::NodalElement {
 public:
  TipSpring(int node, Eigen::Vector2d anchor, double stiffness)
      : node_(node), anchor_(anchor), k_(stiffness) {}
  std::vector<int> nodes() const override { return {node_}; }
  void evaluate(const std::vector<Eigen::Vector2d>& x, Eigen::VectorXd& f, Eigen::MatrixXd& k) override {
    const Eigen::Vector2d stretch = x[0] - anchor_ - Eigen::Vector2d(0.05, 0.0);  // unstretched length 5 cm
    f.resize(2);  // element by element: a fixed 2-vector assigned to a dynamic one makes GCC 12 warn falsely
    f(0) = k_ * stretch.x();
    f(1) = k_ * stretch.y();
    k = k_ * Eigen::Matrix2d::Identity();
  }

 private:
  int node_;
  Eigen::Vector2d anchor_;
  double k_;
};

std::vector<double> heights(int n, double lo, double hi) {
  std::vector<double> h;
  for (int k = 0; k < n; ++k) h.push_back(lo + (hi - lo) * (k + 0.5) / n);
  return h;
}

// Gap of each final particle position against its contact segment at the end of the step.
std::vector<double> final_gaps(const hs::PlateSolver& s, const hc::ContactSystem& sys,
                               const std::vector<hc::ContactInvader>& inv) {
  std::vector<double> g;
  for (std::size_t i = 0; i < inv.size(); ++i) {
    const auto& seg = s.mesh().surface[inv[i].segment];
    g.push_back(
        hc::project_on_segment(sys.positions()[i], s.position(seg.first), s.position(seg.second)).gap);
  }
  return g;
}

void expect_forces_cancel(const hc::ContactSystem& sys) {
  Eigen::Vector2d on_particles = Eigen::Vector2d::Zero(), on_plate = Eigen::Vector2d::Zero();
  double largest = 0.0;
  for (const auto& f : sys.forces()) on_particles += f, largest = std::max(largest, f.norm());
  for (int k = 0; k < sys.structure_forces().size() / 2; ++k)
    on_plate += sys.structure_forces().segment<2>(2 * k);
  ASSERT_GT(largest, 0.0);
  const double imbalance = (on_particles + on_plate).norm() / on_particles.norm();
  std::printf("  force balance: |sum particles + sum plate| / |sum particles| = %.2e (sum = %.4e N/m)\n",
              imbalance, on_particles.norm());
  EXPECT_LT(imbalance, 1e-13);
}

void print_history(const hc::ContactSolveReport& r) {
  std::printf("  Newton: %d iterations; ||r|| [N/m], ||c||_inf [m]:", r.iterations);
  for (std::size_t k = 0; k < r.residual_history.size(); ++k)
    std::printf(" (%.2e, %.2e)", r.residual_history[k], r.gap_history[k]);
  std::printf("\n");
}

hc::ContactSolveReport press(hs::PlateSolver& s, hc::ContactSystem& sys,
                             const std::vector<hc::ContactInvader>& inv, double dt) {
  s.begin_step(0.0, dt);
  const auto report = sys.solve(inv, dt, dt);
  s.end_step();
  return report;
}

}  // namespace

TEST(ContactSystem, InvadersEndOnTheSurfaceTied) {
  hs::PlateSolver s(PETSC_COMM_SELF, plate(2, 20));
  // The paper's mass participation 2 m / dt^2 (the default is the fluid's kick-drift m / dt^2).
  hc::ContactSystem sys(s, hc::ContactConstraint::kTied, "structure_contact_", hc::ContactSolver::kCondensed,
                        2.0);
  const auto inv = hc::testing::right_face_invaders(s, heights(12, 0.02, 0.078), 2e-4);
  const double dt = 1e-4;
  const auto report = press(s, sys, inv, dt);
  print_history(report);
  for (double g : final_gaps(s, sys, inv)) EXPECT_NEAR(g, 0.0, 1e-11);  // Newton stops at 1e-10 x height
  expect_forces_cancel(sys);
  // Pushed outwards (+x) and, tied, carried tangentially with the plate's material point.
  for (std::size_t i = 0; i < inv.size(); ++i) {
    EXPECT_GT(sys.forces()[i].x(), 0.0);
    // Constant acceleration over the step: dx = C dt^2 / (2 m).
    const Eigen::Vector2d dx = sys.positions()[i] - inv[i].predicted;
    EXPECT_NEAR((dx - sys.forces()[i] * dt * dt / (2 * inv[i].mass)).norm(), 0.0, 1e-12 * dx.norm() + 1e-18);
  }
  EXPECT_LT(s.displacement(s.mesh().node("top_right")).x(), 0.0);  // the plate gets the opposite force: -x
  // Quadratic convergence: the force residual falls faster than linearly, to round-off in a few iterations.
  ASSERT_GE(report.residual_history.size(), 3u);
  EXPECT_LE(report.iterations, 6);
}

TEST(ContactSystem, InvadersEndOnTheSurfaceNormal) {
  hs::PlateSolver s(PETSC_COMM_SELF, plate(2, 20));
  hc::ContactSystem sys(s, hc::ContactConstraint::kNormal);
  const auto inv = hc::testing::right_face_invaders(s, heights(12, 0.02, 0.078), 2e-4);
  const auto report = press(s, sys, inv, 1e-4);
  print_history(report);
  for (double g : final_gaps(s, sys, inv)) EXPECT_NEAR(g, 0.0, 1e-11);  // Newton stops at 1e-10 x height
  expect_forces_cancel(sys);
  EXPECT_LE(report.iterations, 6);
}

TEST(ContactSystem, NewtonConvergesQuadraticallyUnderLargeDeflection) {
  // A hard push (heavy invaders 2 mm deep, long step, SSOSD-like target gap) on a stubby plate: geometric
  // nonlinearity and rotating normals need several Newton iterations, and each one squares the error:
  // r_{k+1} <= C r_k^2 with one C. (On the slender 8 cm x 3 mm plate the quadratic regime starts late, with
  // or without contact: its residual is dominated by stiff membrane modes; docs/coupling.md.)
  for (auto form : {hc::ContactConstraint::kTied, hc::ContactConstraint::kNormal}) {
    auto p = plate(2, 4);
    p.geometry.height = 0.02;
    p.geometry.thickness = 0.01;
    p.newton.residual_rtol = 1e-12;  // the whole history, down to round-off
    hs::PlateSolver s(PETSC_COMM_SELF, p);
    hc::ContactSystem sys(s, form);
    auto inv = hc::testing::right_face_invaders(s, heights(8, 0.0105, 0.0185), 2e-3, 5e-4);
    for (auto& i : inv) i.mass *= 2000.0;  // a strong push
    const auto report = press(s, sys, inv, 2e-3);
    print_history(report);
    const double tip = s.displacement(s.mesh().node("top_right")).x();
    std::printf("  tip displacement %.3e m (%.0f%% of the height)\n", tip, 100 * std::abs(tip) / 0.02);
    const auto& r = report.residual_history;
    ASSERT_GE(r.size(), 5u);
    const double first_ratio = r[2] / (r[1] * r[1]);
    for (std::size_t k = 2; k + 1 < r.size(); ++k) {
      if (r[k + 1] < 1e-9 * r[1]) continue;  // round-off floor
      const double ratio = r[k + 1] / (r[k] * r[k]);
      std::printf("  r_%zu / r_%zu^2 = %.2e (first %.2e)\n", k + 1, k, ratio, first_ratio);
      EXPECT_LT(ratio, 30.0 * first_ratio);  // linear convergence would make it grow like 1 / r_k
    }
    EXPECT_LE(report.iterations, 6);
    for (double g : final_gaps(s, sys, inv)) EXPECT_NEAR(g, 5e-4, 1e-12);
    expect_forces_cancel(sys);
  }
}

TEST(ContactSystem, StaticPushEqualsThePointLoad) {
  // One particle pressed against the plate (static plate, tied contact with g* = 0): the plate's equilibrium
  // equals that of the plate with the particle's contact force applied as point loads (1 - eta) C, eta C.
  hs::PlateSolver a(PETSC_COMM_SELF, plate(2, 20));
  hc::ContactSystem sys(a, hc::ContactConstraint::kTied);
  auto inv = hc::testing::right_face_invaders(a, {0.06}, 1e-4);
  inv[0].mass = 10.0;  // kg/m: stiff enough particle to bend the plate
  a.begin_static(0.0);
  sys.solve(inv, 1e-3, 0.0);
  a.end_step();
  const Eigen::Vector2d c = sys.forces()[0];
  ASSERT_GT(c.x(), 0.0);

  hs::PlateSolver b(PETSC_COMM_SELF, plate(2, 20));
  const auto& seg = b.mesh().surface[inv[0].segment];
  b.add_point_load(seg.first, -(1.0 - inv[0].eta) * c);
  b.add_point_load(seg.second, -inv[0].eta * c);
  b.solve_static(0.0, 1);
  const double diff = (a.displacement() - b.displacement()).lpNorm<Eigen::Infinity>();
  const double scale = a.displacement().lpNorm<Eigen::Infinity>();
  std::printf(
      "  static push: C = (%.4e, %.4e) N/m, eta = %.3f, tip %.3e m, |U_contact - U_point|_inf / |U|_inf "
      "= %.2e\n",
      c.x(), c.y(), inv[0].eta, scale, diff / scale);
  EXPECT_LT(diff, 1e-8 * scale);
}

TEST(ContactSystem, CondensedMumpsAndFieldSplitGiveTheSameAnswer) {
  std::vector<Eigen::VectorXd> results;
  for (int variant = 0; variant < 3; ++variant) {
    const char* prefix = variant == 2 ? "fs_test_" : "structure_contact_";
    const auto method = variant == 0 ? hc::ContactSolver::kCondensed : hc::ContactSolver::kSaddlePoint;
    if (variant == 2) {
      PetscOptionsSetValue(nullptr, "-fs_test_ksp_type", "fgmres");
      PetscOptionsSetValue(nullptr, "-fs_test_ksp_rtol", "1e-13");
      PetscOptionsSetValue(nullptr, "-fs_test_pc_type", "fieldsplit");
      PetscOptionsSetValue(nullptr, "-fs_test_pc_fieldsplit_type", "schur");
      PetscOptionsSetValue(nullptr, "-fs_test_pc_fieldsplit_schur_fact_type", "full");
      PetscOptionsSetValue(nullptr, "-fs_test_pc_fieldsplit_schur_precondition", "selfp");
      PetscOptionsSetValue(nullptr, "-fs_test_fieldsplit_primal_ksp_type", "preonly");
      PetscOptionsSetValue(nullptr, "-fs_test_fieldsplit_primal_pc_type", "lu");
      PetscOptionsSetValue(nullptr, "-fs_test_fieldsplit_contact_ksp_type", "gmres");
      PetscOptionsSetValue(nullptr, "-fs_test_fieldsplit_contact_ksp_rtol", "1e-12");
      PetscOptionsSetValue(nullptr, "-fs_test_fieldsplit_contact_pc_type", "lu");
    }
    hs::PlateSolver s(PETSC_COMM_SELF, plate(2, 20));
    hc::ContactSystem sys(s, hc::ContactConstraint::kTied, prefix, method);
    const auto inv = hc::testing::right_face_invaders(s, heights(12, 0.02, 0.078), 2e-4);
    press(s, sys, inv, 1e-4);
    results.push_back(s.displacement());
  }
  PetscOptionsClear(nullptr);
  for (int v = 1; v < 3; ++v)
    EXPECT_LT((results[0] - results[v]).lpNorm<Eigen::Infinity>(),
              1e-9 * results[0].lpNorm<Eigen::Infinity>());
}

TEST(ContactSystem, CondensedAndSaddlePointAgreeWithACable) {
  for (auto form : {hc::ContactConstraint::kTied, hc::ContactConstraint::kNormal}) {
    std::vector<Eigen::VectorXd> plate_u;
    std::vector<std::vector<Eigen::Vector2d>> forces;
    std::vector<int> iterations;
    for (auto method : {hc::ContactSolver::kCondensed, hc::ContactSolver::kSaddlePoint}) {
      hs::PlateSolver s(PETSC_COMM_SELF, plate(2, 20));
      const int tip = s.mesh().node("top_left");
      TipSpring cable(tip, s.mesh().nodes[tip] + Eigen::Vector2d(-0.05, 0.0), 40.0);  // a cable's stand-in
      s.add_nodal_element(&cable);
      hc::ContactSystem sys(s, form, "structure_contact_", method);
      auto inv = hc::testing::right_face_invaders(s, heights(12, 0.02, 0.078), 4e-4, 1e-4);
      for (auto& i : inv) i.mass *= 50.0;
      iterations.push_back(press(s, sys, inv, 1e-3).iterations);
      plate_u.push_back(s.displacement());
      forces.push_back(sys.forces());
    }
    EXPECT_EQ(iterations[0], iterations[1]);
    const double scale = plate_u[0].lpNorm<Eigen::Infinity>();
    EXPECT_LT((plate_u[0] - plate_u[1]).lpNorm<Eigen::Infinity>(), 1e-9 * scale);
    for (std::size_t i = 0; i < forces[0].size(); ++i)
      EXPECT_LT((forces[0][i] - forces[1][i]).norm(), 1e-8 * forces[0][i].norm());
  }
}
