// Renormalised density gradient (eqs. 6-7).
#include <cmath>

#include "halfeti/sph/delta_sph.hpp"

namespace halfeti::sph {

void density_gradient(const ParticleView& pv, const FluidPairList& pairs, std::vector<double>& grad_rho) {
  grad_rho.assign(2 * static_cast<std::size_t>(pv.n_owned), 0.0);
  for (int i = 0; i < pv.n_owned; ++i) {
    // B = sum_j V_j grad_i W_ij (x) r_ji, so that sum_j V_j (f_j - f_i) grad_i W_ij = B grad f for linear f;
    // L_i of eq. 7 is its inverse (written with grad_i W pointing from i towards j).
    double b00 = 0, b01 = 0, b10 = 0, b11 = 0, sx = 0, sy = 0;
    const double rhoi = pv.rho[i], x_i = pv.x[i], y_i = pv.y[i];
    for_each_neighbour(pairs, i, [&](int j, int k) {
      const double vj = pv.volume[j];
      const double ex = pv.x[j] - x_i, ey = pv.y[j] - y_i;        // r_ji
      const double gx = -pairs.f[k] * ex, gy = -pairs.f[k] * ey;  // grad_i W_ij
      b00 += vj * gx * ex;
      b01 += vj * gx * ey;
      b10 += vj * gy * ex;
      b11 += vj * gy * ey;
      const double drho = (pv.rho[j] - rhoi) * vj;  // eq. 6
      sx += drho * gx;
      sy += drho * gy;
    });
    const double det = b00 * b11 - b01 * b10;
    if (std::abs(det) < kRenormalisationMinDet) {  // near-singular L_i (eq. 7): plain SPH gradient
      grad_rho[2 * i] = sx;
      grad_rho[2 * i + 1] = sy;
      continue;
    }
    // Solve B g = s (eq. 6 with L_i = B^-1, eq. 7)
    grad_rho[2 * i] = (b11 * sx - b01 * sy) / det;
    grad_rho[2 * i + 1] = (-b10 * sx + b00 * sy) / det;
  }
}

double moment_min_eigenvalue(const ParticleView& pv, const FluidPairList& pairs, const PairList& ghost_pairs,
                             const WallGhosts& ghosts, int i) {
  double b00 = 0, b01 = 0, b11 = 0;  // B is symmetric: grad_i W_ij = -F r_ji
  auto add = [&](double v, double f, double ex, double ey) {
    const double vf = -v * f;
    b00 += vf * ex * ex;
    b01 += vf * ex * ey;
    b11 += vf * ey * ey;
  };
  const double x_i = pv.x[i], y_i = pv.y[i];
  for_each_neighbour(pairs, i,
                     [&](int j, int k) { add(pv.volume[j], pairs.f[k], pv.x[j] - x_i, pv.y[j] - y_i); });
  if (!ghost_pairs.start.empty())
    for_each_neighbour(ghost_pairs, i, [&](int g, int k) {
      add(ghosts.volume[g], ghost_pairs.f[k], ghost_pairs.ex[k], ghost_pairs.ey[k]);
    });
  const double mean = 0.5 * (b00 + b11), half = 0.5 * (b00 - b11);
  return mean - std::sqrt(half * half + b01 * b01);
}

}  // namespace halfeti::sph
