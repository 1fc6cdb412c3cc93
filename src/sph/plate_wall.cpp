// The plate's surface as a moving wall in the SPH sums (docs/coupling.md, "The plate in the SPH sums").
#include "halfeti/sph/plate_wall.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace halfeti::sph {

void PlateWall::set_outline(const PlateOutline& o, double dx, double support) {
  outline_ = o;
  support_ = support;
  gx_.clear(); gy_.clear(); gvol_.clear(); gnx_.clear(); gny_.clear(); geta_.clear();
  gseg_.clear(); face_of_segment_.clear(); ghost_face_.clear();
  const int ns = static_cast<int>(o.size()) - 1;
  if (ns < 1) return;
  // Faces: runs of segments without a corner (a turn of more than 45 degrees starts a new face).
  int face = 0;
  double tx0 = 0.0, ty0 = 0.0;
  for (int s = 0; s < ns; ++s) {
    const double dxs = o.x[s + 1] - o.x[s], dys = o.y[s + 1] - o.y[s], l = std::hypot(dxs, dys);
    const double tx = dxs / l, ty = dys / l;
    if (s > 0 && tx * tx0 + ty * ty0 < std::sqrt(0.5)) ++face;
    face_of_segment_.push_back(face);
    tx0 = tx;
    ty0 = ty;
  }
  // Rows at (m + 1/2) dx behind the face, as the tank walls' ghosts; points every dx/2 along it.
  const int rows = static_cast<int>(std::ceil(support / dx - 0.5)) + 1;
  for (int s = 0; s < ns; ++s) {
    const double dxs = o.x[s + 1] - o.x[s], dys = o.y[s + 1] - o.y[s], l = std::hypot(dxs, dys);
    const double tx = dxs / l, ty = dys / l, nx = ty, ny = -tx;  // outward normal: tangent turned clockwise
    const int nsub = std::max(1, static_cast<int>(std::lround(l / (0.5 * dx))));
    for (int k = 0; k < nsub; ++k) {
      const double eta = (k + 0.5) / nsub;
      for (int m = 0; m < rows; ++m) {
        gx_.push_back(o.x[s] + eta * dxs - (m + 0.5) * dx * nx);
        gy_.push_back(o.y[s] + eta * dys - (m + 0.5) * dx * ny);
        gvol_.push_back(l / nsub * dx);
        gnx_.push_back(nx);
        gny_.push_back(ny);
        geta_.push_back(eta);
        gseg_.push_back(s);
        ghost_face_.push_back(face_of_segment_[s]);
      }
    }
  }
}

void PlateWall::find_pairs(const double* x, const double* y, int n, const Kernel& kernel) {
  particle_.clear(); start_.clear(); ghost_.clear(); ex_.clear(); ey_.clear(); f_.clear();
  start_.push_back(0);
  if (empty()) return;
  const auto& o = outline_;
  const int ns = static_cast<int>(o.size()) - 1;
  double x0 = o.x[0], x1 = o.x[0], y0 = o.y[0], y1 = o.y[0];
  for (std::size_t k = 0; k < gx_.size(); ++k) {
    x0 = std::min(x0, gx_[k]); x1 = std::max(x1, gx_[k]);
    y0 = std::min(y0, gy_[k]); y1 = std::max(y1, gy_[k]);
  }
  for (std::size_t k = 0; k < o.size(); ++k) {
    x0 = std::min(x0, o.x[k]); x1 = std::max(x1, o.x[k]);
    y0 = std::min(y0, o.y[k]); y1 = std::max(y1, o.y[k]);
  }
  const double r = support_, r2max = r * r;
  const KernelEvaluator ke(kernel);
  for (int i = 0; i < n; ++i) {
    const double xi = x[i], yi = y[i];
    if (xi < x0 - r || xi > x1 + r || yi < y0 - r || yi > y1 + r) continue;
    // Closest segment (eq. 20's projection, clamped for the distance); at a convex corner the tie goes to the
    // face the particle stands more clearly in front of (as the contact search).
    int best = -1;
    double best_d = std::numeric_limits<double>::max(), best_g = 0.0;
    for (int s = 0; s < ns; ++s) {
      const double dxs = o.x[s + 1] - o.x[s], dys = o.y[s + 1] - o.y[s], l2 = dxs * dxs + dys * dys;
      const double rx = xi - o.x[s], ry = yi - o.y[s];
      const double eta = std::clamp((rx * dxs + ry * dys) / l2, 0.0, 1.0);
      const double d = std::hypot(rx - eta * dxs, ry - eta * dys);
      const double g = (rx * dys - ry * dxs) / std::sqrt(l2);
      if (d < best_d || (d == best_d && g > best_g)) {
        best = s;
        best_d = d;
        best_g = g;
      }
    }
    if (best < 0 || best_d >= r || best_g <= 0.0) continue;
    const int face = face_of_segment_[best];
    const std::size_t before = ghost_.size();
    for (std::size_t g = 0; g < gx_.size(); ++g) {
      if (ghost_face_[g] != face) continue;
      const double ex = gx_[g] - xi, ey = gy_[g] - yi, rr2 = ex * ex + ey * ey;
      if (rr2 >= r2max || rr2 == 0.0) continue;
      const int s = gseg_[g];
      if (gnx_[g] * (xi - o.x[s]) + gny_[g] * (yi - o.y[s]) <= 0.0) continue;  // behind this segment's line
      double w, f;
      ke(std::sqrt(rr2), w, f);
      ghost_.push_back(static_cast<int>(g));
      ex_.push_back(ex);
      ey_.push_back(ey);
      f_.push_back(f);
    }
    if (ghost_.size() == before) continue;
    particle_.push_back(i);
    start_.push_back(static_cast<int>(ghost_.size()));
  }
}

