// inputs/validation/hydrostatic_corner.yaml through the program: in still water the pressure probes at the
// floor-wall corners and half a spacing from the floor and the walls read rho g (d - y) within 1 % (issue #20's bar)
// over 0.25-0.5 s (the start's settling past), as does the middle of the floor at the same heights. The probe is the
// first-order (MLS) interpolation, exact for the linear hydrostatic field where the kernel is cut by the walls; what
// is left is the particles' own pressure there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "run_scene.hpp"

using namespace halfeti;

TEST(HydrostaticCorner, CornerProbesReadHydrostaticWithinOnePercent) {
  const std::string scene = test::source_path("inputs/validation/hydrostatic_corner.yaml");
  const std::string out = test::binary_path("validation_hydrostatic_corner");
  ASSERT_EQ(test::run_scene(scene, out, "", 2), 0) << test::read_text(out + ".stderr");
  const auto probes = io::read_probe_csv(out + "/probes.csv");
  const auto t = probes.column("t");
  const double half_dx = 0.00075, depth = 0.10, rho_g = 1000.0 * 9.81;
  for (const auto& [name, y] : {std::pair{"left_corner", 0.0}, std::pair{"left_corner_half_dx", half_dx},
                                std::pair{"left_wall_half_dx", half_dx}, std::pair{"right_corner", 0.0},
                                std::pair{"right_corner_half_dx", half_dx}, std::pair{"floor_middle", 0.0},
                                std::pair{"floor_middle_half_dx", half_dx}}) {
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
