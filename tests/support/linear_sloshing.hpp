// Linear potential-flow sloshing of a rectangular tank under a horizontal ground acceleration a_g(t), in the tank's
// frame (every mass feels -a_g): the reference for the forced-sloshing validation.
//
// Tank length L, still depth d, xi in [0, L] from the left wall. With phi = sum_n c_n(t) cos(k_n xi)
// cosh(k_n y) / cosh(k_n d) and eta = sum_n eta_n(t) cos(k_n xi), k_n = n pi / L, the linearised free-surface
// conditions d(eta)/dt = d(phi)/dy and d(phi)/dt + g eta + a_g (xi - L/2) = 0 give, mode by mode,
//   eta_n'' + w_n^2 eta_n = G_n a_g(t),  w_n^2 = g k_n tanh(k_n d),  G_n = (w_n^2 / g) * 4 / (L k_n^2)  (n odd),
// and nothing for even n (xi - L/2 = sum_n -4 / (L k_n^2) cos(k_n xi) over odd n). A steady a_g tilts the surface
// to eta(0) = a_g L / (2 g): the left wall rises when the tank accelerates to +x.
//
// For the one-cycle cosine pulse a_g = A cos(W t) on [0, T], W = 2 pi / T, from rest:
//   eta_n = G_n A (cos W t - cos w_n t) / (w_n^2 - W^2) for t <= T, then free oscillation from its state at T.
#pragma once

#include <cmath>

namespace halfeti::test {

struct LinearSloshing {
  double length = 0.30, depth = 0.10, gravity = 9.81;
  int modes = 101;  // odd modes up to this n; the wall elevation's terms fall as 1/n^2

  struct Mode {
    double k, w2, G;  // wave number, squared frequency, forcing factor of eta_n'' + w2 eta_n = G a_g
  };
  Mode mode(int n) const {
    const double k = n * M_PI / length, w2 = gravity * k * std::tanh(k * depth);
    return {k, w2, w2 / gravity * 4.0 / (length * k * k)};
  }

  // The steady response to a constant a_g: sum_n G_n a_g / w_n^2 cos(k_n xi), which must be a_g (L/2 - xi) / g.
  double static_elevation(double xi, double a) const {
    double eta = 0.0;
    for (int n = 1; n <= modes; n += 2) {
      const Mode m = mode(n);
      eta += m.G * a / m.w2 * std::cos(m.k * xi);
    }
    return eta;
  }

  // Elevation above the still level at xi (from the left wall) at time t under A cos(2 pi t / T) on [0, T].
  double cosine_pulse_elevation(double xi, double t, double A, double T) const {
    const double W = 2.0 * M_PI / T;
    double eta = 0.0;
    for (int n = 1; n <= modes; n += 2) {
      const Mode m = mode(n);
      const double k = m.k, w2 = m.w2, w = std::sqrt(w2), c = m.G * A / (w2 - W * W);
      const double tau = std::fmin(t, T);
      double e = c * (std::cos(W * tau) - std::cos(w * tau));
      if (t > T) {
        const double v = c * (-W * std::sin(W * T) + w * std::sin(w * T));
        e = e * std::cos(w * (t - T)) + v / w * std::sin(w * (t - T));
      }
      eta += e * std::cos(k * xi);
    }
    return eta;
  }
};

}  // namespace halfeti::test
