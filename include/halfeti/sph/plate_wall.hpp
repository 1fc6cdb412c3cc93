// The plate's surface as a moving wall in the SPH sums (docs/coupling.md, "The plate in the SPH sums"): ghost points
// behind each face of the plate's outline stand for the water the plate and the barrier take out of a particle's
// kernel support, with the pressure continued from the particle (Adami et al. 2012, as the tank walls) and the
// velocity mirrored about the moving face (free slip). The force they exert on a particle is handed to the plate
// as the equal and opposite load on the face's surface points. Pure functions of one particle and the outline, so
// the result is independent of the rank count.
#pragma once

#include <cstdint>
#include <vector>

#include "halfeti/sph/kernel.hpp"

namespace halfeti::sph {

// The plate's outline at the start of a step: an open polyline (the contact surface, outward normal = tangent
// turned clockwise) with the velocity and acceleration of every point, in the tank's frame.
struct PlateOutline {
  std::vector<double> x, y, vx, vy, ax, ay;
  std::size_t size() const { return x.size(); }
};

// Load of one particle on one surface point (N/m), from the plate-wall term of the last force computation.
struct PlateWallLoad {
  std::int64_t gid;
  int point;
  double fx, fy;
};

struct PlateWallConstants {
  double dx = 0.0, h = 0.0, rho0 = 0.0, c0 = 0.0, alpha = 0.0;
  double body_x = 0.0, body_y = 0.0;
  bool clamp = true;  // a wall pushes, never pulls (as the tank walls)
};

class PlateWall {
 public:
  void set_outline(const PlateOutline& outline, double dx, double support);
  bool empty() const { return outline_.size() < 2; }
  // Ghost pairs of the owned particles [0, n) (positions x, y); the face a particle sees is the one of its
  // closest segment, and only its ghosts in front of which the particle stands.
  void find_pairs(const double* x, const double* y, int n, const Kernel& kernel);
  // eq. 4 pressure and viscous terms over the ghosts: adds to ax, ay (per owned particle) and records the loads.
  void momentum(const double* vx, const double* vy, const double* rho, const double* p, const double* mass,
                const std::int64_t* gid, const PlateWallConstants& k, double* ax, double* ay);
  // eq. 3 first term over the ghosts (velocity mirrored about the moving face): adds to drho.
  void continuity(const double* vx, const double* vy, const double* rho, double* drho) const;
  const std::vector<PlateWallLoad>& loads() const { return loads_; }
  std::size_t ghost_count() const { return gx_.size(); }

 private:
  PlateOutline outline_;
  double support_ = 0.0;
  // Ghosts: position, volume, normal, the segment and its parameter (for the load and the wall's motion).
  std::vector<double> gx_, gy_, gvol_, gnx_, gny_, geta_;
  std::vector<int> gseg_, face_of_segment_, ghost_face_;
  // Per particle with ghosts: its index and its pairs [start, start+count).
  std::vector<int> particle_, start_, ghost_;
  std::vector<double> ex_, ey_, f_;
  std::vector<PlateWallLoad> loads_;
};

}  // namespace halfeti::sph
