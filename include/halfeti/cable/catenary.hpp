// Two-node elastic catenary (Yang & Tsay 2007; the paper's section 2.2, eqs. 12-18).
//
// Frame and sign conventions (docs/cable.md derives everything):
//   - y points up; the cable's own load acts along -y in the solver's frame (a general distributed load is
//     handled by rotating into that frame).
//   - s0 is the unstretched arc length measured from end 1 (the "support"), s0 in [0, L0].
//   - (Tx, Ty) is the tension vector at s0 = 0, which is also the force the cable exerts on end 1. Along the
//     cable the tension vector is (Tx, Ty + w s0), so the force the cable exerts on end 2 is -(Tx, Ty + w
//     L0). The seed measures y downwards, hence its "Ty - m_c g s0" in eqs. 13-16.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace halfeti::cable {

// One cable element. In the 2D model these are per unit depth (see cable_set.hpp).
struct CableProperties {
  double unstretched_length = 0.0;  // L0 [m]
  double axial_stiffness = 0.0;     // EA [N]
  double weight_per_length = 0.0;  // w = m_c g per unit unstretched length, acting along -y [N/m]; may be < 0
  double horizontal_load = 0.0;    // extra distributed load along +x per unit unstretched length [N/m]
};

// The projection equations (eqs. 15-16 at s0 = L0) and their derivatives (eq. 17), in the solver's frame:
// load w >= 0 along -y, tx >= 0.
struct CatenaryProjection {
  double horizontal = 0.0;            // l = x(L0)
  double vertical = 0.0;              // h = y(L0)
  Eigen::Matrix2d flexibility;        // d(l, h) / d(Tx, Ty), symmetric positive definite
  double complementary_energy = 0.0;  // C with grad C = (l, h): integral of T + T^2 / (2 EA) over s0
};

// Evaluates the projections of a cable of unstretched length `length` whose end-1 tension is (tx, ty).
// Stable for w -> 0 (no division by w), tx -> 0 and nearly horizontal cables. Entries that are unbounded
// (tx = 0 with the cable folded back on itself) are +infinity.
CatenaryProjection catenary_projection(double tx, double ty, double length, double axial_stiffness,
                                       double weight_per_length);

// Coordinates (x(s0), y(s0)) of the point at unstretched arc length s0 from end 1 (eqs. 15-16).
Eigen::Vector2d catenary_point(double tx, double ty, double s0, double axial_stiffness,
                               double weight_per_length);

enum class CableState { kTaut, kSlack };

const char* to_string(CableState state);

struct CatenarySolution {
  Eigen::Vector2d end_tension = Eigen::Vector2d::Zero();  // (Tx, Ty) at s0 = 0, global frame
  double tension_start = 0.0;                             // T(0), eq. 14
  double tension_end = 0.0;                               // T(L0), eq. 14
  double sag = 0.0;  // largest distance between chord and curve, measured along the load
  double chord = 0.0;
  CableState state = CableState::kSlack;  // slack: chord shorter than L0
  bool carries_load = false;  // false only for a weightless slack cable (zero force and stiffness)
  Eigen::Matrix2d flexibility = Eigen::Matrix2d::Zero();  // d(end2 - end1)/d(Tx, Ty); inf laterally if folded
  Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();    // d(Tx, Ty)/d(d)
  Eigen::Vector4d nodal_force = Eigen::Vector4d::Zero();  // force the cable exerts on (x1, y1, x2, y2)
  Eigen::Matrix4d tangent = Eigen::Matrix4d::Zero();      // -d(nodal_force)/d(x1, y1, x2, y2) = [K -K; -K K]
  int iterations = 0;
};

// Solves the projection equations l = x(L0), h = y(L0) for the end-1 tension by Newton on the complementary
// energy (convex, so the damped iteration converges from any first guess). `first_guess` (Tx, Ty in the
// global frame, e.g. the last converged state) is used when it is on the right side of the frame; otherwise
// an inextensible catenary (slack) or an elastic bar (taut) supplies it. Throws NumericalError if Newton
// fails.
CatenarySolution solve_catenary(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                                const CableProperties& cable, const Eigen::Vector2d* first_guess = nullptr);

// The shape of a solved cable, for drawing: `segments` + 1 points at equal unstretched arc lengths from end 1 to
// end 2 (eqs. 15-16 in the solver's frame, rotated back) with the tension there (eq. 14). A weightless cable is
// straight with one tension (none when slack: its shape is then unknown and drawn as the chord).
struct CurvePoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double tension = 0.0;
};
std::vector<CurvePoint> catenary_curve(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                                       const CableProperties& cable, const CatenarySolution& solution,
                                       int segments);

// The unstretched length for which T(L0) (the tension at end 2) equals `end_tension`, on the taut branch.
// Throws UserError if no length attains it (a heavy cable's end tension has a positive minimum).
double unstretched_length_for_end_tension(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                                          double axial_stiffness, double weight_per_length,
                                          double end_tension);

}  // namespace halfeti::cable
