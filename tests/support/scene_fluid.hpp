// The water of a scene file as the program builds it (app::fluid_params), for the tests that drive sph::Fluid
// directly: the scene in inputs/ stays the one statement of a validation case's parameters, and a test changes
// only what it names, as `--set` does.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "halfeti/app/fluid_section.hpp"
#include "halfeti/app/scene_schema.hpp"
#include "halfeti/core/scene.hpp"

namespace halfeti::test {

// `relative`: a scene path from the repository's root; `sets`: "key=value" overrides. Still-tank scenes only (the
// automatic sound speed is taken with no ground motion).
inline sph::FluidParams scene_fluid_params(const std::string& relative,
                                           const std::vector<std::string>& sets = {}) {
  const scene::Scene s = scene::load_scene(std::string(HALFETI_SOURCE_DIR) + "/" + relative, sets,
                                           *app::scene_schema(), MPI_COMM_WORLD);
  return app::fluid_params(s.root(), 0.0);
}

}  // namespace halfeti::test
