// The scene schema: the top-level sections, each declared by the module it configures.
#pragma once

#include <memory>

#include "halfeti/core/schema.hpp"

namespace halfeti::app {

std::shared_ptr<const scene::Schema> scene_schema();

}  // namespace halfeti::app
