// Restart from a checkpoint through the program (mpirun, as a user runs it): a run stopped at some step and continued
// with --restart is bit for bit the run that never stopped, on the same rank count and on another (1 -> 2, 3 -> 1,
// 4 -> 2), for the water alone and for the coupled paper scene with cables (and for the dam break onto the plate
// with the free-surface mark, 3 -> 1); the stops a cluster job meets (a
// signal, --max-wall) leave a checkpoint and a summary that say so; a restart that would change the physics, a
// folder that holds another run, a file that is no checkpoint are one clear error each; a full disk is an I/O error
// (exit status 6) naming the file and the reason, with no half-written file left. A restarted run's summary counts
// the CPU seconds of the legs before it (null from a checkpoint of the earlier layout, which still continues).
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

#include "halfeti/io/checkpoint.hpp"
#include "halfeti/io/probe_writer.hpp"
#include "run_scene.hpp"

using namespace halfeti;

namespace {

struct Case {
  std::string scene, args;
  double end, middle;  // s: the run's end, and where the first leg of a restarted run stops
};

// The water alone: the Martin & Moyce dam break at a / 12.5 (about 300 particles), through the surge's impact.
const Case kWater{
    test::source_path("inputs/validation/dambreak.yaml"),
    "--set fluid.spacing=0.004572 --set output.field_interval=0.05 --set output.checkpoint_keep=0", 0.2, 0.1};
// The paper's rubber plate with two cable sets under the cosine pulse, water at dx = 6 mm (837 particles).
const Case kCoupled{
    test::source_path("inputs/paper/cosine_cable.yaml"),
    "--set fluid.spacing=0.006 --set output.field_interval=0.05 --set output.checkpoint_keep=0", 0.1, 0.05};

// The same with the plate-water exchange converged within each step and the trapezoidal rule (docs/coupling.md,
// section 16): a step repeated from its saved start, and the forces of the next step computed at this one's end.
const Case kImplicit{kCoupled.scene,
                     kCoupled.args +
                         " --set coupling.plate_wall_exchange=implicit --set coupling.added_mass=none"
                         " --set structure.newmark_gamma=0.5 --set structure.newmark_beta=0.25",
                     0.1, 0.05};

// The same with the Q4 enhanced-strain plate: its elements' enhanced parameters are state the checkpoint carries.
const Case kQ4Eas{kCoupled.scene, kCoupled.args + " --set structure.element=q4_eas", kCoupled.end,
                  kCoupled.middle};

// The dam break onto the plate at L/40 with water that has left a face meeting it as a free surface
// (coupling.plate_wall_free_surface, docs/coupling.md section 21; c0 100 m/s, where it runs the explicit exchange):
// particles are marked at 0.126-0.129, 0.132 and 0.139-0.141 s, on both sides of the restart.
const Case kFreeSurface{test::source_path("inputs/validation/dambreak_plate.yaml"),
                        "--set fluid.sound_speed=100 --set coupling.plate_wall_free_surface=true"
                        " --set output.field_interval=0 --set output.checkpoint_keep=0",
                        0.14, 0.128};

std::string end_time(double t) {
  return " --set scene.end_time=" + std::to_string(t);
}

std::string latest(const std::string& run) {
  const auto all = io::list_checkpoints(run + "/checkpoints");
  return all.empty() ? std::string() : all.back();
}

// Every number of the two checkpoints agrees bit for bit: the particles (matched by global id), the parts' state
// and the health log; only the wall and CPU seconds spent so far (the run block's last two entries) may differ.
void expect_same_state(const std::string& a, const std::string& b) {
  ASSERT_FALSE(a.empty());
  ASSERT_FALSE(b.empty());
  const io::Checkpoint x = io::read_checkpoint(a), y = io::read_checkpoint(b);
  EXPECT_EQ(x.steps, y.steps);
  EXPECT_EQ(x.time, y.time);
  const auto order = [](const std::vector<std::int64_t>& gid) {
    std::vector<std::size_t> o(gid.size());
    std::iota(o.begin(), o.end(), 0);
    std::sort(o.begin(), o.end(), [&](std::size_t i, std::size_t j) { return gid[i] < gid[j]; });
    return o;
  };
  const auto ox = order(x.particles.gid), oy = order(y.particles.gid);
  ASSERT_EQ(ox.size(), oy.size());
  const std::pair<const std::vector<double>*, const std::vector<double>*> fields[] = {
      {&x.particles.x, &y.particles.x},     {&x.particles.y, &y.particles.y},
      {&x.particles.vx, &y.particles.vx},   {&x.particles.vy, &y.particles.vy},
      {&x.particles.rho, &y.particles.rho}, {&x.particles.mass, &y.particles.mass}};
  int differing = 0;
  for (std::size_t k = 0; k < ox.size(); ++k) {
    EXPECT_EQ(x.particles.gid[ox[k]], y.particles.gid[oy[k]]);
    for (const auto& [fx, fy] : fields) differing += (*fx)[ox[k]] != (*fy)[oy[k]];
  }
  EXPECT_EQ(differing, 0) << "particle values differ between " << a << " and " << b;
  ASSERT_EQ(x.blocks.size(), y.blocks.size());
  for (const auto& [name, values] : x.blocks) {
    const auto it = y.blocks.find(name);
    ASSERT_NE(it, y.blocks.end()) << name;
    std::vector<double> u = values, v = it->second;
    if (name == "run") u.resize(u.size() - 2), v.resize(v.size() - 2);  // the wall and CPU seconds
    EXPECT_EQ(u, v) << "block " << name;
  }
  for (const char* text : {"health_log", "active_warnings"}) {
    const auto ix = x.texts.find(text), iy = y.texts.find(text);
    EXPECT_EQ(ix == x.texts.end(), iy == y.texts.end()) << text;
    if (ix != x.texts.end() && iy != y.texts.end()) {
      EXPECT_EQ(ix->second, iy->second) << text;
    }
  }
}

// The reference run (np 2, never stopped), then for each rank pair a first leg to the middle and a second leg from
// its checkpoint, into another folder, to the end.
void expect_restarts_bit_for_bit(const Case& c, const std::string& name,
                                 const std::vector<std::pair<int, int>>& rank_pairs = {
                                     {1, 2}, {3, 1}, {4, 2}}) {
  const std::string ref = test::binary_path("restart_" + name + "_ref");
  ASSERT_EQ(test::run_scene(c.scene, ref, c.args + end_time(c.end), 2), 0)
      << test::read_text(ref + ".stderr");
  for (const auto& [first, second] : rank_pairs) {
    const std::string tag = name + "_" + std::to_string(first) + "to" + std::to_string(second);
    const std::string leg1 = test::binary_path("restart_" + tag + "_a"),
                      leg2 = test::binary_path("restart_" + tag + "_b");
    ASSERT_EQ(test::run_scene(c.scene, leg1, c.args + end_time(c.middle), first), 0)
        << test::read_text(leg1 + ".stderr");
    ASSERT_EQ(test::run_scene(c.scene, leg2, c.args + end_time(c.end) + " --restart " + leg1, second), 0)
        << test::read_text(leg2 + ".stderr");
    SCOPED_TRACE(tag);
    expect_same_state(latest(ref), latest(leg2));
    // probes.csv: the rows before the checkpoint carried from the first leg's folder, the rest written anew.
    EXPECT_EQ(test::read_text(leg2 + "/probes.csv"), test::read_text(ref + "/probes.csv"));
    EXPECT_NE(test::read_text(leg2 + "/summary.json").find("\"restarted_from\": \"" + latest(leg1)),
              std::string::npos);
  }
}

// The text of summary.json after `"name": ` (its value and what follows), "" when the key is missing.
std::string summary_value(const std::string& run, const std::string& name) {
  const std::string s = test::read_text(run + "/summary.json"), key = "\"" + name + "\": ";
  const auto at = s.find(key);
  return at == std::string::npos ? std::string() : s.substr(at + key.size());
}

std::string summary_status(const std::string& run) {
  const std::string v = summary_value(run, "exit_status");
  if (v.empty()) return "(none)";
  return v.substr(1, v.find('"', 1) - 1);
}

// summary.json's cost.earlier_cpu_seconds: the CPU seconds of the runs a restarted run continues (NaN for null).
double earlier_cpu_seconds(const std::string& run) {
  const std::string v = summary_value(run, "earlier_cpu_seconds");
  if (v.empty()) return -1.0;
  if (v.compare(0, 4, "null") == 0) return std::numeric_limits<double>::quiet_NaN();
  return std::stod(v);
}

// An integer of summary.json's top level (steps, steps_this_run); -1 when it is missing.
long long summary_integer(const std::string& run, const std::string& name) {
  const std::string v = summary_value(run, name);
  return v.empty() ? -1 : std::stoll(v);
}

}  // namespace

