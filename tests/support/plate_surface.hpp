// Checks shared by the plate-mesh tests: the surface (the contact outline) is one chain of segments, and the area
// it encloses with the clamped edge (last point back to the first) is the plate's, positive when it runs
// counterclockwise.
#pragma once

#include <gtest/gtest.h>

#include "halfeti/structure/plate_mesh.hpp"

namespace halfeti::test {

// Signed area enclosed by the surface closed by the clamped edge; a gap in the chain fails the calling test.
inline double closed_surface_area(const structure::PlateMesh& m) {
  double area = 0.0;
  const auto add = [&](int from, int to) {
    const Eigen::Vector2d a = m.nodes[from], b = m.nodes[to];
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  };
  for (std::size_t k = 0; k < m.surface.size(); ++k) {
    if (k > 0) {
      EXPECT_EQ(m.surface[k].first, m.surface[k - 1].second) << "segment " << k;
    }
    add(m.surface[k].first, m.surface[k].second);
  }
  add(m.surface.back().second, m.surface.front().first);
  return area;
}

}  // namespace halfeti::test
