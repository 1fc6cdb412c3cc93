// SSOSD relocation (eq. 22) and layer thickness (eq. 23).
#include "halfeti/coupling/ssosd.hpp"

#include <algorithm>
#include <cmath>

#include "halfeti/core/error.hpp"

namespace halfeti::coupling {

void validate(const SsosdParameters& p) {
  if (!(p.layer_ratio >= 5.0 && p.layer_ratio <= 50.0))
    HALFETI_USER_ERROR("coupling.ssosd.layer_ratio = "
                       << p.layer_ratio << " must lie in [5, 50] (eq. 23: 5 <= L / (u_max dt) <= 50)");
  if (!(p.velocity_floor > 0.0) || !std::isfinite(p.velocity_floor))
    HALFETI_USER_ERROR("coupling.ssosd.velocity_floor = " << p.velocity_floor << " m/s must be > 0");
}

double layer_thickness(const SsosdParameters& p, double u_max, double dt) {
  if (!p.enabled) return 0.0;
  return p.layer_ratio * std::max(u_max, p.velocity_floor) * dt;  // eq. 23
}

double modified_overlap(double overlap, double layer) {
  if (!(layer > 0.0)) return overlap;
  return overlap - layer + layer * std::exp(-overlap / layer);  // eq. 22
}

double relocated_gap(double gap, double layer) {
  if (!(layer > 0.0)) return std::max(gap, 0.0);
  if (gap >= layer) return gap;                    // outside the layer: untouched
  return layer * std::exp((gap - layer) / layer);  // = g + o'(L - g), computed without cancellation
}

}  // namespace halfeti::coupling
