#include "halfeti/coupling/lattice_alignment.hpp"

#include <algorithm>
#include <cmath>

namespace halfeti::coupling {

LatticeAlignment align_plate_with_lattice(const structure::PlateGeometry& g, double dx, double x0,
                                          double y0) {
  const double left = g.base_centre.x() - 0.5 * g.thickness, right = g.base_centre.x() + 0.5 * g.thickness;
  const double lattice_left = x0 + dx * std::ceil((left - x0) / dx - 0.5);
  const double lattice_right = std::max(x0 + dx * std::floor((right - x0) / dx + 0.5), lattice_left + dx);
  LatticeAlignment a;
  if (g.orientation == structure::Orientation::kStanding) {
    const double top = g.base_centre.y() + g.height;
    const double lattice_top = y0 + dx * std::floor((top - y0) / dx + 0.5);
    a.offsets = {lattice_right - right, left - lattice_left, lattice_top - top};
    a.exclusion = {lattice_left, g.base_centre.y() - dx, lattice_right, lattice_top};
  } else {
    // Hanging (the standing plate turned about its clamp): the free end is the bottom, rounded down on a tie; the
    // offsets are in the plate's frame, whose "right" face (the outline's first) is the tank's left face.
    const double bottom = g.base_centre.y() - g.height;
    const double lattice_bottom = y0 + dx * std::ceil((bottom - y0) / dx - 0.5);
    a.offsets = {left - lattice_left, lattice_right - right, bottom - lattice_bottom};
    a.exclusion = {lattice_left, lattice_bottom, lattice_right, g.base_centre.y() + dx};
  }
  return a;
}

}  // namespace halfeti::coupling
