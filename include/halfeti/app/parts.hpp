// The parts a run is built from: only those the scene names (DESIGN.md principle 2).
#pragma once

#include <memory>
#include <string>

#include "halfeti/core/scene.hpp"
#include "halfeti/excitation/ground_motion.hpp"

namespace halfeti::app {

struct Parts {
  std::string scene_dir;  // anchors relative paths in the scene
  double gravity = 9.81;
  std::unique_ptr<excitation::GroundMotion> motion;
};

}  // namespace halfeti::app
