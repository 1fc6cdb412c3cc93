// inputs/validation/plate_cables.yaml through the program: the scene starts at the paper's 135 kPa in both cables,
// symmetric, and the pulse then loads one cable and unloads the other.
#include <gtest/gtest.h>

#include <algorithm>

#include "halfeti/io/checkpoint.hpp"
#include "run_scene.hpp"

using namespace halfeti;

TEST(PlateCablesScene, StartsAt135kPaAndThePulseLoadsOneCable) {
  const std::string out = test::binary_path("validation_plate_cables_scene");
  ASSERT_EQ(test::run_scene(test::source_path("inputs/validation/plate_cables.yaml"), out,
                            "--set scene.end_time=0.1 --set output.field_interval=0"),
            0)
      << test::read_text(out + ".stderr");
  const auto probes = io::read_probe_csv(out + "/probes.csv");
  const auto left = probes.column("left_stress"), right = probes.column("right_stress");
  // The static start keeps 135 kPa within the plate's axial give (0.1%, docs/plate-cables.md), both sides alike.
  EXPECT_NEAR(left[0], 135e3, 0.005 * 135e3);
  EXPECT_DOUBLE_EQ(left[0], right[0]);
  // The cosine pulse pushes the tank to +x: in its frame the plate leans to -x, the right cable tightens.
  const auto tip = probes.column("tip_x");
  EXPECT_LT(*std::min_element(tip.begin(), tip.end()), -1e-6);
  EXPECT_GT(*std::max_element(right.begin(), right.end()), right[0]);
  EXPECT_LT(*std::min_element(left.begin(), left.end()), left[0]);
  EXPECT_NE(test::read_text(out + "/summary.json").find("\"exit_status\": \"ok\""), std::string::npos);
}

TEST(PlateCablesScene, ANewtonFailureStopsEveryRankWithACheckpoint) {
  // One Newton iteration cannot reach the pretensioned equilibrium: the run must stop on both ranks (no hang),
  // with exit status 3, one line on stderr, a checkpoint and summary.json saying so.
  const std::string out = test::binary_path("validation_plate_cables_failure");
  const int status = test::run_scene(test::source_path("inputs/validation/plate_cables.yaml"), out,
                                     "--set structure.newton_max_iterations=1 --set scene.end_time=0.05", 2);
  EXPECT_EQ(status, 3);
  const std::string err = test::read_text(out + ".stderr");
  EXPECT_NE(err.find("halfeti: error: structure: Newton did not converge in 1 iterations"), std::string::npos)
      << err;
  // The pretensioned equilibrium is the static start's: said so, not as a time (it once read "t = -1 s").
  EXPECT_NE(err.find("in the static start, the tank at rest before t = 0"), std::string::npos) << err;
  EXPECT_EQ(err.find("t = -1"), std::string::npos) << err;
  EXPECT_NE(test::read_text(out + "/summary.json").find("\"exit_status\": \"numerical_failure\""),
            std::string::npos);
  const auto checkpoints = io::list_checkpoints(out + "/checkpoints");
  ASSERT_EQ(checkpoints.size(), 1u);
  EXPECT_EQ(io::read_checkpoint(checkpoints[0]).steps, 0);  // before the first step
}
