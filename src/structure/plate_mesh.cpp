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
      for (int i = 0; i < 2; ++i) out.push_back({e[i + 3 * j], e[i + 1 + 3 * j], e[i + 4 + 3 * j], e[i + 3 + 3 * j]});
  return out;
}

namespace {

// Q4 mesh: (cells_across + 1) x (cells_along + 1) nodes, the same named nodes, base, edges (2-node, middle -1)
// and counterclockwise surface as the Q9 mesh.
PlateMesh make_q4_mesh(const PlateGeometry& geo) {
  if (geo.cells_across % 2 != 0)
    HALFETI_USER_ERROR("structure.cells_across = " << geo.cells_across
                                                   << " must be even for the q4_eas element (the top and base "
                                                      "centres must be nodes)");
  PlateMesh mesh;
  mesh.element_type = ElementType::kQ4Eas;
  mesh.cells_across = geo.cells_across;
  mesh.cells_along = geo.cells_along;
  const int nx = geo.cells_across + 1, ny = geo.cells_along + 1;
  auto id = [nx](int i, int j) { return i + nx * j; };
  mesh.nodes.resize(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      mesh.nodes[id(i, j)] = geo.base_centre + Eigen::Vector2d(geo.thickness * (double(i) / (nx - 1) - 0.5),
                                                               geo.height * double(j) / (ny - 1));
  for (int ey = 0; ey < geo.cells_along; ++ey)
    for (int ex = 0; ex < geo.cells_across; ++ex)
      mesh.quads.push_back({id(ex, ey), id(ex + 1, ey), id(ex, ey + 1), id(ex + 1, ey + 1)});
  for (int i = 0; i < nx; ++i) mesh.clamped_nodes.push_back(id(i, 0));
  mesh.named_nodes = {
      {"base_left", id(0, 0)},     {"base_centre", id(nx / 2, 0)},     {"base_right", id(nx - 1, 0)},
      {"top_left", id(0, ny - 1)}, {"top_centre", id(nx / 2, ny - 1)}, {"top_right", id(nx - 1, ny - 1)}};
  auto& left = mesh.edge_sets["left"];
  auto& right = mesh.edge_sets["right"];
  auto& top = mesh.edge_sets["top"];
  for (int j = 0; j + 1 < ny; ++j) {
    left.push_back({id(0, j), -1, id(0, j + 1)});
    right.push_back({id(nx - 1, j), -1, id(nx - 1, j + 1)});
  }
  for (int i = 0; i + 1 < nx; ++i) top.push_back({id(i, ny - 1), -1, id(i + 1, ny - 1)});
  std::vector<int> path;
  for (int j = 0; j < ny; ++j) path.push_back(id(nx - 1, j));
  for (int i = nx - 2; i >= 0; --i) path.push_back(id(i, ny - 1));
  for (int j = ny - 2; j >= 0; --j) path.push_back(id(0, j));
  for (std::size_t k = 0; k + 1 < path.size(); ++k) mesh.surface.push_back({path[k], path[k + 1]});
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
  mesh.cells_across = geo.cells_across;
  mesh.cells_along = geo.cells_along;
  const int nx = 2 * geo.cells_across + 1, ny = 2 * geo.cells_along + 1;  // nodes per row / column
  auto id = [nx](int i, int j) { return i + nx * j; };
  mesh.nodes.resize(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      mesh.nodes[id(i, j)] = geo.base_centre + Eigen::Vector2d(geo.thickness * (double(i) / (nx - 1) - 0.5),
                                                               geo.height * double(j) / (ny - 1));
  for (int ey = 0; ey < geo.cells_along; ++ey)
    for (int ex = 0; ex < geo.cells_across; ++ex) {
      std::array<int, 9> e;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) e[a + 3 * b] = id(2 * ex + a, 2 * ey + b);
      mesh.elements.push_back(e);
    }
  for (int i = 0; i < nx; ++i) mesh.clamped_nodes.push_back(id(i, 0));
  mesh.named_nodes = {
      {"base_left", id(0, 0)},     {"base_centre", id(nx / 2, 0)},     {"base_right", id(nx - 1, 0)},
      {"top_left", id(0, ny - 1)}, {"top_centre", id(nx / 2, ny - 1)}, {"top_right", id(nx - 1, ny - 1)}};

  auto& left = mesh.edge_sets["left"];
  auto& right = mesh.edge_sets["right"];
  auto& top = mesh.edge_sets["top"];
  for (int j = 0; j + 2 < ny; j += 2) {
    left.push_back({id(0, j), id(0, j + 1), id(0, j + 2)});
    right.push_back({id(nx - 1, j), id(nx - 1, j + 1), id(nx - 1, j + 2)});
  }
  for (int i = 0; i + 2 < nx; i += 2) top.push_back({id(i, ny - 1), id(i + 1, ny - 1), id(i + 2, ny - 1)});

  // Counterclockwise surface: right face upwards, top leftwards, left face downwards.
  std::vector<int> path;
  for (int j = 0; j < ny; ++j) path.push_back(id(nx - 1, j));
  for (int i = nx - 2; i >= 0; --i) path.push_back(id(i, ny - 1));
  for (int j = ny - 2; j >= 0; --j) path.push_back(id(0, j));
  for (std::size_t k = 0; k + 1 < path.size(); ++k) mesh.surface.push_back({path[k], path[k + 1]});
  return mesh;
}

}  // namespace halfeti::structure
