// The parts a run is built from: only those the scene names (DESIGN.md principle 2). `check` fills in the
// parameters (which cross-checks the scene); `run` also builds the parts themselves.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "halfeti/core/scene.hpp"
#include "halfeti/excitation/ground_motion.hpp"
#include "halfeti/sph/fluid.hpp"
#include "halfeti/sph/params.hpp"

namespace halfeti::app {

struct Parts {
  std::string scene_dir;  // anchors relative paths in the scene
  double gravity = 9.81;
  std::unique_ptr<excitation::GroundMotion> motion;

  std::optional<sph::FluidParams> fluid_params;  // the scene has `fluid:`
  std::unique_ptr<sph::Fluid> fluid;             // built for a run

  // Throws UserError naming `who` when the scene has no fluid.
  const sph::FluidParams& require_fluid(const std::string& who) const;
};

}  // namespace halfeti::app
