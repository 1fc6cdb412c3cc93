// The scene's `coupling:` section: how water and plate meet through contact (section 2.3, eqs. 19-24). Used when
// the scene has both `fluid:` and `structure:`.
#pragma once

#include <memory>

#include "halfeti/core/scene.hpp"
#include "halfeti/coupling/contact_coupling.hpp"

namespace halfeti::app {

std::shared_ptr<const scene::Schema> coupling_schema();

coupling::CouplingParameters coupling_params(const scene::Node& root);

}  // namespace halfeti::app
