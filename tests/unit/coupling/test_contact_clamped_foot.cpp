// Invaders at the plate's foot: their segment ends at a clamped base node, whose rows are -1 in the contact
// assembly. PETSc skips negative indices in MatSetValues always, but in VecSetValues only when the vector has
// VEC_IGNORE_NEGATIVE_INDICES; otherwise (optimised PETSc) it adds to x[-1], before the vector's array (the
// heap corruption that aborted coupled runs in free() at teardown). The residual vectors must come out with
// nothing written outside them.
#include <gtest/gtest.h>
#include <petscsys.h>

#include <vector>

#include "coupling_fixtures.hpp"
#include "halfeti/coupling/contact_kinematics.hpp"

namespace hc = halfeti::coupling;
namespace hs = halfeti::structure;
using hc::testing::plate;

namespace {

constexpr double kDt = 1e-4;
constexpr double kSentinel = 12345.678;
constexpr int kGuard = 4;

// One invader 0.2 mm inside each face, half a segment above the base: on the first segment (from the right
// face's clamped base corner) and on the last (to the left face's).
std::vector<hc::ContactInvader> foot_invaders(const hs::PlateSolver& s) {
  const hc::SurfacePolyline surface = hc::ContactSystem::surface(s);
  const double half = 0.5 * s.parameters().geometry.thickness, h = 0.5 * surface.points[1].y();
  std::vector<hc::ContactInvader> out;
  for (const Eigen::Vector2d& x : {Eigen::Vector2d(half - 2e-4, h), Eigen::Vector2d(-half + 2e-4, h)}) {
    hc::ContactInvader inv;
    inv.predicted = x;
    inv.mass = hc::testing::kParticleMass;
    const hc::ContactPoint c = hc::closest_segment(surface, x);
    inv.segment = c.segment;
    inv.eta = c.projection.eta;
    out.push_back(inv);
  }
  return out;
}

void expect_on_the_clamped_segments(const hs::PlateSolver& s, const std::vector<hc::ContactInvader>& inv) {
  const auto& segments = s.mesh().surface;
  ASSERT_EQ(inv.size(), 2u);
  EXPECT_EQ(inv[0].segment, 0);
  EXPECT_EQ(inv[1].segment, static_cast<int>(segments.size()) - 1);
  EXPECT_TRUE(s.is_clamped(segments.front().first));
  EXPECT_TRUE(s.is_clamped(segments.back().second));
}

}  // namespace

// Condensed solve (default): the Schur updates go into the plate's own residual vector. Its array is placed
// in a buffer with guards on both sides, which must keep their values.
TEST(ContactClampedFoot, CondensedSolveWritesNothingOutsideThePlatesResidual) {
  hs::PlateSolver s(PETSC_COMM_SELF, plate(2, 10));
  hc::ContactSystem sys(s, hc::ContactConstraint::kTied, "structure_contact_", hc::ContactSolver::kCondensed);
  const auto inv = foot_invaders(s);
  expect_on_the_clamped_segments(s, inv);
  s.begin_step(0.0, kDt);
  s.assemble_newton_system();  // creates the plate's matrix and vectors
  Vec rhs = s.newton_residual();
  PetscInt n = 0;
  ASSERT_EQ(VecGetLocalSize(rhs, &n), 0);
  std::vector<double> buffer(static_cast<std::size_t>(n + 2 * kGuard), kSentinel);
  ASSERT_EQ(VecPlaceArray(rhs, buffer.data() + kGuard), 0);
  const auto report = sys.solve(inv, kDt, kDt);
  ASSERT_EQ(VecResetArray(rhs), 0);
  s.end_step();
  for (int k = 0; k < kGuard; ++k) {
    EXPECT_EQ(buffer[k], kSentinel) << "written " << kGuard - k
                                    << " before the residual's array: " << buffer[k] - kSentinel;
    EXPECT_EQ(buffer[kGuard + n + k], kSentinel) << "written " << k << " past the residual's end";
  }
  // The contact did act: the invaders were pushed out of the plate.
  EXPECT_GE(report.iterations, 1);
  EXPECT_GT(sys.forces()[0].x(), 0.0);
  EXPECT_LT(sys.forces()[1].x(), 0.0);
}

// Saddle-point solve: its own residual vector, created per solve, is checked by PETSc's debugging allocator
// (the test runs with PETSC_OPTIONS=-malloc_debug): a write before an array breaks its allocation's header.
TEST(ContactClampedFoot, SaddlePointSolveKeepsPetscsHeapIntact) {
  PetscBool debug = PETSC_FALSE;
  ASSERT_EQ(PetscMallocGetDebug(&debug, nullptr, nullptr), 0);
  ASSERT_TRUE(debug) << "run with PETSC_OPTIONS=-malloc_debug";
  hs::PlateSolver s(PETSC_COMM_SELF, plate(2, 10));
  hc::ContactSystem sys(s, hc::ContactConstraint::kTied, "structure_contact_",
                        hc::ContactSolver::kSaddlePoint);
  const auto inv = foot_invaders(s);
  expect_on_the_clamped_segments(s, inv);
  s.begin_step(0.0, kDt);
  const auto report = sys.solve(inv, kDt, kDt);
  s.end_step();
  EXPECT_EQ(PetscMallocValidate(__LINE__, PETSC_FUNCTION_NAME, __FILE__), 0);
  EXPECT_GE(report.iterations, 1);
  EXPECT_GT(sys.forces()[0].x(), 0.0);
  EXPECT_LT(sys.forces()[1].x(), 0.0);
}
