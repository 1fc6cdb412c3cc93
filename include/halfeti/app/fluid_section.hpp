// The scene's `fluid:` section (delta-SPH water) and its mapping onto sph::FluidParams.
#pragma once

#include <memory>

#include "halfeti/core/scene.hpp"
#include "halfeti/excitation/ground_motion.hpp"
#include "halfeti/sph/params.hpp"

namespace halfeti::app {

std::shared_ptr<const scene::Schema> fluid_schema();

// Reads the resolved `fluid:` section (with `tank:` and `gravity`) into the fluid's parameters, and checks what
// depends on several keys (water inside the tank, internal walls inside the tank, ...). `peak_ground_acceleration`
// feeds the automatic sound speed (eq. 10).
sph::FluidParams fluid_params(const scene::Node& root, double peak_ground_acceleration);

}  // namespace halfeti::app
