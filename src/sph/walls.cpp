#include "halfeti/sph/walls.hpp"

#include <algorithm>
#include <cmath>

namespace halfeti::sph {

namespace {
// Particles along a->b at spacing close to `db`, extended by `ext` past both ends. Weight = share of [a, b].
void add_line(WallParticles& w, double xa, double ya, double xb, double yb, double db, double ext,
              bool two_sided) {
  const double len = std::hypot(xb - xa, yb - ya);
  const int n = std::max(1, static_cast<int>(std::lround(len / db)));
  const double s = len / n;
  const double tx = (xb - xa) / len, ty = (yb - ya) / len;
  const int next = static_cast<int>(std::ceil(ext / s));
  for (int k = -next; k <= n + next; ++k) {
    w.x.push_back(xa + k * s * tx);
    w.y.push_back(ya + k * s * ty);
    w.nx.push_back(-ty);  // left of a->b is the fluid side
    w.ny.push_back(tx);
    w.weight.push_back(k < 0 || k > n ? 0.0 : (k == 0 || k == n ? 0.5 * s : s));
    w.two_sided.push_back(two_sided ? 1 : 0);
    w.spacing.push_back(s);
  }
}
}  // namespace

WallParticles build_walls(const FluidParams& p, double extension) {
  WallParticles w;
  const double db = p.spacing * p.wall_spacing_ratio, L = p.tank_length, H = p.tank_height;
  add_line(w, 0.0, 0.0, L, 0.0, db, extension, false);         // bottom, normal +y
  add_line(w, 0.0, H, 0.0, 0.0, db, extension, false);         // left, normal +x
  add_line(w, L, 0.0, L, H, db, extension, false);             // right, normal -x
  if (p.lid) add_line(w, L, H, 0.0, H, db, extension, false);  // lid, normal -y
  for (const auto& iw : p.internal_walls) add_line(w, iw.xa, iw.ya, iw.xb, iw.yb, db, 0.0, true);
  return w;
}

WallGhosts build_wall_ghosts(const FluidParams& p, double support) {
  WallGhosts g;
  const double dx = p.spacing, db = dx * p.wall_spacing_ratio, L = p.tank_length, H = p.tank_height;
  const int rows = static_cast<int>(std::ceil(support / dx - 0.5)) + 1;
  // Horizontal walls carry the ghosts past the corners too (they fill the corner quadrants); vertical walls only
  // along their length, so no quadrant is counted twice.
  auto line = [&](double xa, double ya, double xb, double yb, bool with_extension, int internal,
                  double side) {
    const double len = std::hypot(xb - xa, yb - ya);
    const int n = std::max(1, static_cast<int>(std::lround(len / db)));
    const double s = len / n, tx = (xb - xa) / len, ty = (yb - ya) / len, nx = -ty * side, ny = tx * side;
    const int next = with_extension ? static_cast<int>(std::ceil(support / s)) : 0;
    for (int k = -next; k <= n + next; ++k) {
      const double share = (with_extension || (k > 0 && k < n)) ? s : 0.5 * s;
      for (int m = 0; m < rows; ++m) {
        g.x.push_back(xa + k * s * tx - (m + 0.5) * dx * nx);
        g.y.push_back(ya + k * s * ty - (m + 0.5) * dx * ny);
        g.volume.push_back(share * dx);
        g.nx.push_back(nx);
        g.ny.push_back(ny);
        g.internal.push_back(internal);
        g.corner.push_back(
            k < 0 || k > n ? 1 : 0);  // past the end of a horizontal wall: behind the side wall too
      }
    }
  };
  line(0.0, 0.0, L, 0.0, true, -1, 1.0);
  line(0.0, H, 0.0, 0.0, false, -1, 1.0);
  line(L, 0.0, L, H, false, -1, 1.0);
  if (p.lid) line(L, H, 0.0, H, true, -1, 1.0);
  for (std::size_t w = 0; w < p.internal_walls.size(); ++w) {  // one set of ghosts for each side
    const auto& iw = p.internal_walls[w];
    line(iw.xa, iw.ya, iw.xb, iw.yb, false, static_cast<int>(w), 1.0);
    line(iw.xa, iw.ya, iw.xb, iw.yb, false, static_cast<int>(w), -1.0);
  }
  return g;
}

double monaghan_kos_repulsion(double psi, double xi, double db, double two_h, double amplitude) {
  if (psi <= 0.0 || psi >= two_h || std::abs(xi) >= db) return 0.0;
  const double q = std::max(psi / two_h, 1.0e-3);  // keep the 1/sqrt(q) barrier finite
  return amplitude * (1.0 - q) / std::sqrt(q) * 0.5 * (1.0 + std::cos(M_PI * xi / db));
}

void drop_part_into_walls(double x, double y, double band, double length, double height, bool lid, double& ux,
                          double& uy) {
  if (y < band) uy = std::max(uy, 0.0);
  if (lid && y > height - band) uy = std::min(uy, 0.0);
  if (x < band) ux = std::max(ux, 0.0);
  if (x > length - band) ux = std::min(ux, 0.0);
}

}  // namespace halfeti::sph
