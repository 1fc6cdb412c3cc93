// How big a run is before anything is allocated (what `halfeti check` prints, and what a run refuses when it
// would not fit the machine).
#pragma once

#include <string>

#include "halfeti/app/parts.hpp"
#include "halfeti/core/scene.hpp"

namespace halfeti::app {

// A run's size before anything is allocated: water particles (the blocks' area over dx^2), plate elements and
// dofs, and the memory a rank needs, from figures measured on cosine_cable (README, "The program").
struct SizeEstimate {
  double particles = 0.0;
  long long plate_elements = 0, plate_dofs = 0;
  double bytes_per_rank = 0.0;  // the most loaded rank's: rank 0 (its share of the water and the whole plate)
  double machine_bytes = 0.0;   // this machine's memory (MemTotal), 0 when unknown
  // Steps to the end time (the water's acoustic step cfl h / c0, or the plate's step alone; the flow's own speed
  // only shortens the step further) and the wall time at the rate measured on the build machine (0: no water).
  double steps = 0.0, wall_seconds = 0.0;
  std::string describe() const;
};
// Raises UserError naming the key when a rank would need more memory than `max_memory` bytes (--max-memory), or
// than the machine has when `max_memory` is 0.
SizeEstimate estimate_size(const scene::Scene& scene, const Parts& parts, int ranks, double max_memory = 0.0);

}  // namespace halfeti::app
