#include "halfeti/app/run_size.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::app {

namespace {
// Measured on cosine_cable, 1 rank (peak resident memory at dx 3, 1.5, 0.75 mm: 51.7, 59.5, 88.9 MB for 3,246,
// 13,294, 52,772 particles, since the water's pairs no longer store their separation): about 50 MB of libraries
// and 0.75-0.78 kB per particle (the 1 M particles of inputs/bench/long_tank.yaml: 0.67 kB); a 64 x 4096 Q9 plate
// took 2.6 GB, about 10 kB per element.
constexpr double kBaseBytes = 50e6, kBytesPerParticle = 0.8e3, kBytesPerElement = 10e3;
// Wall time per particle-step on one rank, measured on the build machine: water alone 1.7 us (tank_shake at dx
// 3 mm: 117 s for 20,354 steps of 3,300 particles); with the plate and cables about 2.8 us (cosine_cable at dx
// 1.5 mm: 1,171 s for 62,825 steps of 13,294 particles on 2 ranks). Divided by the ranks (an upper bound on the
// speed-up).
constexpr double kSecondsPerParticleStep = 1.7e-6, kSecondsPerParticleStepCoupled = 2.8e-6;

double machine_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  while (in >> key >> kb) {
    if (key == "MemTotal:") return kb * 1024.0;
    in.ignore(1 << 10, '\n');
  }
  return 0.0;
}
}  // namespace

std::string SizeEstimate::describe() const {
  std::ostringstream os;
  os << "about " << static_cast<long long>(particles) << " particles, " << plate_elements
     << " plate elements (" << plate_dofs << " dofs), " << std::setprecision(3) << bytes_per_rank / 1e9
     << " GB on the busiest rank";
  if (machine_bytes > 0) os << " (this machine has " << machine_bytes / 1e9 << " GB)";
  if (steps > 0) os << "; at least " << static_cast<long long>(std::ceil(steps)) << " steps";
  if (wall_seconds > 0)
    os << ", about " << std::setprecision(2) << wall_seconds << " s of wall time at the build machine's rate";
  return os.str();
}

SizeEstimate estimate_size(const scene::Scene& scene, const Parts& parts, int ranks, double max_memory) {
  SizeEstimate e;
  if (parts.fluid_params) {
    const auto& f = *parts.fluid_params;
    for (const auto& b : f.water)
      e.particles += (b.x1 - b.x0) * (b.y1 + std::abs(b.surface_amplitude) - b.y0) / (f.spacing * f.spacing);
  }
  if (parts.structure_setup) {
    const auto& g = parts.structure_setup->params.geometry;
    e.plate_elements = static_cast<long long>(g.cells_across) * g.cells_along;
    const long long per_side = g.element == structure::ElementType::kQ9 ? 2 : 1;
    e.plate_dofs = 2 * (per_side * g.cells_across + 1) * (per_side * g.cells_along + 1);
  }
  const double end = scene.root().section("scene").real("end_time");
  if (parts.fluid_params) {
    const auto& f = *parts.fluid_params;
    double dt = f.cfl * f.h_over_dx * f.spacing / sph::resolved_sound_speed(f);
    if (f.max_dt > 0.0) dt = std::min(dt, f.max_dt);
    e.steps = end / dt;
    e.wall_seconds = e.particles * e.steps *
                     (parts.structure_setup ? kSecondsPerParticleStepCoupled : kSecondsPerParticleStep) /
                     std::max(1, ranks);
  } else if (parts.structure_setup) {
    e.steps = end / parts.structure_setup->time_step;
  }
  e.bytes_per_rank = kBaseBytes + kBytesPerParticle * e.particles / std::max(1, ranks) +
                     kBytesPerElement * static_cast<double>(e.plate_elements);
  e.machine_bytes = machine_memory();
  const double limit = max_memory > 0.0 ? max_memory : e.machine_bytes;
  if (limit > 0 && e.bytes_per_rank > limit) {
    // The key of the part that takes most of it.
    const bool water =
        kBytesPerParticle * e.particles > kBytesPerElement * static_cast<double>(e.plate_elements);
    HALFETI_USER_ERROR(
        scene.file << ": " << (water ? "fluid.spacing" : "structure.cells_along") << ": the run would need "
                   << e.describe() << " on " << ranks << " rank(s), above "
                   << (max_memory > 0.0 ? "--max-memory " : "this machine's ") << std::setprecision(3)
                   << limit / 1e9 << " GB; coarsen it or run on more ranks");
  }
  return e;
}

}  // namespace halfeti::app
