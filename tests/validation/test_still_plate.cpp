// inputs/validation/still_plate.yaml through the program: still water around the submerged plate stays still.
// Acceptance (docs/coupling.md, "Still water around the plate"): tip displacement < 0.1 % of the plate's height,
// no particle inside the plate (the coupling's health check: the run would stop with exit status 3), pressure 2 mm
// from the plate within a tolerance of rho g (d - y), as a time mean over the second half of the run.
// STILL_PLATE_FULL selects the full scene (dx 1.5 mm, 2 s; label validation); otherwise a coarse short run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "run_scene.hpp"

using namespace halfeti;

namespace {
double mean_over_second_half(const std::vector<double>& v) {
  double s = 0.0;
  const std::size_t first = v.size() / 2;
  for (std::size_t k = first; k < v.size(); ++k) s += v[k];
  return s / static_cast<double>(v.size() - first);
}
}  // namespace

TEST(StillPlate, WaterAndPlateStayStill) {
#ifdef STILL_PLATE_FULL
  const std::string out = test::binary_path("validation_still_plate_full");
  const std::string args = "--set output.field_interval=0";
  const double pressure_tolerance = 0.02;
#else
  const std::string out = test::binary_path("validation_still_plate");
  // The paper's dx (the water lattice then starts half a spacing from both faces, as the wall ghosts assume; at dx
  // 2 or 3 mm it starts 0.75 or 1 spacing away and the first row's pressure is 20-100 % off), 30 ms.
  const std::string args = "--set scene.end_time=0.03 --set output.field_interval=0";
  const double pressure_tolerance = 0.04;  // the start's acoustic ringing is not yet damped
#endif
  ASSERT_EQ(test::run_scene(test::source_path("inputs/validation/still_plate.yaml"), out, args, 2), 0)
      << test::read_text(out + ".stderr");
  const auto probes = io::read_probe_csv(out + "/probes.csv");
  const auto tip = probes.column("tip_x");
  double worst = 0.0;
  for (double u : tip) worst = std::max(worst, std::abs(u));
  EXPECT_LT(worst, 0.001 * 0.08) << "tip displacement";
  const double rho_g = 1000.0 * 9.81, depth = 0.10;
  for (const char* side : {"left", "right"})
    for (int mm : {20, 40, 60}) {
      const std::string name = std::string("p_") + side + "_" + std::to_string(mm) + "mm";
      const double expected = rho_g * (depth - mm * 1e-3);
      EXPECT_NEAR(mean_over_second_half(probes.column(name)), expected, pressure_tolerance * expected)
          << name;
    }
  EXPECT_NE(test::read_text(out + "/summary.json").find("\"exit_status\": \"ok\""), std::string::npos);
}
