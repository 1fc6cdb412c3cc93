#include "halfeti/structure/plate_mesh.hpp"

#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::structure {

int PlateMesh::node(const std::string& name) const {
  auto it = named_nodes.find(name);
  if (it == named_nodes.end()) {
    std::ostringstream known;
    for (const auto& [k, v] : named_nodes) known << " " << k;
    HALFETI_USER_ERROR("structure: no node named '" << name << "'; known names:" << known.str());
  }
  return it->second;
}

ElementType parse_element_type(const std::string& name) {
  if (name == "q9") return ElementType::kQ9;
  if (name == "q4_eas") return ElementType::kQ4Eas;
  HALFETI_USER_ERROR("structure.element: unknown element '" << name << "' (known: q9, q4_eas)");
}

std::string to_string(ElementType type) {
  return type == ElementType::kQ9 ? "q9" : "q4_eas";
}

Orientation parse_orientation(const std::string& name) {
  if (name == "standing") return Orientation::kStanding;
  if (name == "hanging") return Orientation::kHanging;
  HALFETI_USER_ERROR("structure.orientation: unknown orientation '" << name
                                                                    << "' (known: standing, hanging)");
}

int PlateMesh::element_count() const {
  return static_cast<int>(element_type == ElementType::kQ9 ? elements.size() : quads.size());
}

const int* PlateMesh::element_nodes(int e) const {
  return element_type == ElementType::kQ9 ? elements[e].data() : quads[e].data();
}

std::vector<std::array<int, 4>> PlateMesh::linear_cells() const {
  std::vector<std::array<int, 4>> out;
  if (element_type == ElementType::kQ4Eas) {
    for (const auto& q : quads) out.push_back({q[0], q[1], q[3], q[2]});
    return out;
  }
  for (const auto& e : elements)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        out.push_back({e[i + 3 * j], e[i + 1 + 3 * j], e[i + 4 + 3 * j], e[i + 3 + 3 * j]});
  return out;
}

namespace {

// The node grid both meshes share, nx x ny nodes (row by row from the clamped base), with its clamped base,
// named nodes, edge sets (edges of `per_edge` nodes: 3 for Q9, 2 for Q4 with the middle -1) and the
// counterclockwise surface: right face upwards, top leftwards, left face downwards. All in the plate's frame; a
// hanging plate maps it to the tank by the half turn about the clamp, x -> c - (x - c), which keeps the outline
// counterclockwise and swaps the names of the sides.
void lay_out_grid(const PlateGeometry& geo, int nx, int ny, int per_edge, PlateMesh& mesh) {
  auto id = [nx](int i, int j) { return i + nx * j; };
  mesh.cells_across = geo.cells_across;
  mesh.cells_along = geo.cells_along;
  mesh.nodes.resize(static_cast<std::size_t>(nx) * ny);
  const bool hanging = geo.orientation == Orientation::kHanging;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Eigen::Vector2d local(geo.thickness * (double(i) / (nx - 1) - 0.5),
                                  geo.height * double(j) / (ny - 1));
      mesh.nodes[id(i, j)] =
          hanging ? Eigen::Vector2d(geo.base_centre - local) : Eigen::Vector2d(geo.base_centre + local);
    }
  for (int i = 0; i < nx; ++i) mesh.clamped_nodes.push_back(id(i, 0));
  if (hanging)
    mesh.named_nodes = {{"clamp_left", id(nx - 1, 0)},
                        {"clamp_centre", id(nx / 2, 0)},
                        {"clamp_right", id(0, 0)},
                        {"bottom_left", id(nx - 1, ny - 1)},
                        {"bottom_centre", id(nx / 2, ny - 1)},
                        {"bottom_right", id(0, ny - 1)}};
  else
    mesh.named_nodes = {
        {"base_left", id(0, 0)},     {"base_centre", id(nx / 2, 0)},     {"base_right", id(nx - 1, 0)},
        {"top_left", id(0, ny - 1)}, {"top_centre", id(nx / 2, ny - 1)}, {"top_right", id(nx - 1, ny - 1)}};
  const int step = per_edge - 1;
  auto edge = [&](int a, int mid, int b) { return std::array<int, 3>{a, per_edge == 3 ? mid : -1, b}; };
  auto& left = mesh.edge_sets[hanging ? "right" : "left"];
  auto& right = mesh.edge_sets[hanging ? "left" : "right"];
  auto& top = mesh.edge_sets[hanging ? "bottom" : "top"];
  for (int j = 0; j + step < ny; j += step) {
    left.push_back(edge(id(0, j), id(0, j + 1), id(0, j + step)));
    right.push_back(edge(id(nx - 1, j), id(nx - 1, j + 1), id(nx - 1, j + step)));
  }
  for (int i = 0; i + step < nx; i += step)
    top.push_back(edge(id(i, ny - 1), id(i + 1, ny - 1), id(i + step, ny - 1)));
  std::vector<int> path;
  for (int j = 0; j < ny; ++j) path.push_back(id(nx - 1, j));
  for (int i = nx - 2; i >= 0; --i) path.push_back(id(i, ny - 1));
  for (int j = ny - 2; j >= 0; --j) path.push_back(id(0, j));
  for (std::size_t k = 0; k + 1 < path.size(); ++k) mesh.surface.push_back({path[k], path[k + 1]});
}

// Q4 mesh: (cells_across + 1) x (cells_along + 1) nodes.
PlateMesh make_q4_mesh(const PlateGeometry& geo) {
  if (geo.cells_across % 2 != 0)
    HALFETI_USER_ERROR("structure.cells_across = "
                       << geo.cells_across
                       << " must be even for the q4_eas element (the top and base "
                          "centres must be nodes)");
  PlateMesh mesh;
  mesh.element_type = ElementType::kQ4Eas;
  const int nx = geo.cells_across + 1, ny = geo.cells_along + 1;
  lay_out_grid(geo, nx, ny, 2, mesh);
  auto id = [nx](int i, int j) { return i + nx * j; };
  for (int ey = 0; ey < geo.cells_along; ++ey)
    for (int ex = 0; ex < geo.cells_across; ++ex)
      mesh.quads.push_back({id(ex, ey), id(ex + 1, ey), id(ex, ey + 1), id(ex + 1, ey + 1)});
  return mesh;
}

}  // namespace

PlateMesh make_plate_mesh(const PlateGeometry& geo) {
  if (!(geo.height > 0.0) || !(geo.thickness > 0.0))
    HALFETI_USER_ERROR("structure.geometry: height " << geo.height << " m and thickness " << geo.thickness
                                                     << " m must be positive");
  if (geo.cells_across < 1 || geo.cells_along < 1)
    HALFETI_USER_ERROR("structure.mesh: cells_across " << geo.cells_across << " and cells_along "
                                                       << geo.cells_along << " must be at least 1");
  if (geo.element == ElementType::kQ4Eas) return make_q4_mesh(geo);
  PlateMesh mesh;
  const int nx = 2 * geo.cells_across + 1, ny = 2 * geo.cells_along + 1;  // nodes per row / column
  lay_out_grid(geo, nx, ny, 3, mesh);
  auto id = [nx](int i, int j) { return i + nx * j; };
  for (int ey = 0; ey < geo.cells_along; ++ey)
    for (int ex = 0; ex < geo.cells_across; ++ex) {
      std::array<int, 9> e;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) e[a + 3 * b] = id(2 * ex + a, 2 * ey + b);
      mesh.elements.push_back(e);
    }
  return mesh;
}

}  // namespace halfeti::structure
