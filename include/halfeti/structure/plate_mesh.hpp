// Structured mesh of the plate, Q9 (default) or Q4 (the `q4_eas` element): cells across the thickness (x) times
// cells along the height (y), the clamped end's centre at a given point. A standing plate rises from its clamped
// base; a hanging one is the standing plate turned by 180 degrees about its clamp (clamped at its top, free end
// below), so the plate's own frame, node numbering and counterclockwise outline are the same for both. Nodes are numbered
// across the thickness first, so the stiffness matrix is banded with a half-bandwidth of about 2 (nodes per
// row + 1) dofs.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace halfeti::structure {

// The plate's element: nine-node Q9 with selective reduced integration (q9_element.hpp), or four-node Q4 with
// enhanced assumed strain (q4_eas_element.hpp).
enum class ElementType { kQ9, kQ4Eas };
ElementType parse_element_type(const std::string& name);  // "q9", "q4_eas"; UserError otherwise
std::string to_string(ElementType type);

// Standing: clamped at its base, free end up (the paper's plate). Hanging: clamped at its top, free end down (a
// gate, e.g. Antoci et al. 2007).
enum class Orientation { kStanding, kHanging };
Orientation parse_orientation(const std::string& name);  // "standing", "hanging"; UserError otherwise

struct PlateGeometry {
  double height = 0.08;                   // m, > 0 (paper: 8 cm)
  double thickness = 0.003;               // m, > 0 (paper: 0.3 cm)
  Eigen::Vector2d base_centre{0.0, 0.0};  // m, tank frame: the clamped end's centre (a standing plate's base)
  int cells_across = 2;                   // Q9 cells through the thickness, >= 1
  int cells_along = 60;                   // Q9 cells along the height, >= 1 (2 x 60 = the paper's 120)
  ElementType element = ElementType::kQ9;  // kQ4Eas needs an even cells_across (a node at the top centre)
  Orientation orientation = Orientation::kStanding;
};

// A straight piece of the outer surface between two consecutive surface nodes, for the contact coupling.
struct SurfaceSegment {
  int first = -1;   // node id
  int second = -1;  // node id; the outward normal is the tangent (second - first) turned clockwise
};

// An element edge for edge loads: (end, middle, end) on a Q9 mesh; (end, -1, end) on a Q4 mesh.
using QuadraticEdge = std::array<int, 3>;

struct PlateMesh {
  std::vector<Eigen::Vector2d> nodes;  // reference positions [m]
  ElementType element_type = ElementType::kQ9;
  std::vector<std::array<int, 9>> elements;  // Q9 connectivity, tensor order (see q9_element.hpp); Q9 only
  std::vector<std::array<int, 4>> quads;  // Q4 connectivity, tensor order (see q4_eas_element.hpp); Q4 only
  std::vector<int> clamped_nodes;         // the clamped end, in the plate's frame left to right
  // Names in the tank's frame. Standing: "top_left", "top_centre", "top_right" (free end), "base_left",
  // "base_centre", "base_right" (clamped). Hanging: "bottom_left", "bottom_centre", "bottom_right" (free end),
  // "clamp_left", "clamp_centre", "clamp_right".
  std::map<std::string, int> named_nodes;
  std::map<std::string, std::vector<QuadraticEdge>>
      edge_sets;  // "left", "right", "top" ("bottom" if hanging)
  // Outer surface without the clamped end, counterclockwise: from the clamp along the plate's one face, across
  // the free end, back along the other face (standing: up the right face, right to left across the top, down the
  // left face; hanging: down the left face, left to right across the bottom, up the right face). Consecutive
  // segments share a node.
  std::vector<SurfaceSegment> surface;

  int node(const std::string& name) const;  // UserError naming the known names if absent
  int element_count() const;
  int nodes_per_element() const { return element_type == ElementType::kQ9 ? 9 : 4; }
  const int* element_nodes(int e) const;  // nodes_per_element() ids
  // Linear quadrilaterals for drawing, counterclockwise: each Q9 as its four sub-quads, each Q4 as itself.
  std::vector<std::array<int, 4>> linear_cells() const;
  int cells_across = 0, cells_along = 0;
};

PlateMesh make_plate_mesh(const PlateGeometry& geometry);

}  // namespace halfeti::structure
