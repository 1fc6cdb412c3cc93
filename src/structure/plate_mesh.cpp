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

PlateMesh make_plate_mesh(const PlateGeometry& geo) {
  if (!(geo.height > 0.0) || !(geo.thickness > 0.0))
    HALFETI_USER_ERROR("structure.geometry: height " << geo.height << " m and thickness " << geo.thickness
                                                     << " m must be positive");
  if (geo.cells_across < 1 || geo.cells_along < 1)
    HALFETI_USER_ERROR("structure.mesh: cells_across " << geo.cells_across << " and cells_along "
                                                       << geo.cells_along << " must be at least 1");
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
