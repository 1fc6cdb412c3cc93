// The hanging plate (structure.orientation: hanging, e.g. the Antoci et al. 2007 gate) is the standing plate turned
// by 180 degrees about its clamp: the mesh, its clamped nodes, named nodes and counterclockwise outline, and the
// plate-wall ghost lattice built from that outline (src/sph/plate_wall.cpp) must be the standing plate's turned
// about the clamp, point for point, lattice offsets included (docs/coupling.md, section 14).
#include <gtest/gtest.h>

#include <cmath>

#include "halfeti/core/error.hpp"
#include "halfeti/sph/kernel.hpp"
#include "halfeti/sph/plate_wall.hpp"
#include "halfeti/structure/plate_mesh.hpp"
#include "plate_surface.hpp"

namespace hs = halfeti::structure;
namespace sph = halfeti::sph;

namespace {

const Eigen::Vector2d kClamp(0.1025, 0.080);  // the gate's clamp (inputs/validation/antoci_gate.yaml)

hs::PlateGeometry gate(hs::Orientation orientation, hs::ElementType element = hs::ElementType::kQ9) {
  hs::PlateGeometry g;
  g.base_centre = kClamp;
  g.height = 0.079;
  g.thickness = 0.005;
  g.cells_across = 2;
  g.cells_along = 40;
  g.element = element;
  g.orientation = orientation;
  return g;
}

// The outline the coupling hands to the fluid (ContactSystem::surface): the surface nodes in order.
sph::PlateOutline outline(const hs::PlateMesh& m) {
  sph::PlateOutline o;
  auto add = [&](int node) {
    o.x.push_back(m.nodes[node].x());
    o.y.push_back(m.nodes[node].y());
  };
  add(m.surface.front().first);
  for (const auto& s : m.surface) add(s.second);
  o.vx.assign(o.size(), 0.0);
  o.vy.assign(o.size(), 0.0);
  o.ax.assign(o.size(), 0.0);
  o.ay.assign(o.size(), 0.0);
  return o;
}

Eigen::Vector2d turned(const Eigen::Vector2d& p) {
  return 2.0 * kClamp - p;
}

}  // namespace

TEST(HangingPlate, MeshIsTheStandingMeshTurnedAboutTheClamp) {
  for (auto element : {hs::ElementType::kQ9, hs::ElementType::kQ4Eas}) {
    const auto standing = hs::make_plate_mesh(gate(hs::Orientation::kStanding, element));
    const auto hanging = hs::make_plate_mesh(gate(hs::Orientation::kHanging, element));
    ASSERT_EQ(hanging.nodes.size(), standing.nodes.size());
    for (std::size_t n = 0; n < standing.nodes.size(); ++n)
      EXPECT_LT((hanging.nodes[n] - turned(standing.nodes[n])).norm(), 1e-15) << n;
    // Clamped at the top: the clamped nodes are the highest, at the clamp's height, and nothing is above them.
    ASSERT_EQ(hanging.clamped_nodes, standing.clamped_nodes);
    for (int n : hanging.clamped_nodes) EXPECT_NEAR(hanging.nodes[n].y(), kClamp.y(), 1e-15);
    for (const auto& p : hanging.nodes) EXPECT_LE(p.y(), kClamp.y() + 1e-15);
    // Names in the tank's frame.
    const double half = 0.0025, bottom = kClamp.y() - 0.079;
    EXPECT_LT((hanging.nodes[hanging.node("bottom_centre")] - Eigen::Vector2d(kClamp.x(), bottom)).norm(),
              1e-15);
    EXPECT_LT(
        (hanging.nodes[hanging.node("bottom_left")] - Eigen::Vector2d(kClamp.x() - half, bottom)).norm(),
        1e-15);
    EXPECT_LT(
        (hanging.nodes[hanging.node("bottom_right")] - Eigen::Vector2d(kClamp.x() + half, bottom)).norm(),
        1e-15);
    EXPECT_LT(
        (hanging.nodes[hanging.node("clamp_left")] - Eigen::Vector2d(kClamp.x() - half, kClamp.y())).norm(),
        1e-15);
    EXPECT_LT(
        (hanging.nodes[hanging.node("clamp_right")] - Eigen::Vector2d(kClamp.x() + half, kClamp.y())).norm(),
        1e-15);
    EXPECT_THROW(hanging.node("top_right"), halfeti::UserError);  // no standing names on a hanging plate
    EXPECT_EQ(hanging.edge_sets.at("bottom").size(), standing.edge_sets.at("top").size());
    EXPECT_EQ(hanging.edge_sets.count("top"), 0u);
    for (const auto& e : hanging.edge_sets.at("left"))
      EXPECT_NEAR(hanging.nodes[e[0]].x(), kClamp.x() - half, 1e-15);
    // Elements keep a positive orientation (a half turn is a rotation).
    for (int e = 0; e < hanging.element_count(); ++e) {
      const int* en = hanging.element_nodes(e);
      const int across = element == hs::ElementType::kQ9 ? 2 : 1,
                up = element == hs::ElementType::kQ9 ? 6 : 2;
      const Eigen::Vector2d a = hanging.nodes[en[across]] - hanging.nodes[en[0]],
                            b = hanging.nodes[en[up]] - hanging.nodes[en[0]];
      EXPECT_GT(a.x() * b.y() - a.y() * b.x(), 0.0) << e;
    }
  }
  EXPECT_EQ(hs::parse_orientation("hanging"), hs::Orientation::kHanging);
  EXPECT_THROW(hs::parse_orientation("upside_down"), halfeti::UserError);
}

