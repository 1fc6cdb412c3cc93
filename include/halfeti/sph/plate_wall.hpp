// The plate's surface as a moving wall in the SPH sums (docs/coupling.md, "The plate in the SPH sums"): ghost points
// behind each face of the plate's outline stand for the water the plate and the barrier take out of a particle's
// kernel support, with the pressure continued from the particle (Adami et al. 2012, as the tank walls) and the
// velocity mirrored about the moving face (free slip). The force they exert on a particle is handed to the plate
// as the equal and opposite load on the face's surface points. Pure functions of one particle and the outline, so
// the result is independent of the rank count.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "halfeti/sph/kernel.hpp"
#include "halfeti/sph/neighbour_list.hpp"

namespace halfeti::sph {

// The plate's outline at the start of a step: an open polyline (the contact surface, outward normal = tangent
// turned clockwise) with the velocity and acceleration of every point, in the tank's frame.
struct PlateOutline {
  std::vector<double> x, y, vx, vy, ax, ay;
  std::size_t size() const { return x.size(); }
};

// The top corners of a plate's outline: the first point, from the start (first) and from the end (second), where
// the polyline turns by more than 45 degrees; -1 where there is none.
std::pair<int, int> outline_corners(const PlateOutline& o);

// Load of one particle on one surface point (N/m), from the plate-wall term of the last force computation.
struct PlateWallLoad {
  std::int64_t gid;
  int point;
  double fx, fy;
};

// How far the water lattice's image of the plate lies outside the plate's true faces (m, outward positive; the
// simulation computes them from the initial lattice: docs/coupling.md, "The plate as the lattice sees it").
struct LatticeOffsets {
  double right = 0.0, left = 0.0, top = 0.0;
};

struct PlateWallConstants {
  double dx = 0.0, h = 0.0, rho0 = 0.0, c0 = 0.0, alpha = 0.0;
  double laminar_nu = 0.0;  // the laminar viscous term's nu (fluid_rates.cpp), over the face ghosts too
  double body_x = 0.0, body_y = 0.0;
  // The tank walls' Monaghan & Kos (1999) repulsion, on the faces as on the walls: amplitude (m/s^2) and range (m)
  double wall_amplitude = 0.0, wall_range = 0.0;
  // The tank [0, tank_length] x [0, tank_height] (the lid only with `lid`): within one spacing of a tank wall the
  // faces' repulsion does not push a particle into it
  double tank_length = 0.0, tank_height = 0.0;
  bool lid = false;
};

// Ghost lattice (docs/coupling.md, sections 12 and 17): the plate (its outline runs up the right face, across the top
// and down the left face) is cut into rows about one lattice spacing tall, measured down both faces from the top
// corners, as many on each face (so that they reach its foot however the plate bends). Each
// row holds body ghosts filling the plate's thickness and band ghosts continuing the water's lattice (m + 1/2) dx
// beyond each face. A particle uses every body ghost in its support and
// a band ghost only when the plate hides it (the segment between them crosses the plate's mid-line): the ghosts
// then stand exactly for the solid and for the water the mid-line barrier takes out of the support, on a face, on
// the top and round a corner alike.
// All in the plate's own frame: for a hanging plate (the standing one turned about its clamp, structure.orientation)
// the outline's "top" is its free end, below, and its first face the tank's left face (docs/coupling.md, section 14).
class PlateWall {
 public:
  // The offsets apply to every outline set after this call.
  void set_offsets(const LatticeOffsets& offsets) { offsets_ = offsets; }
  void set_outline(const PlateOutline& outline, double dx, double support);
  // The faces' velocities only (the true outline's points, as set_outline() takes them): the positions, ghosts and
  // pairs stay. The converged exchange sets the plate's motion over a step after the step's pairs were found.
  void set_wall_velocity(const PlateOutline& motion);
  bool empty() const { return outline_.size() < 2; }
  // The mid-line of the plate as the lattice sees it, base to top: the barrier between the two sides.
  std::vector<Barrier> midline() const;
  // The outline as the lattice sees it (offset faces), and for each of its points the true outline's point.
  const PlateOutline& outline() const { return outline_; }
  // Ghost pairs of the owned particles [0, n) (positions x, y).
  void find_pairs(const double* x, const double* y, int n, const Kernel& kernel);
  // Marks which of particles() (as find_pairs left them) stand at a free surface, the water around them gone
  // (moment_min_eigenvalue below kFreeSurfaceEigenvalue): their pressure term over the ghosts pushes and never
  // pulls, and their density does not fall as they leave the face (the gap they open is the air's), as water that
  // has separated from a face meets it at the atmosphere's pressure (docs/coupling.md, section 21). Cleared by
  // find_pairs; none marked unless called.
  void set_free_surface(std::vector<unsigned char> marks);
  std::size_t free_surface_count() const;  // how many of particles() are marked
  // eq. 4 pressure and viscous terms over the ghosts, and the walls' short-range repulsion within k.wall_range of a
  // face: adds to ax, ay (per owned particle) and records the loads (the plate takes the opposite of both).
  void momentum(const double* vx, const double* vy, const double* rho, const double* p, const double* mass,
                const std::int64_t* gid, const PlateWallConstants& k, double* ax, double* ay);
  // eq. 3 first term over the ghosts (velocity mirrored about the wall): adds to drho.
  void continuity(const double* vx, const double* vy, const double* rho, double* drho) const;
  const std::vector<PlateWallLoad>& loads() const { return loads_; }
  std::size_t ghost_count() const { return gx_.size(); }

