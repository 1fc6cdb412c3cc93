// Closed forms of the elastic catenary's projections (eqs. 15-16) and flexibility (eq. 17, our eq. 18).
//
// Every term is an integral over s0 of a function of the tension vector (tx, V), V = va + w s0, written in a
// form that neither divides by w nor cancels: see docs/cable.md, "Evaluating the integrals".
#include <array>
#include <cmath>
#include <limits>

#include "halfeti/cable/catenary.hpp"

namespace halfeti::cable {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// asinh(z) / z for z >= 0, exact at z = 0.
double asinhc(double z) {
  if (z < 1e-4) return 1.0 - z * z / 6.0 + 0.075 * z * z * z * z;
  return std::asinh(z) / z;
}

// asinh(v / tx) for tx > 0 without overflow of v / tx when tx is tiny (nearly vertical cables).
double asinh_ratio(double v, double tx) {
  const double av = std::fabs(v);
  if (av <= tx) return std::asinh(v / tx);
  const double value = std::log(av + std::hypot(tx, v)) - std::log(tx);
  return v < 0.0 ? -value : value;
}

// 16-point Gauss-Legendre rule on [-1, 1], computed once by Newton on the Legendre polynomial.
struct GaussLegendre16 {
  std::array<double, 16> node{};
  std::array<double, 16> weight{};
  GaussLegendre16() {
    const int n = 16;
    for (int i = 0; i < n; ++i) {
      double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
      double dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1.0);
        const double dx = p1 / dp;
        x -= dx;
        if (std::fabs(dx) < 1e-16) break;
      }
      node[i] = x;
      weight[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
  }
};

const GaussLegendre16& gauss16() {
  static const GaussLegendre16 rule;
  return rule;
}

// The inextensible part of the cable over s0 in [0, s]: integrals of 1/T, V/T, V^2/T^3, -tx V/T^3,
// tx^2/T^3 and T, with tx >= 0, w >= 0.
struct SegmentIntegrals {
  double inv_tension = 0.0;  // int 1/T        (x = tx * this)
  double vertical = 0.0;     // int V/T        (y)
  double f11 = 0.0;          // int V^2/T^3    (dx/dtx)
  double f12 = 0.0;          // -int tx V/T^3  (dx/dty = dy/dtx)
  double f22 = 0.0;          // int tx^2/T^3   (dy/dty)
  double tension = 0.0;      // int T          (complementary energy)
};

SegmentIntegrals integrate_segment(double tx, double va, double w, double s) {
  SegmentIntegrals r;
  const double load = w * s;
  const double vb = va + load;
  const double ta = std::hypot(tx, va);
  const double tb = std::hypot(tx, vb);
  if (ta + tb == 0.0) {  // no tension anywhere (weightless, unloaded)
    r.inv_tension = r.f11 = r.f22 = kInf;
    return r;
  }
  const double vsum = va + vb;
  // (Tb - Ta) / w = s (va + vb) / (Ta + Tb), since Tb^2 - Ta^2 = (vb - va)(vb + va).
  r.vertical = s * vsum / (ta + tb);
  r.f12 = (ta > 0.0 && tb > 0.0) ? -tx * s * vsum / (ta * tb * (ta + tb)) : 0.0;

  double vt_difference = 0.0;  // (vb Tb - va Ta) / w
  const bool one_signed = va >= 0.0 || vb <= 0.0;
  if (one_signed) {
    if (vsum == 0.0) {  // va = vb = 0, w = 0: straight horizontal cable
      r.inv_tension = s / tx;
      r.f22 = s / tx;
      vt_difference = s * tx;
    } else {
      // asinh(b) - asinh(a) = asinh(z) with z = w s q: no cancellation when a and b share a sign.
      const double den = vb * ta + va * tb;
      if (den == 0.0) {
        r.inv_tension = kInf;  // tx = 0 and T = 0 at one end
      } else {
        const double q = vsum / den;
        r.inv_tension = s * q * asinhc(load * q);
        r.f22 = (tx > 0.0) ? s * tx * tx * q / (ta * tb) : 0.0;
      }
      vt_difference = s * vsum * (tx * tx + va * va + vb * vb) / (vb * tb + va * ta);
    }
  } else {
    // va < 0 < vb: the lowest point is inside the span; both terms add, and load > |va| + |vb| - 0 > 0.
    r.inv_tension = (tx > 0.0) ? s * (asinh_ratio(vb, tx) - asinh_ratio(va, tx)) / load : kInf;
    r.f22 = s * (vb / tb - va / ta) / load;
    vt_difference = s * (vb * tb - va * ta) / load;
  }

  const double umax = std::fmax(std::fabs(va), std::fabs(vb));
  if (tx > 0.0 && umax <= 0.5 * tx) {
    // Nearly horizontal: int V^2/T^3 = int 1/T - int tx^2/T^3 would cancel; integrate u^2 (1+u^2)^-3/2 over
    // u = V/tx in [va/tx, vb/tx] instead (analytic within |u| < 1, so 16 points give round-off accuracy).
    const GaussLegendre16& g = gauss16();
    const double a = va / tx;
    const double b = vb / tx;
    const double mid = 0.5 * (a + b);
    const double half = 0.5 * (b - a);
    double mean = 0.0;
    for (int i = 0; i < 16; ++i) {
      const double u = mid + half * g.node[i];
      const double u2 = u * u;
      mean += g.weight[i] * u2 / ((1.0 + u2) * std::sqrt(1.0 + u2));
    }
    r.f11 = 0.5 * mean * s / tx;
  } else if (tx == 0.0) {
    // Vertical: int 1/|V| = log(vmax/vmin)/w, unbounded if the cable folds (V changes sign).
    if (!one_signed || std::fmin(std::fabs(va), std::fabs(vb)) == 0.0) {
      r.f11 = kInf;
    } else {
      const double vmin = std::fmin(std::fabs(va), std::fabs(vb));
      const double x = load / vmin;
      r.f11 = (x < 1e-8) ? s / vmin * (1.0 - 0.5 * x) : s * std::log1p(x) / load;
    }
    r.inv_tension = r.f11;  // int 1/T = int V^2/T^3 when tx = 0
  } else {
    r.f11 = r.inv_tension - r.f22;
  }
  const double tx2_inv = (tx > 0.0) ? tx * tx * r.inv_tension : 0.0;
  r.tension = 0.5 * (vt_difference + tx2_inv);
  return r;
}

}  // namespace