TEST(Restart, WaterAloneContinuesBitForBitOnOtherRankCounts) {
  expect_restarts_bit_for_bit(kWater, "water");
}

TEST(Restart, CoupledSceneWithCablesContinuesBitForBitOnOtherRankCounts) {
  expect_restarts_bit_for_bit(kCoupled, "coupled");
}

TEST(Restart, EnhancedStrainPlateContinuesBitForBitOnOtherRankCounts) {
  expect_restarts_bit_for_bit(kQ4Eas, "q4_eas", {{3, 1}});
}

TEST(Restart, ConvergedExchangeContinuesBitForBitOnOtherRankCounts) {
  expect_restarts_bit_for_bit(kImplicit, "implicit");
  // It iterated: more than one evaluation of the water's load in some step.
  const std::string s = test::read_text(test::binary_path("restart_implicit_ref") + "/summary.json");
  const auto at = s.find("\"most_in_a_step\": ");
  ASSERT_NE(at, std::string::npos) << "summary.json has no exchange counts";
  EXPECT_GT(std::stoi(s.substr(at + 18)), 1);
}

TEST(Restart, PlateFreeSurfaceMarkContinuesBitForBitOnOtherRankCounts) {
  // One pair (3 ranks, then 1, against 2): the scene is 3,200 particles for 13,000 steps.
  expect_restarts_bit_for_bit(kFreeSurface, "free_surface", {{3, 1}});
  // The mark acted, before and after the restart.
  const auto probes = io::read_probe_csv(test::binary_path("restart_free_surface_ref") + "/probes.csv");
  const auto t = probes.column("t"), marked = probes.column("plate_free_surface");
  int before = 0, after = 0;
  for (std::size_t k = 0; k < t.size(); ++k) (t[k] < kFreeSurface.middle ? before : after) += marked[k] > 0.0;
  EXPECT_GT(before, 0);
  EXPECT_GT(after, 0);
}

