// The program's commands end to end: exit statuses, --set, outputs of a run, the probe registry.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "halfeti/app/cli.hpp"
#include "halfeti/app/probes.hpp"
#include "halfeti/app/scene_schema.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/io/probe_writer.hpp"
#include "halfeti/io/run_log.hpp"

using namespace halfeti;

namespace {

const std::string kBin = std::string(HALFETI_BINARY_DIR) + "/src/app/halfeti";
const std::string kDir = std::string(HALFETI_BINARY_DIR) + "/app_commands";

int status_of(const std::string& args) {
  const int raw = std::system((kBin + " " + args + " >" + kDir + "/out.txt 2>" + kDir + "/err.txt").c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string write_scene(const std::string& name, const std::string& text) {
  io::make_directories(kDir);
  const std::string path = kDir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

const char* kPulseScene =
    "scene: {name: pulse, end_time: 0.5}\n"
    "output: {probe_interval: 0.01}\n"
    "excitation: {kind: cosine_pulse, amplitude: 3.0, period: 0.4, start: 0.05}\n"
    "probes:\n  - {name: ag, kind: ground_acceleration}\n";

}  // namespace

TEST(Commands, ExitStatuses) {
  const std::string scene = write_scene("pulse.yaml", kPulseScene);
  EXPECT_EQ(status_of("--help"), 0);
  EXPECT_EQ(status_of("--version"), 0);
  EXPECT_NE(file_text(kDir + "/out.txt").find("halfeti 0."), std::string::npos);
  // --version names the commit the binary was built at, as summary.json's provenance does
  EXPECT_NE(file_text(kDir + "/out.txt").find("(commit "), std::string::npos);
  EXPECT_EQ(status_of("check " + scene), 0);
  EXPECT_EQ(status_of(""), 2);
  EXPECT_EQ(status_of("frobnicate"), 2);
  EXPECT_EQ(status_of("run"), 2);
  EXPECT_EQ(status_of("run " + scene + " --bogus"), 2);
  EXPECT_EQ(status_of("check " + kDir + "/no_such_scene.yaml"), 2);
  EXPECT_EQ(file_text(kDir + "/err.txt"), "halfeti: error: cannot open scene file '" + kDir +
                                              "/no_such_scene.yaml': no such file or not readable\n");
  EXPECT_EQ(status_of("check " + scene + " --set excitation.period=-1"), 2);
  EXPECT_EQ(status_of("run " + scene + " --out /proc/forbidden/out"), 2);
  // A folder for a scene, and --set through a value: bad input, one line (once a yaml-cpp exception, status 4).
  EXPECT_EQ(status_of("run " + kDir), 2);
  EXPECT_EQ(file_text(kDir + "/err.txt"),
            "halfeti: error: scene file '" + kDir + "' is a folder; give the scene's .yaml file\n");
  EXPECT_EQ(status_of("check " + scene + " --set scene.end_time.x=1"), 2);
  EXPECT_EQ(file_text(kDir + "/err.txt"),
            "halfeti: error: --set scene.end_time.x=1: 'scene.end_time' holds a value, not a section\n");
  const std::string bad_record = write_scene(
      "record.yaml", "scene: {name: r, end_time: 1}\nexcitation: {kind: record, file: missing.csv}\n");
  EXPECT_EQ(status_of("check " + bad_record), 2);
  EXPECT_NE(file_text(kDir + "/err.txt").find("cannot open accelerogram"), std::string::npos);
}

TEST(Commands, CheckPrintsTheSizeAndRefusesARunTooBigForTheMachine) {
  const std::string scene = std::string(HALFETI_SOURCE_DIR) + "/inputs/paper/cosine_cable.yaml";
  ASSERT_EQ(status_of("check " + scene), 0);
  // The blocks' area over dx^2 (13,294 laid: the plate's place is left dry) and the 2 x 60 Q9 plate.
  EXPECT_NE(file_text(kDir + "/out.txt").find("ok; about 13333 particles, 120 plate elements (1210 dofs), "),
            std::string::npos)
      << file_text(kDir + "/out.txt");
  // dx = 0.1 um: 3e12 particles, about 3e6 GB: refused before anything is allocated (it once died after 29 s).
  EXPECT_EQ(status_of("check " + scene + " --set fluid.spacing=1e-7"), 2);
  EXPECT_NE(
      file_text(kDir + "/err.txt").find("fluid.spacing: the run would need about 3000000000000 particles"),
      std::string::npos)
      << file_text(kDir + "/err.txt");
  EXPECT_EQ(status_of("run " + scene + " --out " + kDir + "/huge --overwrite --set fluid.spacing=1e-7"), 2);
}

TEST(Commands, HelpAfterACommandAndSchedulesFinerThanAStepEnd) {
  EXPECT_EQ(status_of("run --help"), 0);
  EXPECT_NE(file_text(kDir + "/out.txt").find("--restart"), std::string::npos);
  EXPECT_EQ(status_of("check --help"), 0);
  // An end time or an output interval far below the time step (here 1e-300 s) once kept the schedule loop adding
  // an interval that no longer changed the next time: the run must end (ctest's timeout would catch a hang).
  const std::string scene = write_scene("tiny.yaml", kPulseScene);
  const std::string out = kDir + "/tiny_out";
  EXPECT_EQ(status_of("run " + scene + " --out " + out + " --overwrite --set scene.end_time=1e-300"), 0);
  EXPECT_EQ(status_of("run " + scene + " --out " + out +
                      " --overwrite --set output.probe_interval=1e-300 "
                      "--set scene.end_time=1e-300"),
            0);
  EXPECT_EQ(status_of("run " + scene + " --out " + out +
                      " --overwrite --set output.field_interval=1e-300 "
                      "--set output.checkpoint_interval=1e-300 --set output.progress_interval=1e-300 "
                      "--set scene.end_time=1e-3"),
            0);
  EXPECT_NE(file_text(out + "/summary.json").find("\"exit_status\": \"ok\""), std::string::npos);
}

TEST(Commands, RunWritesProbesSummaryLogAndResolvedScene) {
  const std::string scene = write_scene("pulse.yaml", kPulseScene);
  const std::string out = kDir + "/pulse_out";
  ASSERT_EQ(status_of("run " + scene + " --out " + out + " --overwrite --set excitation.amplitude=2.0"), 0);
  const auto probes = io::read_probe_csv(out + "/probes.csv");
  ASSERT_EQ(probes.names, (std::vector<std::string>{"t", "ag"}));
  ASSERT_EQ(probes.rows.size(), 51u);  // t = 0, 0.01, ..., 0.5
  EXPECT_NEAR(probes.column("t").back(), 0.5, 1e-12);
  EXPECT_NEAR(probes.column("ag")[5], 2.0,
              1e-9);  // the override took effect: cosine peak at the start, 0.05 s
  EXPECT_EQ(probes.column("ag")[0], 0.0);
  const std::string summary = file_text(out + "/summary.json");
  for (const char* key : {"\"scene\": \"pulse\"", "\"ranks\": 1", "\"steps\": 50", "\"simulated_time\": 0.5",
                          "\"exit_status\": \"ok\"", "\"timers\"", "\"health_events\"", "\"wall_time\""})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  EXPECT_NE(file_text(out + "/log.txt").find("done:"), std::string::npos);
  const std::string columns = file_text(out + "/probes.json");  // each column's unit
  EXPECT_NE(columns.find("\"name\": \"ag\",\n      \"unit\": \"m/s^2\""), std::string::npos) << columns;
  // The resolved scene runs again as it is and records the override.
  const std::string resolved = file_text(out + "/scene.resolved.yaml");
  EXPECT_NE(resolved.find("amplitude: 2.0"), std::string::npos);
  EXPECT_EQ(status_of("check " + out + "/scene.resolved.yaml"), 0);
}

TEST(Commands, CommandLineParsing) {
  const auto c = app::parse_command_line(
      {"run", "a.yaml", "--set", "x.y=1", "--set=z=2", "--out", "o", "--", "-structure_ksp_type", "gmres"});
  EXPECT_EQ(c.kind, app::Command::Kind::kRun);
  EXPECT_EQ(c.scene, "a.yaml");
  EXPECT_EQ(c.overrides, (std::vector<std::string>{"x.y=1", "z=2"}));
  EXPECT_EQ(c.out_dir, "o");
  EXPECT_EQ(c.petsc_args, (std::vector<std::string>{"-structure_ksp_type", "gmres"}));
  EXPECT_THROW(app::parse_command_line({"check", "a.yaml", "b.yaml"}), UserError);
  EXPECT_THROW(app::parse_command_line({"check", "a.yaml", "--out", "o"}), UserError);
  EXPECT_THROW(app::parse_command_line({"run", "a.yaml", "--set"}), UserError);
  EXPECT_FALSE(c.trace_coupling);
  EXPECT_TRUE(app::parse_command_line({"run", "a.yaml", "--trace", "coupling"}).trace_coupling);
  EXPECT_THROW(app::parse_command_line({"run", "a.yaml", "--trace", "fluid"}), UserError);
  EXPECT_THROW(app::parse_command_line({"check", "a.yaml", "--trace", "coupling"}), UserError);
}

TEST(Commands, ProbeKindsComeFromTheRegistry) {
  const auto& names = app::probe_registry().names();
  const auto schema = app::probe_schema();
  const auto* kind = schema->find("kind");
  ASSERT_NE(kind, nullptr);
  EXPECT_EQ(kind->choices(), names);
  for (const auto& n : names) EXPECT_EQ(schema->variants().count(n), 1u) << n;
}

TEST(Commands, SceneReferencePageIsCurrent) {
  // docs/scene-reference.md is generated from the schema; regenerate with
  //   build/src/app/halfeti reference > docs/scene-reference.md
  ASSERT_EQ(status_of("reference"), 0);
  const std::string generated = file_text(kDir + "/out.txt");
  const std::string checked_in = file_text(std::string(HALFETI_SOURCE_DIR) + "/docs/scene-reference.md");
  if (generated == checked_in) return;
  std::istringstream a(generated), b(checked_in);
  std::string la, lb;
  int line = 0;
  while (true) {
    ++line;
    const bool more_a = static_cast<bool>(std::getline(a, la)),
               more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a && !more_b) break;
    if (la != lb || more_a != more_b) break;
  }
  ADD_FAILURE()
      << "docs/scene-reference.md is stale (regenerate it, see the comment above); first difference at line "
      << line << ":\n  generated:  " << la << "\n  checked in: " << lb;
}
