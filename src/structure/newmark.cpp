#include "halfeti/structure/newmark.hpp"

#include "halfeti/core/error.hpp"

namespace halfeti::structure {

void validate(const NewmarkParameters& p) {
  if (!(p.beta > 0.0 && p.beta <= 0.5))
    HALFETI_USER_ERROR("structure.newmark.beta = " << p.beta << " must lie in (0, 0.5]");
  if (!(p.gamma >= 0.5 && p.gamma <= 1.0))
    HALFETI_USER_ERROR("structure.newmark.gamma = " << p.gamma << " must lie in [0.5, 1]");
  if (p.beta < 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5) - 1e-14)
    HALFETI_USER_ERROR("structure.newmark: beta = " << p.beta
                                                    << " < (gamma + 1/2)^2 / 4 is only "
                                                       "conditionally stable; use beta >= "
                                                    << 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5));
}

}  // namespace halfeti::structure