TEST(Restart, MaxWallStopsResumablyAndTheRunContinuesInItsOwnFolder) {
  // --max-wall far below one step's cost stops the run after its first step: exit status 5, a checkpoint, the
  // summary "stopped". Continued twice in the same folder (the second leg stopped the same way), the run ends as
  // the one that never stopped: its state, its probes.csv and its field series.
  const Case& c = kCoupled;
  const std::string ref = test::binary_path("restart_wall_ref"), run = test::binary_path("restart_wall");
  ASSERT_EQ(test::run_scene(c.scene, ref, c.args + end_time(c.end), 2), 0)
      << test::read_text(ref + ".stderr");
  ASSERT_EQ(test::run_scene(c.scene, run, c.args + end_time(c.end) + " --max-wall 1e-6", 2), 5)
      << test::read_text(run + ".stderr");
  EXPECT_EQ(summary_status(run), "stopped");
  EXPECT_EQ(earlier_cpu_seconds(ref), 0.0);  // a run that continues none
  EXPECT_GT(summary_integer(ref, "steps"), 1);
  EXPECT_EQ(summary_integer(ref, "steps_this_run"), summary_integer(ref, "steps"));
  EXPECT_EQ(summary_integer(run, "steps_this_run"), summary_integer(run, "steps"));
  // The checkpoint records the CPU seconds the two ranks spent so far (start-up and one step: more than nothing).
  const io::Checkpoint first = io::read_checkpoint(latest(run));
  ASSERT_EQ(first.blocks.at("run").size(), 6u);
  const double cpu_first = first.blocks.at("run")[5];
  EXPECT_GT(cpu_first, 0.0);
  const std::string log = test::read_text(run + "/log.txt");
  EXPECT_NE(log.find("stopped: the wall-time limit (--max-wall 1e-06 s) at t = "), std::string::npos) << log;
  EXPECT_NE(log.find("continue with: halfeti run"), std::string::npos) << log;
  ASSERT_EQ(test::run_scene(c.scene, run, c.args + end_time(c.end) + " --max-wall 1e-6 --restart " + run, 2),
            5)
      << test::read_text(run + ".stderr");
  const long long steps_before = io::read_checkpoint(latest(run)).steps;
  ASSERT_EQ(test::run_scene(c.scene, run, c.args + end_time(c.end) + " --restart " + run, 1), 0)
      << test::read_text(run + ".stderr");
  EXPECT_EQ(summary_status(run), "ok");
  // Its steps are the whole run's; steps_this_run, which its wall time and timers count, the last leg's.
  EXPECT_EQ(summary_integer(run, "steps"), summary_integer(ref, "steps"));
  EXPECT_EQ(summary_integer(run, "steps_this_run"), summary_integer(ref, "steps") - steps_before);
  EXPECT_GT(steps_before, 0);
  // The last leg's summary counts the CPU seconds of the two legs before it: at least the first leg's.
  EXPECT_GE(earlier_cpu_seconds(run), cpu_first);
  expect_same_state(latest(ref), latest(run));
  EXPECT_EQ(test::read_text(run + "/probes.csv"), test::read_text(ref + "/probes.csv"));
  EXPECT_EQ(test::read_text(run + "/fields/plate.xdmf"), test::read_text(ref + "/fields/plate.xdmf"));
  EXPECT_EQ(test::read_text(run + "/fields/fluid.xdmf"), test::read_text(ref + "/fields/fluid.xdmf"));
  // The log holds all three legs.
  const std::string all = test::read_text(run + "/log.txt");
  EXPECT_EQ(std::count(all.begin(), all.end(), '\n') > 10, true);
  EXPECT_NE(all.find("restart: from "), std::string::npos);
}

