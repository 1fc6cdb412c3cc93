// The water's particle state as plain arrays (one entry per particle): what a checkpoint holds and what the fluid
// is distributed from, at the start and at a restart.
#pragma once

#include <cstdint>
#include <vector>

namespace halfeti {

struct ParticleArrays {
  std::vector<std::int64_t> gid;
  std::vector<double> x, y, vx, vy, rho, mass;
};

}  // namespace halfeti
