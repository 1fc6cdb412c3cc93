// The paper's tank with its water alone (0.30 m long, 0.40 m tall, 0.10 m of still water), for the water's tests
// under the tank's motion.
#pragma once

#include "halfeti/sph/params.hpp"

namespace halfeti::test {

inline constexpr double kPaperTankLength = 0.30, kPaperWaterDepth = 0.10;

// Still water at spacing dx; `peak_acceleration` sets the automatic c0 (eq. 10) as a scene's excitation would.
inline sph::FluidParams paper_tank_water(double dx, double peak_acceleration) {
  sph::FluidParams p;
  p.tank_length = kPaperTankLength;
  p.tank_height = 0.40;
  p.spacing = dx;
  p.water = {{0.0, 0.0, kPaperTankLength, kPaperWaterDepth, 0.0}};
  p.peak_ground_acceleration = peak_acceleration;
  return p;
}

}  // namespace halfeti::test
