// Health monitors of the fluid (DESIGN.md): density variation (warning), particle outside the tank (fatal),
// spacing collapse (warning), NaN/Inf (fatal), dt below the floor (fatal). Checks are collective; a fatal one
// throws halfeti::NumericalError with the same single message on every rank.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "halfeti/core/collective.hpp"
#include "halfeti/core/health.hpp"

namespace halfeti::sph {

using HealthEvent = halfeti::HealthEvent;  // one record for every part's monitors (core/health.hpp)

using halfeti::first_problem;  // the lowest-key problem on every rank (core/collective.hpp)

}  // namespace halfeti::sph
