// The water's load on one surface point with the interface added mass (docs/coupling.md, section 13): the load is
// handed on (extrapolated to mid-step), motion at constant velocity meets no added-mass force, an acceleration over
// the step meets minus the added mass times its normal part, and the tangent is M_a / dt^2.
#include <gtest/gtest.h>

#include "halfeti/coupling/contact_coupling.hpp"

using halfeti::coupling::SurfacePointLoad;

namespace {
constexpr double kDt = 2.5e-5;    // s, about the paper's step
constexpr double kMass = 3.0e-4;  // kg/m: 1000 kg/m^3 x 0.25 dx x 1.5 mm x a 0.8 mm share of the face

Eigen::Vector2d evaluate(SurfacePointLoad& l, const Eigen::Vector2d& x, Eigen::MatrixXd* tangent = nullptr) {
  Eigen::VectorXd f;
  Eigen::MatrixXd k;
  l.evaluate({x}, f, k);
  if (tangent) *tangent = k;
  return f;  // internal-force convention: the load enters as -f
}
}  // namespace

TEST(SurfacePointLoad, ExtrapolatesTheWatersLoadToMidStep) {
  SurfacePointLoad l(3);
  EXPECT_EQ(l.nodes(), std::vector<int>{3});
  const Eigen::Vector2d x(0.15, 0.05);
  l.start_step(Eigen::Vector2d(1.0, -2.0), x, Eigen::Matrix2d::Zero(), SurfacePointLoad::Guess::kMidStep);
  EXPECT_EQ(l.force(), Eigen::Vector2d(1.0, -2.0));  // no previous load: as computed
  l.start_step(Eigen::Vector2d(2.0, -1.0), x, Eigen::Matrix2d::Zero(), SurfacePointLoad::Guess::kMidStep);
  EXPECT_EQ(l.force(), Eigen::Vector2d(2.5, -0.5));  // 1.5 F_n - 0.5 F_n-1
  l.start_step(Eigen::Vector2d(4.0, 0.0), x, Eigen::Matrix2d::Zero(), SurfacePointLoad::Guess::kStart);
  EXPECT_EQ(l.force(), Eigen::Vector2d(4.0, 0.0));  // lagged
  l.start_step(Eigen::Vector2d(5.0, 1.0), x, Eigen::Matrix2d::Zero(), SurfacePointLoad::Guess::kStepEnd);
  EXPECT_EQ(l.force(), Eigen::Vector2d(6.0, 2.0));  // 2 F_n - F_n-1, the converged exchange's first iterate
  l.start_step(Eigen::Vector2d(4.0, 0.0), x, Eigen::Matrix2d::Zero(), SurfacePointLoad::Guess::kStart);
  l.set_time_step(kDt);
  EXPECT_EQ(evaluate(l, x + Eigen::Vector2d(1e-3, 0.0)),
            Eigen::Vector2d(-4.0, 0.0));  // no added mass: a dead load
}

TEST(SurfacePointLoad, AddedMassResistsAccelerationNormalToTheFaceOnly) {
  const Eigen::Vector2d n = Eigen::Vector2d(1.0, 0.2).normalized(), t(-n.y(), n.x());
  const Eigen::Matrix2d added = kMass * n * n.transpose();
  const Eigen::Vector2d load(0.3, -0.1), x0(0.1515, 0.04), v(0.2, -0.05);
  SurfacePointLoad l(7);
  for (int step = 0; step < 3; ++step)
    l.start_step(load, x0 + step * kDt * v, added, SurfacePointLoad::Guess::kStart);
  l.set_time_step(kDt);
  const Eigen::Vector2d x_n = x0 + 2 * kDt * v;
  // Constant velocity: the load alone (to the round-off of positions ~0.15 m over dt^2: 1e-17 m / 6e-10 s^2).
  const Eigen::Vector2d steady = evaluate(l, x_n + kDt * v) + load;
  EXPECT_LT(steady.norm(), 1e-6 * load.norm()) << steady.transpose();
  // An acceleration a over the step: internal force M_a a (the plate feels -m_a (a . n) n).
  const double a = 40.0;  // m/s^2
  Eigen::MatrixXd tangent;
  const Eigen::Vector2d normal = evaluate(l, x_n + kDt * v + kDt * kDt * a * n, &tangent) + load;
  EXPECT_NEAR((normal - kMass * a * n).norm(), 0.0, 1e-6 * kMass * a);
  const Eigen::Vector2d tangential = evaluate(l, x_n + kDt * v + kDt * kDt * a * t) + load;
  EXPECT_LT(tangential.norm(), 1e-6 * kMass * a);
  EXPECT_LT((tangent - Eigen::MatrixXd(added / (kDt * kDt))).norm(), 1e-9 * kMass / (kDt * kDt));
}

// The acoustic added mass (docs/coupling.md, section 15): with m_a = rho0 c0 dt per face area, a face whose normal
// velocity changes by dv over the step meets the water's acoustic impedance, the force -rho0 c0 A dv n (a piston's
// pressure jump rho0 c0 dv, Joukowsky), whatever the step; a tangential change meets nothing.
TEST(SurfacePointLoad, AcousticAddedMassIsTheWatersImpedance) {
  halfeti::coupling::CouplingParameters p;
  p.density = 1000.0;
  p.sound_speed = 35.0;
  const double area = 8e-4;  // m^2/m: the point's share of the face
  const Eigen::Vector2d n = Eigen::Vector2d(0.9, -0.3).normalized(), t(-n.y(), n.x());
  const Eigen::Vector2d x0(0.1515, 0.04), v(0.2, -0.05), dv_n = 0.03 * n, dv_t = 0.05 * t;
  for (double dt : {1e-5, 4e-5}) {
    EXPECT_DOUBLE_EQ(p.added_mass_per_area(dt), 1000.0 * 35.0 * dt);
    const Eigen::Matrix2d added = p.added_mass_per_area(dt) * area * n * n.transpose();
    SurfacePointLoad l(2);
    for (int step = 0; step < 2; ++step)
      l.start_step(Eigen::Vector2d::Zero(), x0 + step * dt * v, added, SurfacePointLoad::Guess::kStart);
    l.set_time_step(dt);
    const Eigen::Vector2d x_n = x0 + dt * v;
    // v_n+1/2 = v + dv: the internal-force convention gives +rho0 c0 A (dv . n) n (the plate feels minus it).
    const Eigen::Vector2d normal = evaluate(l, x_n + dt * (v + dv_n));
    const Eigen::Vector2d expected = 1000.0 * 35.0 * area * dv_n;
    EXPECT_LT((normal - expected).norm(), 1e-6 * expected.norm())
        << normal.transpose() << " / " << expected.transpose();
    EXPECT_LT(evaluate(l, x_n + dt * (v + dv_t)).norm(), 1e-6 * expected.norm());
  }
  p.added_mass_kind = halfeti::coupling::CouplingParameters::AddedMass::kNone;
  EXPECT_EQ(p.added_mass_per_area(1e-5), 0.0);
}
