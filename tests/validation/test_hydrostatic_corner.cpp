// inputs/validation/hydrostatic_corner.yaml through the program: in still water the pressure probes at the
// floor-wall corners and half a spacing from the floor and the walls read rho g (d - y) within 1 % (issue #20's bar)
// over 0.25-0.5 s (the start's settling past), as does the middle of the floor at the same heights. The probe is the
// first-order (MLS) interpolation, exact for the linear hydrostatic field where the kernel is cut by the walls; what
// is left is the particles' own pressure there. The same at the plate's foot (inputs/validation/still_plate.yaml, its
// first 0.5 s): where the plate's faces meet the floor, and half a spacing from face and floor.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "run_scene.hpp"

using namespace halfeti;

namespace {
constexpr double kHalfDx = 0.00075;  // half the scenes' 1.5 mm spacing

// Each probe's mean over 0.25-0.5 s against rho g (d - y), within 1 %.
void expect_hydrostatic(const std::string& out,
                        const std::vector<std::pair<const char*, double>>& probes_at) {
  const auto probes = io::read_probe_csv(out + "/probes.csv");
  const auto t = probes.column("t");
  const double depth = 0.10, rho_g = 1000.0 * 9.81;
  for (const auto& [name, y] : probes_at) {
    const auto p = probes.column(name);
    double sum = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] >= 0.25) {
        sum += p[k];
        ++n;
      }
    ASSERT_GT(n, 10);
    const double mean = sum / n, hydrostatic = rho_g * (depth - y);
    std::printf("%-22s %7.1f Pa against %7.1f Pa: %+.2f %%\n", name, mean, hydrostatic,
                100.0 * (mean - hydrostatic) / hydrostatic);
    EXPECT_NEAR(mean, hydrostatic, 0.01 * hydrostatic) << name;
  }
}
}  // namespace

TEST(HydrostaticCorner, CornerProbesReadHydrostaticWithinOnePercent) {
  const std::string scene = test::source_path("inputs/validation/hydrostatic_corner.yaml");
  const std::string out = test::binary_path("validation_hydrostatic_corner");
  ASSERT_EQ(test::run_scene(scene, out, "", 2), 0) << test::read_text(out + ".stderr");
  expect_hydrostatic(out, {{"left_corner", 0.0},
                           {"left_corner_half_dx", kHalfDx},
                           {"left_wall_half_dx", kHalfDx},
                           {"right_corner", 0.0},
                           {"right_corner_half_dx", kHalfDx},
                           {"floor_middle", 0.0},
                           {"floor_middle_half_dx", kHalfDx}});
}

TEST(HydrostaticCorner, ThePlatesFootReadsHydrostaticWithinOnePercent) {
  const std::string scene = test::source_path("inputs/validation/still_plate.yaml");
  const std::string out = test::binary_path("validation_hydrostatic_foot");
  ASSERT_EQ(test::run_scene(scene, out, "--set scene.end_time=0.5 --set output.field_interval=0", 2), 0)
      << test::read_text(out + ".stderr");
  expect_hydrostatic(out, {{"foot_left", 0.0},
                           {"foot_left_half_dx", kHalfDx},
                           {"foot_right", 0.0},
                           {"foot_right_half_dx", kHalfDx}});
}
