// How the water's initial lattice meets the plate (docs/coupling.md, section 12): the water fills its blocks except
// where the plate stands, as the lattice resolves it. The plate's faces are rounded to the nearest lattice lines
// (ties outward, at least one column); the plate-wall ghosts stand at those lines, so that the first water row is
// half a spacing from them.
#pragma once

#include "halfeti/sph/params.hpp"
#include "halfeti/sph/plate_wall.hpp"
#include "halfeti/structure/plate_mesh.hpp"

namespace halfeti::coupling {

struct LatticeAlignment {
  sph::LatticeOffsets offsets;  // from each face (in the plate's frame) to its lattice line
  sph::Exclusion exclusion;     // the lattice points the plate takes
};

// `dx`: the lattice spacing; (x0, y0): a lattice point (the first water block's corner).
LatticeAlignment align_plate_with_lattice(const structure::PlateGeometry& plate, double dx, double x0,
                                          double y0);

}  // namespace halfeti::coupling
