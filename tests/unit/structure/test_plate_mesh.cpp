// The structured plate mesh: sizes, named nodes, clamped base, edge sets and the ordered outer surface that
// the contact coupling walks.
#include <gtest/gtest.h>

#include <set>

#include "halfeti/core/error.hpp"
#include "halfeti/structure/plate_mesh.hpp"
#include "plate_surface.hpp"

namespace hs = halfeti::structure;

namespace {

hs::PlateGeometry geometry(int across, int along) {
  hs::PlateGeometry g;
  g.cells_across = across;
  g.cells_along = along;
  g.base_centre = Eigen::Vector2d(0.15, 0.01);
  return g;
}

TEST(PlateMesh, SizesAndNamedNodes) {
  const auto g = geometry(2, 60);
  const auto m = hs::make_plate_mesh(g);
  EXPECT_EQ(m.elements.size(), 120u);
  EXPECT_EQ(m.nodes.size(), 5u * 121u);
  EXPECT_EQ(m.clamped_nodes.size(), 5u);
  for (int n : m.clamped_nodes) EXPECT_NEAR(m.nodes[n].y(), 0.01, 1e-15);
  const double top = 0.01 + g.height, half = 0.5 * g.thickness;
  EXPECT_TRUE(m.nodes[m.node("top_left")].isApprox(Eigen::Vector2d(0.15 - half, top)));
  EXPECT_TRUE(m.nodes[m.node("top_right")].isApprox(Eigen::Vector2d(0.15 + half, top)));
  EXPECT_TRUE(m.nodes[m.node("top_centre")].isApprox(Eigen::Vector2d(0.15, top)));
  EXPECT_TRUE(m.nodes[m.node("base_centre")].isApprox(Eigen::Vector2d(0.15, 0.01)));
  EXPECT_THROW(m.node("tip"), halfeti::UserError);
  EXPECT_THROW(hs::make_plate_mesh(geometry(0, 4)), halfeti::UserError);
}

TEST(PlateMesh, ElementsAreCounterclockwiseTensorOrder) {
  const auto m = hs::make_plate_mesh(geometry(1, 3));
  for (const auto& e : m.elements) {
    const Eigen::Vector2d dx = m.nodes[e[2]] - m.nodes[e[0]], dy = m.nodes[e[6]] - m.nodes[e[0]];
    EXPECT_GT(dx.x() * dy.y() - dx.y() * dy.x(), 0.0);
    EXPECT_TRUE(m.nodes[e[4]].isApprox(0.5 * (m.nodes[e[0]] + m.nodes[e[8]])));  // centre node
  }
}

TEST(PlateMesh, SurfaceIsAContinuousCounterclockwiseChainWithoutTheBase) {
  const auto g = geometry(2, 10);
  const auto m = hs::make_plate_mesh(g);
  // 2 x 10 cells: 21 nodes per side, 5 across: (20 + 4 + 20) segments.
  ASSERT_EQ(m.surface.size(), 44u);
  EXPECT_EQ(m.surface.front().first, m.node("base_right"));
  EXPECT_EQ(m.surface.back().second, m.node("base_left"));
  double length = 0.0, signed_area = 0.0;
  const Eigen::Vector2d centre(0.15, 0.01 + 0.5 * g.height);
  for (std::size_t k = 0; k < m.surface.size(); ++k) {
    const auto& s = m.surface[k];
    if (k > 0) {
      EXPECT_EQ(s.first, m.surface[k - 1].second);
    }
    const Eigen::Vector2d a = m.nodes[s.first], b = m.nodes[s.second];
    length += (b - a).norm();
    signed_area += 0.5 * (a.x() * b.y() - b.x() * a.y());
    // Outward normal: tangent turned clockwise points away from the plate's centre line.
    const Eigen::Vector2d t = b - a, normal(t.y(), -t.x()), mid = 0.5 * (a + b);
    EXPECT_GT(normal.dot(mid - Eigen::Vector2d(centre.x(), mid.y())) + normal.dot(mid - centre) * 1e-3, 0.0);
    EXPECT_GT(mid.y(), 0.01);  // no base segment
  }
  EXPECT_NEAR(length, 2 * g.height + g.thickness, 1e-12);
  // Closing the chain along the base gives the plate's area, positive: counterclockwise.
  const Eigen::Vector2d a = m.nodes[m.node("base_left")], b = m.nodes[m.node("base_right")];
  signed_area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  EXPECT_NEAR(signed_area, g.height * g.thickness, 1e-12);
}

// The Q4 mesh (element q4_eas): the same named nodes, base and counterclockwise surface as the Q9 mesh of the
// same cells, with (cells + 1) nodes per line; 2-node edges; tensor-order quads; an odd count across is refused.
TEST(PlateMesh, Q4MeshHasTheSameNamedNodesBaseAndSurface) {
  auto g = geometry(2, 10);
  g.element = hs::ElementType::kQ4Eas;
  const auto m = hs::make_plate_mesh(g);
  EXPECT_TRUE(m.elements.empty());
  EXPECT_EQ(m.element_count(), 20);
  EXPECT_EQ(m.nodes_per_element(), 4);
  EXPECT_EQ(m.nodes.size(), 3u * 11u);
  EXPECT_EQ(m.clamped_nodes.size(), 3u);
  auto g9 = geometry(2, 10);
  const auto m9 = hs::make_plate_mesh(g9);
  for (const auto& [name, id] : m9.named_nodes)
    EXPECT_TRUE(m.nodes[m.node(name)].isApprox(m9.nodes[id])) << name;
  for (const auto& q : m.quads) {
    const Eigen::Vector2d dx = m.nodes[q[1]] - m.nodes[q[0]], dy = m.nodes[q[2]] - m.nodes[q[0]];
    EXPECT_GT(dx.x() * dy.y() - dx.y() * dy.x(), 0.0);
    EXPECT_TRUE((m.nodes[q[3]] - m.nodes[q[0]]).isApprox(dx + dy));
  }
  ASSERT_EQ(m.surface.size(), 22u);  // 10 + 2 + 10
  EXPECT_EQ(m.surface.front().first, m.node("base_right"));
  EXPECT_EQ(m.surface.back().second, m.node("base_left"));
  for (const auto& [first, second] : m.surface) EXPECT_GT(0.5 * (m.nodes[first] + m.nodes[second]).y(), 0.01);
  EXPECT_NEAR(halfeti::test::closed_surface_area(m), g.height * g.thickness, 1e-12);
  EXPECT_EQ(m.edge_sets.at("top").size(), 2u);
  EXPECT_EQ(m.edge_sets.at("left").size(), 10u);
  for (const auto& e : m.edge_sets.at("top")) EXPECT_EQ(e[1], -1);
  EXPECT_EQ(m.linear_cells().size(), 20u);
  EXPECT_EQ(m9.linear_cells().size(), 80u);
  auto odd = geometry(1, 10);
  odd.element = hs::ElementType::kQ4Eas;
  EXPECT_THROW(hs::make_plate_mesh(odd), halfeti::UserError);
  EXPECT_THROW(hs::parse_element_type("q8"), halfeti::UserError);
  EXPECT_EQ(hs::parse_element_type("q4_eas"), hs::ElementType::kQ4Eas);
}

TEST(PlateMesh, EdgeSetsCoverTheirFaces) {
  const auto g = geometry(2, 10);
  const auto m = hs::make_plate_mesh(g);
  EXPECT_EQ(m.edge_sets.at("top").size(), 2u);
  EXPECT_EQ(m.edge_sets.at("left").size(), 10u);
  EXPECT_EQ(m.edge_sets.at("right").size(), 10u);
  double top_length = 0.0;
  for (const auto& e : m.edge_sets.at("top")) top_length += (m.nodes[e[2]] - m.nodes[e[0]]).norm();
  EXPECT_NEAR(top_length, g.thickness, 1e-15);
}

}  // namespace
