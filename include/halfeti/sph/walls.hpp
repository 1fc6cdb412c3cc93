// Tank walls and rigid internal walls as lines of boundary particles with normals, fixed in the tank's frame
// (Monaghan & Kos 1999). Each particle carries a quadrature weight (its share of the wall line inside the tank)
// for the wall-pressure term.
#pragma once

#include <vector>

#include "halfeti/sph/params.hpp"

namespace halfeti::sph {

struct WallParticles {
  std::vector<double> x, y, nx, ny;  // position and unit normal pointing into the fluid
  std::vector<double> weight;        // length of wall it stands for, 0 on extensions past the corners
  std::vector<char> two_sided;       // internal walls push on both sides
  std::vector<double> spacing;       // boundary particle spacing of its line (Delta b)
  std::size_t size() const { return x.size(); }
};

// Virtual points behind the tank walls (a few rows at (m + 1/2) dx behind each wall particle, volume = the wall
// particle's share times dx) on which the wall's pressure acts: they stand for the fluid the truncated kernel
// misses: pressure continued hydrostatically (Adami et al. 2012) and velocity mirrored (free slip), so that still
// water is in equilibrium next to a wall and a particle leaving a wall expands. They carry no state.
struct WallGhosts {
  std::vector<double> x, y, volume;
  std::vector<double> nx, ny;  // normal of their wall (into the fluid)
  std::vector<int> internal;   // index of the internal wall they stand behind, -1 for the tank walls
  std::vector<char>
      corner;  // 1 in a corner quadrant (behind two tank walls): both directions are wall normals
  std::size_t size() const { return x.size(); }
};

// Ghost rows behind the tank walls and on both sides of the internal walls; depth = the kernel support.
WallGhosts build_wall_ghosts(const FluidParams& p, double support);

// Builds the tank walls (x = 0, x = L, y = 0, lid y = H if asked) and the internal walls. Tank walls extend
// `extension` past the corners so that the repulsion stays a partition of unity there.
WallParticles build_walls(const FluidParams& p, double extension);

// Monaghan & Kos (1999) repulsion magnitude per unit mass at normal distance psi and tangential offset xi from a
// boundary particle of spacing db: A (1 - q) / sqrt(q) * P(xi), q = psi / 2h, P(xi) = (1 + cos(pi xi / db)) / 2.
double monaghan_kos_repulsion(double psi, double xi, double db, double two_h, double amplitude);

// The part of a vector at (x, y) (a force or a velocity change) that points into a wall of the tank [0, length] x
// [0, height] (the lid only with `lid`) within `band` of that wall, removed: the rigid wall takes it. Used for the
// contact's corrections and the plate faces' repulsion.
void drop_part_into_walls(double x, double y, double band, double length, double height, bool lid, double& ux,
                          double& uy);

}  // namespace halfeti::sph