TEST(HangingPlate, OutlineRunsDownTheLeftFaceAcrossTheBottomAndUpTheRightFaceWithOutwardNormals) {
  const auto m = hs::make_plate_mesh(gate(hs::Orientation::kHanging));
  ASSERT_EQ(m.surface.size(), 80u + 4u + 80u);
  EXPECT_EQ(m.surface.front().first, m.node("clamp_left"));
  EXPECT_EQ(m.surface.back().second, m.node("clamp_right"));
  EXPECT_EQ(m.surface[80].first, m.node("bottom_left"));
  EXPECT_EQ(m.surface[83].second, m.node("bottom_right"));
  for (std::size_t k = 0; k < m.surface.size(); ++k) {
    const Eigen::Vector2d a = m.nodes[m.surface[k].first], b = m.nodes[m.surface[k].second];
    // The outward normal (the tangent turned clockwise, as the coupling and the plate wall take it).
    const Eigen::Vector2d t = b - a, normal = Eigen::Vector2d(t.y(), -t.x()).normalized();
    const Eigen::Vector2d expected = k < 80   ? Eigen::Vector2d(-1, 0)
                                     : k < 84 ? Eigen::Vector2d(0, -1)
                                              : Eigen::Vector2d(1, 0);
    EXPECT_LT((normal - expected).norm(), 1e-12) << k;
    EXPECT_LT(0.5 * (a + b).y(), kClamp.y());  // no segment on the clamp
  }
  EXPECT_NEAR(halfeti::test::closed_surface_area(m), 0.079 * 0.005, 1e-12);  // positive: counterclockwise
}

// The ghost lattice and the mid-line of the hanging plate are the standing plate's turned about the clamp, with the
// lattice offsets given in the plate's own frame (as read_parameters hands them: first face, last face, free end).
TEST(HangingPlate, GhostLatticeIsTheStandingOnesTurnedAboutTheClamp) {
  const double dx = 0.001;
  const sph::Kernel kernel{sph::KernelKind::kCubicSpline, 1.33 * dx, 1.0};
  for (const sph::LatticeOffsets offsets :
       {sph::LatticeOffsets{0.0, 0.0, 0.0}, sph::LatticeOffsets{0.0, 0.5e-3, 1e-3}}) {
    sph::PlateWall standing, hanging;
    standing.set_offsets(offsets);
    hanging.set_offsets(offsets);
    standing.set_outline(outline(hs::make_plate_mesh(gate(hs::Orientation::kStanding))), dx,
                         kernel.support());
    hanging.set_outline(outline(hs::make_plate_mesh(gate(hs::Orientation::kHanging))), dx, kernel.support());
    ASSERT_GT(standing.ghost_count(), 0u);
    ASSERT_EQ(hanging.ghost_count(), standing.ghost_count());
    double lowest = 1.0;
    for (int g = 0; g < static_cast<int>(standing.ghost_count()); ++g) {
      const Eigen::Vector2d s(standing.ghost_x(g), standing.ghost_y(g)),
          h(hanging.ghost_x(g), hanging.ghost_y(g));
      EXPECT_LT((h - turned(s)).norm(), 1e-14) << g;
      EXPECT_DOUBLE_EQ(hanging.ghost_volume(g), standing.ghost_volume(g)) << g;
      lowest = std::min(lowest, h.y());
    }
    const auto ms = standing.midline(), mh = hanging.midline();
    ASSERT_EQ(mh.size(), ms.size());
    for (std::size_t q = 0; q < ms.size(); ++q) {
      EXPECT_LT((Eigen::Vector2d(mh[q].xa, mh[q].ya) - turned({ms[q].xa, ms[q].ya})).norm(), 1e-14);
      EXPECT_LT((Eigen::Vector2d(mh[q].xb, mh[q].yb) - turned({ms[q].xb, ms[q].yb})).norm(), 1e-14);
    }
    // The hanging mid-line runs from the clamp down to the (offset) free end.
    EXPECT_NEAR(mh.front().ya, kClamp.y(), 1e-15);
    EXPECT_NEAR(mh.back().yb, kClamp.y() - 0.079 - offsets.top, 1e-12);
    // The lowest ghost row lies half a spacing above the free end as the lattice sees it (lowered by offsets.top).
    EXPECT_NEAR(lowest, kClamp.y() - 0.079 - offsets.top + 0.5 * dx, 1e-12);
  }
}