void PlateWall::momentum(const double* vx, const double* vy, const double* rho, const double* p,
                         const double* mass, const std::int64_t* gid, const PlateWallConstants& k, double* ax,
                         double* ay) {
  loads_.clear();
  const double viscosity = k.alpha * k.h * k.c0 * k.rho0;  // eq. 4
  const double eta2 = 0.01 * k.h * k.h;
  std::vector<double> lx(outline_.size()), ly(outline_.size());
  std::vector<int> hit;
  for (std::size_t a = 0; a < particle_.size(); ++a) {
    const int i = particle_[a];
    const double rhoi = rho[i], pi = p[i], inv_rhoi = 1.0 / rhoi;
    double sx = 0.0, sy = 0.0;
    hit.clear();
    for (int q = start_[a]; q < start_[a + 1]; ++q) {
      const int g = ghost_[q], s = gseg_[g];
      const double ex = ex_[q], ey = ey_[q], f = f_[q], eta = geta_[g];
      // Adami et al. (2012): pressure continued from the particle with the body force
      const double pg = pi + rhoi * (k.body_x * ex + k.body_y * ey);
      const double psum = k.clamp ? std::max(pi + pg, 0.0) : pi + pg;
      // eq. 4 pressure term: -(1/rho_i) (p_i + p_g) V_g grad_i W, grad_i W = -F e
      double scalar = psum * gvol_[g] * f * inv_rhoi;
      // eq. 8 with the ghost's velocity mirrored about the moving face: u_g - u_i = -2 ((u_i - u_w).n) n
      const double uwx = (1.0 - eta) * outline_.vx[s] + eta * outline_.vx[s + 1];
      const double uwy = (1.0 - eta) * outline_.vy[s] + eta * outline_.vy[s + 1];
      const double un = (vx[i] - uwx) * gnx_[g] + (vy[i] - uwy) * gny_[g];
      const double du_dot_e = -2.0 * un * (gnx_[g] * ex + gny_[g] * ey);
      scalar -= viscosity * du_dot_e / (ex * ex + ey * ey + eta2) * gvol_[g] * f * inv_rhoi;
      const double gx = scalar * ex, gy = scalar * ey;
      sx += gx;
      sy += gy;
      // the plate gets the opposite force, shared by the segment's points as a contact force (eq. 19's (1-eta), eta)
      if (lx[s] == 0.0 && ly[s] == 0.0) hit.push_back(s);
      if (lx[s + 1] == 0.0 && ly[s + 1] == 0.0) hit.push_back(s + 1);
      lx[s] -= (1.0 - eta) * mass[i] * gx;
      ly[s] -= (1.0 - eta) * mass[i] * gy;
      lx[s + 1] -= eta * mass[i] * gx;
      ly[s + 1] -= eta * mass[i] * gy;
    }
    ax[i] += sx;
    ay[i] += sy;
    std::sort(hit.begin(), hit.end());
    hit.erase(std::unique(hit.begin(), hit.end()), hit.end());
    for (int pt : hit) {
      if (lx[pt] != 0.0 || ly[pt] != 0.0) loads_.push_back({gid[i], pt, lx[pt], ly[pt]});
      lx[pt] = ly[pt] = 0.0;
    }
  }
}

void PlateWall::continuity(const double* vx, const double* vy, const double* rho, double* drho) const {
  for (std::size_t a = 0; a < particle_.size(); ++a) {
    const int i = particle_[a];
    double d = 0.0;
    for (int q = start_[a]; q < start_[a + 1]; ++q) {
      const int g = ghost_[q], s = gseg_[g];
      const double eta = geta_[g];
      const double uwx = (1.0 - eta) * outline_.vx[s] + eta * outline_.vx[s + 1];
      const double uwy = (1.0 - eta) * outline_.vy[s] + eta * outline_.vy[s + 1];
      const double un = (vx[i] - uwx) * gnx_[g] + (vy[i] - uwy) * gny_[g];
      const double n_dot_grad = -f_[q] * (gnx_[g] * ex_[q] + gny_[g] * ey_[q]);
      d += 2.0 * rho[i] * gvol_[g] * un * n_dot_grad;  // eq. 3 first term over the ghosts
    }
    drho[i] += d;
  }
}

}  // namespace halfeti::sph