  // Inspection (tests): the particles with ghosts after find_pairs, and each one's ghosts.
  const std::vector<int>& particles() const { return particle_; }
  std::vector<int> ghosts_of(std::size_t a) const {
    return {ghost_.begin() + start_[a], ghost_.begin() + start_[a + 1]};
  }
  double ghost_x(int g) const { return gx_[g]; }
  double ghost_y(int g) const { return gy_[g]; }
  double ghost_volume(int g) const { return gvol_[g]; }
  bool ghost_in_solid(int g) const { return gregion_[g] == kBody; }

 private:
  enum Region : int { kBody = 0, kRightBand = 1, kLeftBand = 2 };
  PlateOutline outline_;
  std::vector<int> point_;  // outline_ point -> the true outline's point (where loads go)
  LatticeOffsets offsets_;
  double support_ = 0.0;
  int corner_points_ = -1, corner_right_ = 0, corner_left_ = 0;  // the true outline's corners, found once
  int right_end_ = 0,
      left_start_ = 0;  // outline points [0, right_end_] up the right face, [left_start_, n) down the left
  int fibres_ = 0, fibre_window_ = 0, row_window_ = 0;
  double dx_ = 0.0;
  double row_height_[2] = {0.0, 0.0};  // the rows' height along the right and the left face
  std::vector<double> mid_x_, mid_y_;  // mid-line points, base to top (fibres_ + 1)
  std::vector<double> mid_box_;        // and its segments' boxes (x0, y0, x1, y1)
  std::vector<int> run_start_;         // runs of 8 outline segments [run_start_[r], run_start_[r + 1])
  std::vector<double> run_box_;        // and their boxes (x0, y0, x1, y1)
  std::array<double, 4> box_{};        // the outline's box (x0, y0, x1, y1)
  std::vector<double> arc_;  // per outline point: arc length from its face's top corner (0 on the top)
  // Ghosts, in rows of one lattice spacing from the top down: position, volume, region, the right face's segment
  // beside it; row_start_ indexes the rows.
  std::vector<double> gx_, gy_, gvol_;
  std::vector<int> gregion_, gfibre_, row_start_;
  // Per particle with ghosts: its index, its pairs [start, start+count), its wall normal, closest segment, the
  // parameter of its closest point on it (where the load goes), its distance from it and its position.
  std::vector<int> particle_, start_, ghost_, seg_;
  std::vector<double> ex_, ey_, f_, nx_, ny_, eta_, distance_, px_, py_;
  std::vector<PlateWallLoad> loads_;
  std::vector<unsigned char> free_surface_;  // per particle with ghosts, or empty

  bool hidden(double xi, double yi, double xg, double yg, int fibre) const;
  void closest_point(double xi, double yi, double reach, int& best, double& best_d, double& best_g,
                     double& best_eta) const;
  double normal_velocity(std::size_t a, const double* vx, const double* vy) const;
  bool marked(std::size_t a) const { return !free_surface_.empty() && free_surface_[a] != 0; }
  void offset_outline(const PlateOutline& o, double dx);
};

}  // namespace halfeti::sph
