// A uniform grid of square cells over a rectangle (the tank plus a margin). Cells are the unit of distribution
// (each cell belongs to one rank) and of the neighbour search (cell size >= kernel support, so a particle's
// neighbours lie in its own and the 8 surrounding cells). Global cell index = iy * nx + ix: "global cell order".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace halfeti::parallel {

struct CellGrid {
  double x0 = 0.0, y0 = 0.0;  // lower-left corner
  double size = 1.0;          // cell edge (>= support radius)
  int nx = 1, ny = 1;

  // Covers [xmin, xmax] x [ymin, ymax] with cells no smaller than min_size.
  static CellGrid covering(double xmin, double ymin, double xmax, double ymax, double min_size) {
    CellGrid g;
    g.x0 = xmin;
    g.y0 = ymin;
    g.size = min_size;
    g.nx = std::max(1, static_cast<int>(std::ceil((xmax - xmin) / min_size)));
    g.ny = std::max(1, static_cast<int>(std::ceil((ymax - ymin) / min_size)));
    return g;
  }
  int cell_count() const { return nx * ny; }
  // Points outside the grid are clamped into the border cells (the health monitor reports them separately).
  int ix(double x) const { return std::clamp(static_cast<int>(std::floor((x - x0) / size)), 0, nx - 1); }
  int iy(double y) const { return std::clamp(static_cast<int>(std::floor((y - y0) / size)), 0, ny - 1); }
  int cell_of(double x, double y) const { return iy(y) * nx + ix(x); }
  // Calls f(j) for each of the (up to 8) cells around cell c inside the grid, row by row from below.
  template <typename F>
  void for_each_neighbour(int c, F&& f) const {
    const int cx = c % nx, cy = c / nx;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int jx = cx + dx, jy = cy + dy;
        if ((dx == 0 && dy == 0) || jx < 0 || jy < 0 || jx >= nx || jy >= ny) continue;
        f(jy * nx + jx);
      }
  }
};

}  // namespace halfeti::parallel
