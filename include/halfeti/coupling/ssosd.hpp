// Shifting the surface of the structural domain (SSOSD, eqs. 22-23): an intermediate layer of thickness L
// outside the plate's surface in which fluid particles are relocated by an exponential law instead of being
// pushed exactly onto the surface. See docs/coupling.md for the reading of the garbled eqs. 22 and 23.
#pragma once

namespace halfeti::coupling {

struct SsosdParameters {
  bool enabled = true;          // false: invaders are particles past the surface, pushed exactly onto it
  double layer_ratio = 10.0;    // L / (u_max dt), eq. 23 read dimensionless: [5, 50]
  double velocity_floor = 0.5;  // m/s, > 0: u_max in eq. 23 is at least this (still water keeps a layer; near
                                // the expected peak speed it keeps L steady: docs/coupling.md)
};

void validate(const SsosdParameters& p);  // UserError naming coupling.ssosd.<key> and its range

// Eq. 23: L = ratio * max(u_max, floor) * dt [m]. Zero when SSOSD is off.
double layer_thickness(const SsosdParameters& p, double u_max, double dt);

// Eq. 22: modified overlap o' = o - L + L exp(-o / L) for a penetration o = L - g >= 0 into the layer [m];
// the particle is moved by o' along the normal. L = 0 (no layer) gives o' = o - 0 = -g (exactly onto the
// surface).
double modified_overlap(double overlap, double layer);

// The gap a particle with current gap g is moved to: g + o'(L - g) = L exp((g - L) / L) in (0, L] for g <= L;
// with L = 0, max(g, 0) (plain contact). Monotone increasing in g, never negative (never past the surface).
double relocated_gap(double gap, double layer);

// Whether a particle with gap g takes part in the contact solve: g < L with a layer, g < 0 without one.
inline bool is_invader(double gap, double layer) {
  return layer > 0.0 ? gap < layer : gap < 0.0;
}

}  // namespace halfeti::coupling