TEST(Restart, FromACheckpointWithoutCpuSecondsTheirCountIsUnknown) {
  // A checkpoint of the earlier layout (the run block without the CPU seconds) still continues; the summary's
  // earlier_cpu_seconds is then null, not a number that leaves them out.
  const Case& c = kCoupled;
  const std::string leg1 = test::binary_path("restart_old_layout_a"),
                    leg2 = test::binary_path("restart_old_layout_b");
  ASSERT_EQ(test::run_scene(c.scene, leg1, c.args + end_time(c.middle), 1), 0)
      << test::read_text(leg1 + ".stderr");
  io::Checkpoint old = io::read_checkpoint(latest(leg1));
  old.blocks["run"].pop_back();
  const std::string path = leg1 + "_old_layout.h5";
  io::write_checkpoint(MPI_COMM_WORLD, path, old);
  ASSERT_EQ(test::run_scene(c.scene, leg2, c.args + end_time(c.end) + " --restart " + path, 1), 0)
      << test::read_text(leg2 + ".stderr");
  EXPECT_TRUE(std::isnan(earlier_cpu_seconds(leg2))) << test::read_text(leg2 + "/summary.json");
  // and the run it continues the same, bit for bit, as from the checkpoint as written
  const std::string leg3 = test::binary_path("restart_old_layout_c");
  ASSERT_EQ(test::run_scene(c.scene, leg3, c.args + end_time(c.end) + " --restart " + leg1, 1), 0)
      << test::read_text(leg3 + ".stderr");
  EXPECT_GT(earlier_cpu_seconds(leg3), 0.0);
  expect_same_state(latest(leg3), latest(leg2));
}

TEST(Restart, SigtermStopsAtAStepBoundaryWithACheckpoint) {
  // One process (no mpirun in between): SIGTERM once the run is under way.
  const std::string run = test::binary_path("restart_sigterm");
  const std::string cmd =
      "rm -rf " + run + " && (" + test::binary_path("src/app/halfeti") + " run " + kCoupled.scene +
      " --out " + run + " " + kCoupled.args + end_time(1.5) + " >" + run +
      ".stdout 2>&1 & pid=$!; for i in $(seq 600); do grep -q 'step' " + run +
      "/log.txt 2>/dev/null && break; sleep 0.05; done; kill -TERM $pid; wait $pid; echo $? >" + run +
      ".status)";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(test::read_text(run + ".status"), "5\n") << test::read_text(run + ".stdout");
  EXPECT_EQ(summary_status(run), "stopped");
  EXPECT_NE(test::read_text(run + "/log.txt").find("stopped: SIGTERM at t = "), std::string::npos);
  const std::string checkpoint = latest(run);
  ASSERT_FALSE(checkpoint.empty());
  const io::Checkpoint c = io::read_checkpoint(checkpoint);
  EXPECT_GT(c.time, 0.0);
  EXPECT_LT(c.time, 1.5);
}

