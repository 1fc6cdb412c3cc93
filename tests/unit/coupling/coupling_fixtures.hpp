// Shared set-ups of the coupling tests: the paper's plate (2 x 60 Q9 or coarser) and particles placed against
// it.
#pragma once

#include <cmath>
#include <vector>

#include "halfeti/coupling/contact_system.hpp"
#include "halfeti/structure/plate_solver.hpp"

namespace halfeti::coupling::testing {

inline structure::StructureParameters plate(int across, int along) {
  structure::StructureParameters p;
  p.geometry.cells_across = across;
  p.geometry.cells_along = along;
  p.gravity = Eigen::Vector2d::Zero();
  return p;
}

// Water particle of the paper: spacing 1.5 mm, rho 1000: m = rho dx^2 per unit depth.
constexpr double kSpacing = 1.5e-3;
constexpr double kParticleMass = 1000.0 * kSpacing * kSpacing;

// Invaders `depth` past the right face (x = +t/2) at the given heights, frozen against the reference surface.
inline std::vector<ContactInvader> right_face_invaders(const structure::PlateSolver& solver,
                                                       const std::vector<double>& heights, double depth,
                                                       double target_gap = 0.0) {
  const SurfacePolyline s = ContactSystem::surface(solver);
  std::vector<ContactInvader> out;
  for (double h : heights) {
    ContactInvader inv;
    inv.predicted = Eigen::Vector2d(0.5 * solver.parameters().geometry.thickness - depth, h);
    inv.mass = kParticleMass;
    const ContactPoint c = closest_segment(s, inv.predicted);
    inv.segment = c.segment;
    inv.eta = c.projection.eta;
    inv.target_gap = target_gap;
    out.push_back(inv);
  }
  return out;
}

}  // namespace halfeti::coupling::testing
