// Structured Q9 mesh of the standing plate: cells across the thickness (x) times cells along the height (y),
// the base centre at a given point, the base clamped. Nodes are numbered across the thickness first, so the
// stiffness matrix is banded with a half-bandwidth of about 2 (2 nx + 2) dofs.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace halfeti::structure {

struct PlateGeometry {
  double height = 0.08;                   // m, > 0 (paper: 8 cm)
  double thickness = 0.003;               // m, > 0 (paper: 0.3 cm)
  Eigen::Vector2d base_centre{0.0, 0.0};  // m, tank frame (the scene puts it mid-tank on the floor)
  int cells_across = 2;                   // Q9 cells through the thickness, >= 1
  int cells_along = 60;                   // Q9 cells along the height, >= 1 (2 x 60 = the paper's 120)
};

// A straight piece of the outer surface between two consecutive surface nodes, for the contact coupling.
struct SurfaceSegment {
  int first = -1;   // node id
  int second = -1;  // node id; the outward normal is the tangent (second - first) turned clockwise
};

// A quadratic element edge (3 nodes: end, middle, end), for edge loads.
using QuadraticEdge = std::array<int, 3>;

struct PlateMesh {
  std::vector<Eigen::Vector2d> nodes;        // reference positions [m]
  std::vector<std::array<int, 9>> elements;  // Q9 connectivity, tensor order (see q9_element.hpp)
  std::vector<int> clamped_nodes;            // the base, left to right
  std::map<std::string, int> named_nodes;    // "top_left", "top_centre", "top_right", "base_left",
                                             // "base_centre", "base_right"
  std::map<std::string, std::vector<QuadraticEdge>> edge_sets;  // "left", "right", "top"
  // Outer surface without the clamped base, counterclockwise: up the right face, right to left across the
  // top, down the left face. Consecutive segments share a node.
  std::vector<SurfaceSegment> surface;

  int node(const std::string& name) const;  // UserError naming the known names if absent
  int cells_across = 0, cells_along = 0;
};

PlateMesh make_plate_mesh(const PlateGeometry& geometry);

}  // namespace halfeti::structure