TEST(Restart, RefusesWhatCannotContinue) {
  const Case& c = kWater;
  const std::string run = test::binary_path("restart_refusals");
  ASSERT_EQ(test::run_scene(c.scene, run, c.args + end_time(0.01), 1), 0) << test::read_text(run + ".stderr");
  const std::string bin = test::binary_path("src/app/halfeti");
  const auto attempt = [&](const std::string& args, const std::string& out) {
    const std::string cmd =
        bin + " run " + c.scene + " " + c.args + " " + args + " >" + out + ".stdout 2>" + out + ".stderr";
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  };
  const std::string other = test::binary_path("restart_refusals_other");
  // A physics key changed: refused, the key named.
  EXPECT_EQ(attempt(end_time(0.02) + " --set fluid.sound_speed=31 --restart " + run + " --out " + other +
                        " --overwrite",
                    other),
            2);
  EXPECT_NE(test::read_text(other + ".stderr")
                .find("the scene changes fluid.sound_speed (checkpoint 30.0, now 31)"),
            std::string::npos)
      << test::read_text(other + ".stderr");
  // Nothing left to run.
  EXPECT_EQ(attempt(end_time(0.01) + " --restart " + run + " --out " + other + " --overwrite", other), 2);
  EXPECT_NE(test::read_text(other + ".stderr").find("not before scene.end_time"), std::string::npos);
  // A field file is not a checkpoint; a missing path is not one either.
  EXPECT_EQ(attempt(end_time(0.02) + " --restart " + run + "/fields/fluid_000000.h5 --out " + other +
                        " --overwrite",
                    other),
            2);
  EXPECT_NE(test::read_text(other + ".stderr").find("is not a halfeti checkpoint"), std::string::npos);
  EXPECT_EQ(attempt(end_time(0.02) + " --restart " + run + "/no_such --out " + other + " --overwrite", other),
            2);
  EXPECT_NE(test::read_text(other + ".stderr").find("is neither a checkpoint nor a folder"),
            std::string::npos);
  // A folder that holds another run: refused without --overwrite, its summary untouched.
  EXPECT_EQ(attempt(end_time(0.01) + " --out " + run, run + "_again"), 2);
  EXPECT_NE(test::read_text(run + "_again.stderr").find("holds the outputs of another run"),
            std::string::npos);
  EXPECT_EQ(summary_status(run), "ok");
  // An output folder too long for MPI-IO's file names: one line, before anything is written (not Open MPI's abort).
  const std::string deep = run + "_" + std::string(200, 'd');
  EXPECT_EQ(attempt(end_time(0.01) + " --out " + deep, run + "_deep"), 2);
  EXPECT_NE(test::read_text(run + "_deep.stderr").find("choose a shorter output folder"), std::string::npos)
      << test::read_text(run + "_deep.stderr");
}

TEST(Restart, AFullDiskIsAnIoErrorNamingTheFileWithNoPartialFileLeft) {
  // A 700 KiB file system (tmpfs; the test needs root, as CI has) fills with the coupled scene's fields.
  const std::string mnt = test::binary_path("restart_tmpfs");
  ::mkdir(mnt.c_str(), 0755);
  ::umount(mnt.c_str());
  ASSERT_EQ(::mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=700k"), 0)
      << "mounting a small tmpfs at " << mnt << " failed: " << std::strerror(errno);
  const std::string run = mnt + "/run", log = test::binary_path("restart_tmpfs");  // the messages outside it
  const std::string cmd = test::source_path("tests/support/clean-mpirun") + " -n 2 " +
                          test::binary_path("src/app/halfeti") + " run " + kCoupled.scene + " --out " + run +
                          " " + kCoupled.args + end_time(0.3) + " --set output.field_interval=0.01 >" + log +
                          ".stdout 2>" + log + ".stderr";
  const int raw = std::system(cmd.c_str());
  const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  const std::string err = test::read_text(log + ".stderr");
  std::string listing;
  for (const char* sub : {"/fields", "/checkpoints"}) {
    const std::string cmd = "ls " + run + sub + " > " + test::binary_path("restart_tmpfs.ls") + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    listing += test::read_text(test::binary_path("restart_tmpfs.ls"));
  }
  ::umount(mnt.c_str());
  EXPECT_EQ(status, 6) << err;
  EXPECT_NE(err.find("halfeti: error: "), std::string::npos) << err;
  EXPECT_NE(err.find("No space left on device"), std::string::npos) << err;
  EXPECT_NE(err.find(run), std::string::npos) << err;  // the file named
  EXPECT_EQ(listing.find(".partial"), std::string::npos) << listing;
  EXPECT_EQ(listing.find(".tmp"), std::string::npos) << listing;
}
