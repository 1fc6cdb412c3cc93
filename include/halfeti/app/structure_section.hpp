// The scene's `structure:` (the rubber plate) and `cables:` sections, mapped onto the structure and cable
// modules' parameters.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "halfeti/cable/cable_set.hpp"
#include "halfeti/core/scene.hpp"
#include "halfeti/structure/plate_solver.hpp"

namespace halfeti::app {

std::shared_ptr<const scene::Schema> structure_schema();
std::shared_ptr<const scene::Schema> cable_schema();

struct PointLoad {
  std::string node;
  Eigen::Vector2d force;  // N/m
};

struct StructureSetup {
  structure::StructureParameters params;
  double time_step = 0.0;  // s, used when the scene has no fluid
  std::vector<PointLoad> point_loads;
  bool start_static = false;  // solve the static equilibrium (gravity, cables, loads) before the first step
  int ranks = 1;              // the structure's communicator: the first `ranks` world ranks (1 with water)
};

// One cable set between a wall anchor and a named plate node.
struct CableSetup {
  std::string name;
  Eigen::Vector2d anchor;
  std::string node;
  cable::CableSet set;
  double unstretched_length = 0.0;  // resolved: given, or found from the initial stress
  double initial_stress = 0.0;      // given (0: the length was given)
};

StructureSetup structure_setup(const scene::Node& root);

// Resolves every cable, including the unstretched length for an initial stress (at the undeformed plate).
// `fluid_density` > 0 makes submerged cables buoyant.
std::vector<CableSetup> cable_setups(const scene::Node& root, const StructureSetup& plate,
                                     double fluid_density);

}  // namespace halfeti::app
