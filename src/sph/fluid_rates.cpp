// Right-hand sides of the delta-SPH equations for the owned particles.
#include <algorithm>
#include <cmath>

#include "halfeti/sph/delta_sph.hpp"

namespace halfeti::sph {

namespace {
// Monaghan (2000) tensile-instability coefficient R_i: eps |p| / rho^2, larger for tension.
inline double tensile_coefficient(double p, double rho, double eps_neg, double eps_pos) {
  return (p < 0.0 ? eps_neg * -p : eps_pos * p) / (rho * rho);
}

// The momentum equation's body, compiled twice: with the laminar term (Laminar = true) and without it, so that
// the default path (laminar_viscosity 0) carries no branch or accumulator of a term it does not use.
template <bool Laminar>
void momentum_rates_impl(const ParticleView& pv, const FluidPairList& pairs, const PairList& wall_pairs,
                         const WallParticles& walls, const PairList& ghost_pairs, const WallGhosts& ghosts,
                         const std::vector<double>& grad_rho, const RateConstants& k, Rates& out) {
  const int n = pv.n_owned;
  out.ax.assign(n, 0.0);
  out.ay.assign(n, 0.0);
  double max_mu = 0.0, max_a2 = 0.0;
  // Monaghan (2000) coefficients of every local particle, once (ghosts included).
  std::vector<double> tensile(k.tensile ? pv.n_local : 0);
  for (std::size_t j = 0; j < tensile.size(); ++j)
    tensile[j] = tensile_coefficient(pv.p[j], pv.rho[j], k.eps_neg, k.eps_pos);
  const double inv_w_dx = 1.0 / k.w_dx;
  const double eta2 = 0.01 * k.h * k.h;
  const double viscosity = k.alpha * k.h * k.c0 * k.rho0;  // eq. 4
  const double four_nu = 4.0 * k.laminar_nu;
  const double body_norm = std::hypot(k.body_x, k.body_y);  // |b|, the same for every particle

  for (int i = 0; i < n; ++i) {
    const double rhoi = pv.rho[i], pi = pv.p[i], ui = pv.vx[i], vi = pv.vy[i];
    const double ri_t = k.tensile ? tensile[i] : 0.0, inv_rhoi = 1.0 / rhoi, x_i = pv.x[i], y_i = pv.y[i];
    double ax = 0, ay = 0;
    double mu_i = 0.0;
    [[maybe_unused]] double lx = 0.0, ly = 0.0;  // the laminar term, nu times the velocity's Laplacian
    for_each_neighbour(pairs, i, [&](int j, int q) {
      const double ex = pv.x[j] - x_i, ey = pv.y[j] - y_i, r2 = ex * ex + ey * ey;  // r_ji
      const double vj = pv.volume[j];
      const double du = pv.vx[j] - ui, dv = pv.vy[j] - vi;
      // eq. 4 pressure term in the symmetric volume form -(1/rho_i) sum (p_i + p_j) V_j grad_i W_ij
      // (the 1/rho_i is applied after the sum)
      double scalar = -(pi + pv.p[j]) * vj;
      // eq. 8: pi_ij = (u_j - u_i).(r_j - r_i) / (|r_ji|^2 + eta^2); eq. 4: + alpha h c0 rho0 / rho_i sum pi_ij V_j grad W
      const double u_dot_r = du * ex + dv * ey, mu = u_dot_r / (r2 + eta2);
      scalar += viscosity * mu * vj;
      if (k.tensile) {  // Monaghan (2000): - m_j (R_i + R_j) (W_ij / W(dx))^4 grad_i W_ij (times rho_i / rho_i)
        const double fij = pairs.w[q] * inv_w_dx, f2 = fij * fij;
        scalar -= rhoi * pv.mass[j] * (ri_t + tensile[j]) * f2 * f2;
      }
      // grad_i W_ij = -F r_ji
      ax -= scalar * pairs.f[q] * ex;
      ay -= scalar * pairs.f[q] * ey;
      mu_i = std::max(mu_i, std::abs(mu));
      if constexpr (Laminar) {
        // Morris et al. (1997) in Lo & Shao's (2003) form: nu lap(u)_i = sum_j 4 nu m_j (r_ij.grad_i W_ij)
        // / ((rho_i + rho_j)(r_ij^2 + eta^2)) u_ij, with r_ij.grad_i W_ij = F r^2 (F < 0) and u_ij = -(du, dv)
        const double s = four_nu * pv.mass[j] * pairs.f[q] * r2 / ((rhoi + pv.rho[j]) * (r2 + eta2));
        lx -= s * du;
        ly -= s * dv;
      }
    });
    if constexpr (Laminar) {
      ax = ax * inv_rhoi + lx;
      ay = ay * inv_rhoi + ly;
    } else {
      ax *= inv_rhoi;
      ay *= inv_rhoi;
    }
    max_mu = std::max(max_mu, k.h * mu_i);

    // Wall pressure: the eq. 4 pressure term over the ghost points behind the walls, their pressure continued
    // from particle i as a first-order Taylor expansion, p_g = p_i + (dp/dn)(n.r_gi) + (dp/dt)(t.r_gi). Across
    // the wall, the wall condition dp/dn = rho_i b.n (the wall is at rest in the tank frame). Along it, the
    // particle's own gradient c0^2 <grad rho>^L_i.t (eqs. 6, 9): the hydrostatic slope rho_i b.t in still water
    // (as Adami et al. 2012), none in a film whose pressure does not vary along the wall (the body force's slope
    // there held up a fifth of a film's weight). It is bounded by rho_i |b|, so that the ghosts never accelerate
    // a particle along the wall by more than the body force: unbounded, the gradient at the tip of a film in
    // tension pushed the tip away from the film, which stretched it further (docs/sph.md "Wall films").
    // Corner quadrants lie behind two walls: the wall condition in both directions, p_g = p_i + rho_i b.r_gi.
    // Not clamped: a particle in tension (p_i < 0) next to a wall must see its tension continued behind the wall,
    // or the truncated fluid sum -(1/rho_i) sum (p_i + p_j) V_j grad W pushes it off the wall by about
    // 2 |p_i| / (rho h), it expands and its pressure falls further (docs/sph.md, "Walls").
    const bool taylor = !grad_rho.empty();
    const double gpx = taylor ? k.c0 * k.c0 * grad_rho[2 * i] : 0.0;  // eq. 9: grad p = c0^2 grad rho
    const double gpy = taylor ? k.c0 * k.c0 * grad_rho[2 * i + 1] : 0.0;
    const double slope_bound = rhoi * body_norm;
    if (k.wall_pressure)
      for_each_neighbour(ghost_pairs, i, [&](int g, int q) {
        const double rgx = ghost_pairs.ex[q], rgy = ghost_pairs.ey[q];  // r_g - r_i
        double p_ghost = pi + rhoi * (k.body_x * rgx + k.body_y * rgy);
        if (taylor && !ghosts.corner[g]) {
          // replace the body force's slope along the wall by the bounded slope of the particle's own gradient
          const double tx = -ghosts.ny[g], ty = ghosts.nx[g], along = tx * rgx + ty * rgy;
          const double own = std::clamp(gpx * tx + gpy * ty, -slope_bound, slope_bound);
          p_ghost += (own - rhoi * (k.body_x * tx + k.body_y * ty)) * along;
        }
        double s = -(pi + p_ghost) * ghosts.volume[g] / rhoi * -ghost_pairs.f[q];
        // eq. 8 with the ghost's velocity: mirrored (free slip, u_g - u_i = -2 (u_i.n) n, only the wall-normal
        // motion is damped) or reversed (no slip, u_g - u_i = -2 u_i)
        const double ex = ghost_pairs.ex[q], ey = ghost_pairs.ey[q], r2 = ex * ex + ey * ey;
        const double du_dot_e = k.wall_no_slip ? -2.0 * (ui * ex + vi * ey)
                                               : -2.0 * (ui * ghosts.nx[g] + vi * ghosts.ny[g]) *
                                                     (ghosts.nx[g] * ex + ghosts.ny[g] * ey);
        s += viscosity * (du_dot_e / (r2 + eta2)) * ghosts.volume[g] / rhoi * -ghost_pairs.f[q];
        ax += s * ghost_pairs.ex[q];
        ay += s * ghost_pairs.ey[q];
        if constexpr (Laminar) {
          // the laminar term with the same ghost velocity (m_g = rho_i V_g, rho_g = rho_i): mirrored or reversed
          const double un = ui * ghosts.nx[g] + vi * ghosts.ny[g];
          const double dgx = k.wall_no_slip ? -2.0 * ui : -2.0 * un * ghosts.nx[g];
          const double dgy = k.wall_no_slip ? -2.0 * vi : -2.0 * un * ghosts.ny[g];
          const double lam = 0.5 * four_nu * ghosts.volume[g] * ghost_pairs.f[q] * r2 / (r2 + eta2);
          ax -= lam * dgx;  // lam u_ig = -lam (u_g - u_i)
          ay -= lam * dgy;
        }
      });
    // Walls: Monaghan & Kos (1999) repulsion, kept as a short-range barrier against penetration.
    for_each_neighbour(wall_pairs, i, [&](int w, int q) {
      const double rx = -wall_pairs.ex[q], ry = -wall_pairs.ey[q];  // r_i - r_w
      double nx = walls.nx[w], ny = walls.ny[w];
      double psi = rx * nx + ry * ny;
      if (walls.two_sided[w] && psi < 0.0) {
        psi = -psi;
        nx = -nx;
        ny = -ny;
      }
      if (psi <= 0.0) return;
      const double xi = -rx * ny + ry * nx;
      const double push = monaghan_kos_repulsion(psi, xi, walls.spacing[w], k.wall_range, k.wall_amplitude);
      ax += push * nx;
      ay += push * ny;
    });
    ax += k.body_x;
    ay += k.body_y;
    out.ax[i] = ax;
    out.ay[i] = ay;
    max_a2 = std::max(max_a2, ax * ax + ay * ay);
  }
  out.max_mu = max_mu;
  out.max_accel = std::sqrt(max_a2);
}
}  // namespace

void momentum_rates(const ParticleView& pv, const FluidPairList& pairs, const PairList& wall_pairs,
                    const WallParticles& walls, const PairList& ghost_pairs, const WallGhosts& ghosts,
                    const std::vector<double>& grad_rho, const RateConstants& k, Rates& out) {
  if (k.laminar_nu > 0.0)
    momentum_rates_impl<true>(pv, pairs, wall_pairs, walls, ghost_pairs, ghosts, grad_rho, k, out);
  else
    momentum_rates_impl<false>(pv, pairs, wall_pairs, walls, ghost_pairs, ghosts, grad_rho, k, out);
}

void continuity_rates(const ParticleView& pv, const FluidPairList& pairs, const PairList& ghost_pairs,
                      const WallGhosts& ghosts, const std::vector<double>& grad_rho, const RateConstants& k,
                      Rates& out) {
  const int n = pv.n_owned;
  out.drho.assign(n, 0.0);
  out.xsph_x.assign(n, 0.0);
  out.xsph_y.assign(n, 0.0);
  const double diffusion = k.delta * k.h * k.c0;  // eq. 3
  const bool use_delta = k.delta > 0.0 && !grad_rho.empty();
  for (int i = 0; i < n; ++i) {
    const double rhoi = pv.rho[i], ui = pv.vx[i], vi = pv.vy[i], x_i = pv.x[i], y_i = pv.y[i];
    const double gri_x = use_delta ? grad_rho[2 * i] : 0.0, gri_y = use_delta ? grad_rho[2 * i + 1] : 0.0;
    double div = 0, diff = 0, xs = 0, ys = 0;
    for_each_neighbour(pairs, i, [&](int j, int q) {
      const double ex = pv.x[j] - x_i, ey = pv.y[j] - y_i, f = pairs.f[q];  // r_ji
      const double vj = pv.volume[j];
      const double du = pv.vx[j] - ui, dv = pv.vy[j] - vi;
      // eq. 3, first term, in Marrone et al.'s (2011) form -rho_i sum V_j (u_j - u_i).grad_i W_ij, grad_i W = -F r_ji
      div -= vj * f * (du * ex + dv * ey);
      if (use_delta) {
        // eqs. 3, 5: delta h c0 sum V_j psi_ij.grad_i W_ij, psi_ij = 2 (rho_j - rho_i) r_ji / r^2 - (grad^L_i + grad^L_j)
        // (two particles at one point, which the contact's relocation can produce, have no direction: 0)
        const double r2 = ex * ex + ey * ey, s = r2 > 0.0 ? 2.0 * (pv.rho[j] - rhoi) / r2 : 0.0;
        const double psx = s * ex - (gri_x + grad_rho[2 * j]), psy = s * ey - (gri_y + grad_rho[2 * j + 1]);
        diff -= vj * f * (psx * ex + psy * ey);
      }
      // eq. 11 (XSPH), written towards the neighbours' mean velocity: eps sum m_j (u_j - u_i) / rho_bar_ij W_ij
      const double wm = pv.mass[j] * pairs.w[q] / (0.5 * (rhoi + pv.rho[j]));
      xs += wm * du;
      ys += wm * dv;
    });
    double drho = -rhoi * div + diffusion * diff;
    // Wall ghosts move as the mirror image of particle i (free slip): u_g - u_i = -2 (u_i . n) n.
    if (k.wall_pressure)
      for_each_neighbour(ghost_pairs, i, [&](int g, int q) {
        const double un = ui * ghosts.nx[g] + vi * ghosts.ny[g];
        const double n_dot_grad =
            -ghost_pairs.f[q] * (ghosts.nx[g] * ghost_pairs.ex[q] + ghosts.ny[g] * ghost_pairs.ey[q]);
        drho += 2.0 * rhoi * ghosts.volume[g] * un * n_dot_grad;  // eq. 3 first term over the ghosts
      });
    out.drho[i] = drho;
    out.xsph_x[i] = k.xsph * xs;
    out.xsph_y[i] = k.xsph * ys;
  }
}

}  // namespace halfeti::sph
