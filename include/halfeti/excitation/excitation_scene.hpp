// The scene's `excitation:` section: which ground motion shakes the tank. Kinds resolve through one registry.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "halfeti/core/registry.hpp"
#include "halfeti/core/scene.hpp"
#include "halfeti/excitation/ground_motion.hpp"

namespace halfeti::excitation {

// Builds a ground motion from its resolved section; `scene_dir` anchors relative record paths.
using GroundMotionFactory =
    std::function<std::unique_ptr<GroundMotion>(const scene::Node& section, const std::string& scene_dir)>;

const Registry<GroundMotionFactory>& ground_motion_registry();

// The `excitation:` section schema (kind: none | sine_pulse | cosine_pulse | record).
std::shared_ptr<const scene::Schema> excitation_schema();

// Builds the ground motion a resolved `excitation:` section names (throws UserError for a bad record file).
std::unique_ptr<GroundMotion> make_ground_motion(const scene::Node& section, const std::string& scene_dir);

}  // namespace halfeti::excitation
