// Newton solution of the elastic catenary's projection equations, and the element's force and tangent.
#include <algorithm>
#include <cmath>
#include <limits>

#include "halfeti/cable/catenary.hpp"
#include "halfeti/core/error.hpp"

namespace halfeti::cable {
namespace {

constexpr int kMaxNewtonIterations = 200;

// Frame in which the cable's load points along -y and the span is to the right (l >= 0): global vectors are
// `axes * local`, with columns (e_x, e_y) of the local frame.
struct SolverFrame {
  Eigen::Matrix2d axes = Eigen::Matrix2d::Identity();
  double load = 0.0;  // |distributed load| per unit unstretched length, >= 0
};

SolverFrame make_frame(const Eigen::Vector2d& span, const CableProperties& cable) {
  SolverFrame f;
  const Eigen::Vector2d q(cable.horizontal_load, -cable.weight_per_length);
  f.load = q.norm();
  Eigen::Vector2d ey(0.0, 1.0);
  if (f.load > 0.0) ey = -q / f.load;
  Eigen::Vector2d ex(ey.y(), -ey.x());
  if (ex.dot(span) < 0.0) ex = -ex;  // mirror so that the horizontal span is >= 0
  f.axes.col(0) = ex;
  f.axes.col(1) = ey;
  return f;
}

// Inextensible catenary through (l, h) with length L0 > chord: sinh(lambda)/lambda = sqrt(L0^2 - h^2)/l,
// tx = w l / (2 lambda); the end-1 slope parameter alpha = atanh(h/L0) - lambda gives ty = tx sinh(alpha).
Eigen::Vector2d inextensible_guess(double l, double h, double l0, double w) {
  const double rho = std::sqrt((l0 - h) * (l0 + h)) / l;
  // Both starting points lie right of the root (sinh x / x > rho there) and Newton on the convex
  // sinh(x) - rho x then decreases monotonically to it.
  double lambda = std::min(std::sqrt(6.0 * (rho - 1.0)), 2.0 * std::log(2.0 * rho) + 1.0);
  for (int it = 0; it < 100 && lambda > 0.0; ++it) {
    const double step = (std::sinh(lambda) - rho * lambda) / (std::cosh(lambda) - rho);
    lambda -= step;
    if (!(std::fabs(step) > 1e-14 * lambda)) break;
  }
  lambda = std::max(lambda, 1e-6);
  const double tx = w * l / (2.0 * lambda);
  const double alpha = std::atanh(std::clamp(h / l0, -1.0 + 1e-16, 1.0 - 1e-16)) - lambda;
  return {tx, tx * std::sinh(alpha)};
}

Eigen::Vector2d first_guess_in_frame(double l, double h, const CableProperties& cable, double w) {
  const double l0 = cable.unstretched_length;
  const double chord = std::hypot(l, h);
  if (chord < l0) return inextensible_guess(l, h, l0, w);
  // Taut: an elastic bar along the chord carrying half the weight at each end.
  const double tension = std::max(cable.axial_stiffness * (chord / l0 - 1.0), 0.5 * w * l0);
  return {tension * l / chord, tension * h / chord - 0.5 * w * l0};
}

struct FrameSolution {
  Eigen::Vector2d tension;  // (tx, ty)
  CatenaryProjection projection;
  int iterations = 0;
};

[[noreturn]] void newton_failed(double l, double h, const CableProperties& c, double w, double residual) {
  HALFETI_NUMERICAL_ERROR("catenary cable did not converge: span l = "
                          << l << " m, h = " << h << " m, L0 = " << c.unstretched_length << " m, EA = "
                          << c.axial_stiffness << " N, w = " << w << " N/m (residual " << residual << " m)");
}

// Vertical chord (l = 0): tx = 0 by symmetry, and h(ty) is piecewise linear (fold or no fold).
FrameSolution solve_vertical(double h, const CableProperties& c, double w) {
  const double l0 = c.unstretched_length;
  const double ea = c.axial_stiffness;
  const double load = w * l0;
  const double h_up = load * l0 / (2.0 * ea) + l0;     // h at ty = 0 (cable hangs from end 2)
  const double h_down = -load * l0 / (2.0 * ea) - l0;  // h at ty = -w L0 (cable hangs from end 1)
  double ty;
  if (h >= h_up) {
    ty = ea * (h - l0) / l0 - 0.5 * load;
  } else if (h <= h_down) {
    ty = ea * (h + l0) / l0 - 0.5 * load;
  } else {
    ty = 0.5 * (h / (l0 / (2.0 * ea) + l0 / load) - load);
  }
  FrameSolution s;
  s.tension = {0.0, ty};
  s.projection = catenary_projection(0.0, ty, l0, ea, w);
  return s;
}

FrameSolution solve_in_frame(double l, double h, const CableProperties& c, double w,
                             const Eigen::Vector2d* guess) {
  const double l0 = c.unstretched_length;
  const double ea = c.axial_stiffness;
  if (l == 0.0) return solve_vertical(h, c, w);

  Eigen::Vector2d x = first_guess_in_frame(l, h, c, w);
  if (guess && (*guess)(0) > 0.0 && guess->allFinite()) x = *guess;
  const double scale = std::max(std::hypot(l, h), l0);
  const Eigen::Vector2d target(l, h);
  auto potential = [&](const Eigen::Vector2d& t, const CatenaryProjection& p) {
    return p.complementary_energy - t.dot(target);
  };

  FrameSolution s;
  CatenaryProjection p = catenary_projection(x(0), x(1), l0, ea, w);
  Eigen::Vector2d r = Eigen::Vector2d(p.horizontal, p.vertical) - target;
  double pot = potential(x, p);
  for (int it = 1; it <= kMaxNewtonIterations; ++it) {
    if (r.norm() <= 1e-15 * scale) break;
    const Eigen::Vector2d d = -p.flexibility.ldlt().solve(r);
    // Keep tx > 0 (the minimiser has tx > 0 when l > 0).
    double alpha = 1.0;
    if (x(0) + d(0) <= 0.0) alpha = 0.9 * x(0) / -d(0);
    const double slope = r.dot(d);  // directional derivative of the potential, < 0
    bool accepted = false;
    Eigen::Vector2d x_new;
    CatenaryProjection p_new;
    Eigen::Vector2d r_new;
    double pot_new = 0.0;
    for (int ls = 0; ls < 60; ++ls, alpha *= 0.5) {
      x_new = x + alpha * d;
      p_new = catenary_projection(x_new(0), x_new(1), l0, ea, w);
      r_new = Eigen::Vector2d(p_new.horizontal, p_new.vertical) - target;
      pot_new = potential(x_new, p_new);
      if (!std::isfinite(pot_new) || !r_new.allFinite()) continue;
      const double round_off = 1e-13 * (std::fabs(p_new.complementary_energy) + std::fabs(x_new.dot(target)));
      if (pot_new <= pot + 1e-4 * alpha * slope ||
          (std::fabs(pot_new - pot) <= round_off && r_new.norm() < r.norm())) {
        accepted = true;
        break;
      }
    }
    s.iterations = it;
    if (!accepted) break;  // no further decrease: at the round-off floor (checked below) or stuck
    // At the round-off floor the residual only jitters: stop once it no longer halves.
    const bool stalled = (x_new - x).norm() <= 1e-16 * x_new.norm() ||
                         (r_new.norm() <= 1e-12 * scale && r_new.norm() > 0.5 * r.norm());
    x = x_new;
    p = p_new;
    r = r_new;
    pot = pot_new;
    if (stalled) break;
  }
  if (!(r.norm() <= 1e-10 * scale)) newton_failed(l, h, c, w, r.norm());
  s.tension = x;
  s.projection = p;
  return s;
}

// Largest distance, measured along the load, between the chord and the curve (the frame's vertical).
double sag_in_frame(const FrameSolution& s, double l, double h, const CableProperties& c, double w) {
  const double l0 = c.unstretched_length;
  const double ea = c.axial_stiffness;
  const double tx = s.tension(0);
  const double ty = s.tension(1);
  if (w == 0.0) return 0.0;
  if (l <= 1e-6 * std::hypot(l, h)) {
    // Nearly vertical chord: depth of the fold below the lower end, if the cable folds.
    if (!(ty < 0.0 && ty + w * l0 > 0.0)) return 0.0;
    const double y_low = catenary_point(tx, ty, -ty / w, ea, w).y();
    return std::max(0.0, std::min(0.0, h) - y_low);
  }
  // The curve is convex; the largest gap is where its slope V/tx equals the chord's h/l.
  const double s0 = std::clamp((tx * h / l - ty) / w, 0.0, l0);
  const Eigen::Vector2d p = catenary_point(tx, ty, s0, ea, w);
  return std::max(0.0, h / l * p.x() - p.y());
}

CatenarySolution weightless(const Eigen::Vector2d& span, const CableProperties& c) {
  CatenarySolution sol;
  const double chord = span.norm();
  sol.chord = chord;
  sol.state = chord > c.unstretched_length ? CableState::kTaut : CableState::kSlack;
  if (sol.state == CableState::kSlack) return sol;  // carries nothing: zero force and stiffness
  const double l0 = c.unstretched_length;
  const double tension = c.axial_stiffness * (chord - l0) / l0;
  const Eigen::Vector2d n = span / chord;
  const Eigen::Matrix2d along = n * n.transpose();
  const Eigen::Matrix2d across = Eigen::Matrix2d::Identity() - along;
  sol.carries_load = true;
  sol.end_tension = tension * n;
  sol.tension_start = sol.tension_end = tension;
  // Axial EA/L0 along the chord, string stiffness T/chord across it (the stretched length is the chord).
  sol.stiffness = c.axial_stiffness / l0 * along + tension / chord * across;
  sol.flexibility = l0 / c.axial_stiffness * along + (tension > 0.0 ? chord / tension : 0.0) * across;
  return sol;
}

}  // namespace

CatenarySolution solve_catenary(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                                const CableProperties& cable, const Eigen::Vector2d* first_guess) {
  HALFETI_CHECK(cable.unstretched_length > 0.0 && cable.axial_stiffness > 0.0,
                "cable needs L0 > 0 and EA > 0 (L0 = " << cable.unstretched_length
                                                       << ", EA = " << cable.axial_stiffness << ")");
  const Eigen::Vector2d span = end2 - end1;
  HALFETI_CHECK(span.allFinite(), "cable end positions are not finite");
  const SolverFrame frame = make_frame(span, cable);
  const double w = frame.load;
  CatenarySolution sol;
  if (w == 0.0) {
    sol = weightless(span, cable);
  } else {
    const Eigen::Vector2d local_span = frame.axes.transpose() * span;
    const double l = std::max(0.0, local_span.x());
    const double h = local_span.y();
    Eigen::Vector2d guess;
    if (first_guess) guess = frame.axes.transpose() * *first_guess;
    const FrameSolution fs = solve_in_frame(l, h, cable, w, first_guess ? &guess : nullptr);
    const double tx = fs.tension(0);
    const double ty = fs.tension(1);
    const double l0 = cable.unstretched_length;
    sol.chord = span.norm();
    sol.state = sol.chord < l0 ? CableState::kSlack : CableState::kTaut;
    sol.carries_load = true;
    sol.iterations = fs.iterations;
    sol.end_tension = frame.axes * fs.tension;
    sol.tension_start = std::hypot(tx, ty);         // eq. 14, s0 = 0
    sol.tension_end = std::hypot(tx, ty + w * l0);  // eq. 14, s0 = L0
    sol.sag = sag_in_frame(fs, l, h, cable, w);
    const Eigen::Matrix2d& f = fs.projection.flexibility;
    Eigen::Matrix2d k;
    if (std::isinf(f(0, 0))) {
      k << 0.0, 0.0, 0.0, 1.0 / f(1, 1);  // vertical folded cable: no lateral stiffness
    } else {
      k = f.inverse();
      k(0, 1) = k(1, 0) = 0.5 * (k(0, 1) + k(1, 0));
    }
    const Eigen::Matrix2d& a = frame.axes;
    if (std::isinf(f(0, 0))) {
      // Unbounded along the frame's x; written entry by entry so that a zero direction cosine gives 0, not
      // NaN.
      const Eigen::Matrix2d along_x = a.col(0) * a.col(0).transpose();
      sol.flexibility = f(1, 1) * a.col(1) * a.col(1).transpose();
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          if (along_x(i, j) != 0.0) sol.flexibility(i, j) = std::copysign(f(0, 0), along_x(i, j));
    } else {
      sol.flexibility = a * f * a.transpose();
    }
    sol.stiffness = a * k * a.transpose();
  }
  // Forces on the ends: +T(0) on end 1, -T(L0) on end 2; they sum to the cable's load.
  const Eigen::Vector2d total_load(cable.horizontal_load * cable.unstretched_length,
                                   -cable.weight_per_length * cable.unstretched_length);
  sol.nodal_force.head<2>() = sol.end_tension;
  sol.nodal_force.tail<2>() =
      sol.carries_load ? Eigen::Vector2d(total_load - sol.end_tension) : Eigen::Vector2d::Zero();
  // d(end_tension)/d(end2 - end1) = K, so the force the nodes exert on the cable has tangent [K -K; -K K].
  sol.tangent.topLeftCorner<2, 2>() = sol.stiffness;
  sol.tangent.topRightCorner<2, 2>() = -sol.stiffness;
  sol.tangent.bottomLeftCorner<2, 2>() = -sol.stiffness;
  sol.tangent.bottomRightCorner<2, 2>() = sol.stiffness;
  return sol;
}

std::vector<CurvePoint> catenary_curve(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                                       const CableProperties& cable, const CatenarySolution& solution,
                                       int segments) {
  HALFETI_CHECK(segments >= 1, "a cable's curve needs at least one segment (" << segments << ")");
  std::vector<CurvePoint> out(static_cast<std::size_t>(segments) + 1);
  const SolverFrame frame = make_frame(end2 - end1, cable);
  const double l0 = cable.unstretched_length;
  // End 1's tension in the solver's frame; along the cable it is (Tx, Ty + w s0) there (eq. 14).
  const Eigen::Vector2d t0 = frame.axes.transpose() * solution.end_tension;
  for (int k = 0; k <= segments; ++k) {
    const double s0 = l0 * k / segments;
    CurvePoint& p = out[static_cast<std::size_t>(k)];
    if (frame.load == 0.0 || !solution.carries_load) {
      p.position = end1 + (end2 - end1) * (static_cast<double>(k) / segments);
      p.tension = solution.carries_load ? solution.tension_start : 0.0;
    } else {
      p.position = end1 + frame.axes * catenary_point(t0.x(), t0.y(), s0, cable.axial_stiffness, frame.load);
      p.tension = std::hypot(t0.x(), t0.y() + frame.load * s0);
    }
  }
  return out;
}

}  // namespace halfeti::cable
