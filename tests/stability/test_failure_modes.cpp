// Each failure the atlas maps (docs/stability.md) is detected by a named monitor, with its cause, before a NaN
// reaches an output; warnings are seen as they happen (stderr, log.txt), tallied in summary.json and in the run's
// status and last line; a failure's checkpoint and summary carry the failed step's time.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "halfeti/io/checkpoint.hpp"
#include "run_scene.hpp"

using namespace halfeti;

namespace {

std::string scene(const std::string& name) {
  return test::source_path("inputs/stability/" + name + ".yaml");
}

// The text of one member of summary.json's top level (its value up to the next top-level member).
std::string member(const std::string& summary, const std::string& key) {
  const std::size_t at = summary.find("\n  \"" + key + "\": ");
  if (at == std::string::npos) return "";
  const std::size_t end = summary.find("\n  \"", at + 1);
  return summary.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(FailureModes, ACableGoingSlackAndSnappingTautIsWarnedAndItsSnapLoadKept) {
  const std::string out = test::binary_path("stability_cable_snap");
  ASSERT_EQ(test::run_scene(scene("cable_snap"), out, "--set scene.end_time=0.3"), 0)
      << test::read_text(out + ".stderr");
  const std::string err = test::read_text(out + ".stderr"), log = test::read_text(out + "/log.txt");
  // Both cables start 0.5 % longer than their chords: slack at the first step, said on stderr and in the log.
  EXPECT_NE(err.find("warning: t = 0.0003 s, step 1: cable 'left' went slack"), std::string::npos) << err;
  EXPECT_NE(log.find("warning: t = 0.0003 s, step 1: cable 'left' went slack"), std::string::npos) << log;
  EXPECT_NE(err.find("taut again after"), std::string::npos) << err;
  const std::string summary = test::read_text(out + "/summary.json");
  EXPECT_NE(summary.find("\"exit_status\": \"ok_with_warnings\""), std::string::npos);
  const std::string health = member(summary, "health");
  EXPECT_NE(health.find("\"cable_slack\": {"), std::string::npos) << health;
  ASSERT_NE(health.find("\"cable_snap\": {"), std::string::npos) << health;
  // The snap load: the largest stress of one cable while taut again, a positive number of Pa, with its place
  // (the plate's top corner, 0.08 m up) and time.
  const std::string snap = health.substr(health.find("\"cable_snap\": {"));
  const double worst = std::stod(snap.substr(snap.find("\"worst\": ") + 9));
  EXPECT_GT(worst, 1e3);
  const std::string at = snap.substr(snap.find("\"worst_at\": [") + 13);
  EXPECT_NEAR(std::stod(at.substr(at.find(',') + 1)), 0.08, 0.005) << at;
  // The last line counts the warnings by kind.
  EXPECT_NE(log.find("warnings (cable_slack "), std::string::npos) << log;
  // At most RunHealth::kPrinted (3) episodes of a kind are printed, then one line says the rest are counted.
  EXPECT_LE(count(err, "went slack"), 3u);
}

TEST(FailureModes, TheHealthTallyOfARestartedRunIsThatOfOneThatNeverStopped) {
  const std::string whole = test::binary_path("stability_snap_whole"),
                    legs = test::binary_path("stability_snap_legs");
  ASSERT_EQ(test::run_scene(scene("cable_snap"), whole, "--set scene.end_time=0.3"), 0);
  ASSERT_EQ(test::run_scene(scene("cable_snap"), legs, "--set scene.end_time=0.15"), 0);
  ASSERT_EQ(test::run_scene(scene("cable_snap"), legs, "--set scene.end_time=0.3 --restart " + legs), 0)
      << test::read_text(legs + ".stderr");
  const std::string a = test::read_text(whole + "/summary.json"), b = test::read_text(legs + "/summary.json");
  EXPECT_FALSE(member(a, "health").empty());
  EXPECT_EQ(member(a, "health"), member(b, "health"));
  EXPECT_EQ(member(a, "health_events"), member(b, "health_events"));
  // The continued run does not say again what the first leg said.
  EXPECT_EQ(test::read_text(legs + ".stderr").find("step 1: cable 'left' went slack"), std::string::npos);
}

TEST(FailureModes, AStepPastTheStabilityLimitStopsAtTheFailedStepWithItsTimeInTheCheckpoint) {
  // fluid.cfl = 2: twice the explicit step's limit. A particle leaves the tank within a few steps; the run says so
  // (exit 3, the monitor's message), before a NaN reaches probes.csv, and the checkpoint and summary.json carry the
  // failed step's time and number, those in the message.
  const std::string out = test::binary_path("stability_cfl");
  ASSERT_EQ(
      test::run_scene(scene("tank_shake"), out, "--set fluid.cfl=2.0 --set output.probe_interval=0.0001"), 3);
  const std::string err = test::read_text(out + ".stderr");
  EXPECT_NE(err.find("warning: fluid.cfl = 2 is past the explicit step's usual stability limit"),
            std::string::npos);
  const std::size_t at = err.find("halfeti: error: t = ");
  ASSERT_NE(at, std::string::npos) << err;
  EXPECT_NE(err.find("left the tank through a wall", at), std::string::npos) << err;
  const long long step = std::stoll(err.substr(err.find("step ", at) + 5));
  const double t = std::stod(err.substr(at + 20));
  const auto checkpoints = io::list_checkpoints(out + "/checkpoints");
  ASSERT_EQ(checkpoints.size(), 1u);
  const io::Checkpoint c = io::read_checkpoint(checkpoints[0]);
  EXPECT_EQ(c.steps, step);
  EXPECT_NEAR(c.time, t, 5e-5);  // the message prints 4 decimals
  const std::string summary = test::read_text(out + "/summary.json");
  EXPECT_NE(summary.find("\"exit_status\": \"numerical_failure\""), std::string::npos);
  EXPECT_NE(summary.find("\"steps\": " + std::to_string(step) + ","), std::string::npos) << summary;
  EXPECT_NE(member(summary, "health").find("\"outside_tank\": {"), std::string::npos);
  const std::string probes = test::read_text(out + "/probes.csv");
  EXPECT_EQ(probes.find("nan"), std::string::npos);
  EXPECT_EQ(probes.find("inf"), std::string::npos);
}

TEST(FailureModes, TheTensileInstabilityIsFoundByTheSpacingMonitorWithItsPlace) {
  // Standard SPH without Monaghan's correction under the paper's pulse: particles clump (docs/stability.md: from
  // 0.175 s on, to 0.0007 dx); the monitor warns, and summary.json keeps the closest pair (in dx) and where it was.
  const std::string out = test::binary_path("stability_tensile");
  ASSERT_EQ(test::run_scene(
                scene("tank_shake"), out,
                "--set fluid.scheme=standard --set fluid.tensile_correction=false --set scene.end_time=0.25"),
            0)
      << test::read_text(out + ".stderr");
  EXPECT_NE(test::read_text(out + ".stderr").find("spacing collapse, tensile instability"),
            std::string::npos);
  const std::string health = member(test::read_text(out + "/summary.json"), "health");
  const std::size_t at = health.find("\"spacing_collapse\": {");
  ASSERT_NE(at, std::string::npos) << health;
  const std::string kind = health.substr(at);
  EXPECT_LT(std::stod(kind.substr(kind.find("\"worst\": ") + 9)), 0.2);  // below the monitor's 0.2 dx
  const std::string place = kind.substr(kind.find("\"worst_at\": [") + 13);
  const double x = std::stod(place), y = std::stod(place.substr(place.find(',') + 1));
  EXPECT_TRUE(x >= 0.0 && x <= 0.30 && y >= 0.0 && y <= 0.40) << place;
}

TEST(FailureModes, TheAddedMassInstabilityOfTheTrapezoidalRuleStopsTheCoupledRunNamingTheCoupling) {
  // The paper's light plate with the trapezoidal rule and no interface added mass: the explicit exchange's
  // added-mass instability (docs/stability.md: it fails at 0.016 s) stops the run as a coupling failure, with
  // a checkpoint, before a NaN reaches probes.csv; with the acoustic added mass the same step is passed.
  const std::string sets =
      "--set structure.newmark_gamma=0.5 --set structure.newmark_beta=0.25 --set scene.end_time=0.05";
  const std::string out = test::binary_path("stability_added_mass");
  ASSERT_EQ(test::run_scene(scene("plate_pulse"), out, sets + " --set coupling.added_mass=none"), 3);
  const std::string summary = test::read_text(out + "/summary.json");
  const std::string health = member(summary, "health");
  EXPECT_NE(health.find("\"coupling_failure\": {"), std::string::npos) << health;
  EXPECT_NE(summary.find("\"exit_status\": \"numerical_failure\""), std::string::npos);
  EXPECT_EQ(io::list_checkpoints(out + "/checkpoints").size(), 1u);
  const std::string probes = test::read_text(out + "/probes.csv");
  EXPECT_EQ(probes.find("nan"), std::string::npos);
  const std::string stable = test::binary_path("stability_added_mass_acoustic");
  EXPECT_EQ(test::run_scene(scene("plate_pulse"), stable, sets + " --set scene.end_time=0.03"), 0)
      << test::read_text(stable + ".stderr");
}