CatenaryProjection catenary_projection(double tx, double ty, double length, double axial_stiffness,
                                       double weight_per_length) {
  const double l0 = length;
  const double ea = axial_stiffness;
  const double load = weight_per_length * l0;
  const SegmentIntegrals seg = integrate_segment(tx, ty, weight_per_length, l0);
  CatenaryProjection p;
  // eq. 15 at s0 = L0: elastic stretch + inextensible catenary
  p.horizontal = tx * l0 / ea + (tx > 0.0 ? tx * seg.inv_tension : 0.0);
  // eq. 16 at s0 = L0
  p.vertical = l0 * (ty + 0.5 * load) / ea + seg.vertical;
  // eq. 17-18, derived as the Hessian of the complementary energy (docs/cable.md)
  p.flexibility << l0 / ea + seg.f11, seg.f12, seg.f12, l0 / ea + seg.f22;
  const double mean_v2 = ty * ty + ty * load + load * load / 3.0;
  p.complementary_energy = l0 * (tx * tx + mean_v2) / (2.0 * ea) + seg.tension;
  return p;
}

Eigen::Vector2d catenary_point(double tx, double ty, double s0, double axial_stiffness,
                               double weight_per_length) {
  if (s0 <= 0.0) return Eigen::Vector2d::Zero();
  const SegmentIntegrals seg = integrate_segment(tx, ty, weight_per_length, s0);
  const double x = tx * s0 / axial_stiffness + (tx > 0.0 ? tx * seg.inv_tension : 0.0);
  const double y = s0 * (ty + 0.5 * weight_per_length * s0) / axial_stiffness + seg.vertical;
  return {x, y};
}

const char* to_string(CableState state) {
  return state == CableState::kTaut ? "taut" : "slack";
}

}  // namespace halfeti::cable
