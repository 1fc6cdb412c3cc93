// The table of malformed scenes: each must be answered by `halfeti check` with one line naming file, line, key,
// what was found and what was expected (exit status 2).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>

#include "halfeti/app/scene_schema.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/core/scene.hpp"
#include "halfeti/io/run_log.hpp"

using namespace halfeti;

namespace {

struct Case {
  const char* what;
  const char* text;
  const char* message;  // the whole error line
};

const char* kGood = "scene: {name: s, end_time: 1}\n";

const Case kCases[] = {
    {"missing section", "output: {probe_interval: 0.01}\n",
     "bad.yaml:1:1: scene: required key missing: expected a section (key: value lines)"},
    {"negative end time", "scene: {name: s, end_time: -2}\n",
     "bad.yaml:1:28: scene.end_time: expected a number > 0 and <= 10000 (s), found '-2'"},
    {"text for a number", "scene: {name: s, end_time: soon}\n",
     "bad.yaml:1:28: scene.end_time: expected a number > 0 and <= 10000 (s), found 'soon'"},
    {"near-miss key", "scene: {name: s, end_tme: 1}\n",
     "bad.yaml:1:18: unknown key 'scene.end_tme'; did you mean 'end_time'?"},
    {"unknown section", "scene: {name: s, end_time: 1}\nwather: {}\n",
     "bad.yaml:2:1: unknown key 'wather'; expected one of: scene, output, gravity, tank, excitation, fluid, "
     "structure, cables, coupling, probes"},
    {"near-miss section", "scene: {name: s, end_time: 1}\nfluids: {}\n",
     "bad.yaml:2:1: unknown key 'fluids'; did you mean 'fluid'?"},
    {"unknown choice", "scene: {name: s, end_time: 1}\nexcitation: {kind: sine}\n",
     "bad.yaml:2:20: excitation.kind: expected one of none, sine_pulse, cosine_pulse, record, found 'sine'; "
     "did you mean 'none'?"},
    {"misspelt kind (its default's unknown keys follow from it: not reported)",
     "scene: {name: s, end_time: 1}\nexcitation: {kindx: cosine_pulse, amplitude: 3.0, period: 0.4}\n",
     "bad.yaml:2:14: unknown key 'excitation.kindx' for kind 'none'; did you mean 'kind'?"},
    {"pulse without period", "scene: {name: s, end_time: 1}\nexcitation: {kind: sine_pulse, amplitude: 2}\n",
     "bad.yaml:2:13: excitation.period: required key missing: expected a number > 0 and <= 100 (s)"},
    {"key of another kind", "scene: {name: s, end_time: 1}\nexcitation: {kind: none, period: 1}\n",
     "bad.yaml:2:26: unknown key 'excitation.period' for kind 'none'; expected one of: kind"},
    {"negative interval", "scene: {name: s, end_time: 1}\noutput: {probe_interval: 0}\n",
     "bad.yaml:2:26: output.probe_interval: expected a number > 0 (s), found '0'"},
    {"probe without name", "scene: {name: s, end_time: 1}\nprobes:\n  - {kind: ground_acceleration}\n",
     "bad.yaml:3:5: probes[0].name: required key missing: expected a string"},
    {"probes not a list", "scene: {name: s, end_time: 1}\nprobes: {name: a}\n",
     "bad.yaml:2:9: probes: expected a list of sections, found a section"},
    {"tank too small", "scene: {name: s, end_time: 1}\ntank: {length: 0, height: 1}\n",
     "bad.yaml:2:16: tank.length: expected a number > 0 and <= 100 (m), found '0'"},
    {"unknown kernel",
     "scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
     "fluid: {spacing: 0.01, kernel: gaussian, water: [{from: [0, 0], to: [0.3, 0.1]}]}\n",
     "bad.yaml:3:32: fluid.kernel: expected one of cubic_spline, wendland_c2, found 'gaussian'"},
    {"unknown wall friction",
     "scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
     "fluid: {spacing: 0.01, wall_friction: manning, water: [{from: [0, 0], to: [0.3, 0.1]}]}\n",
     "bad.yaml:3:39: fluid.wall_friction: expected one of none, log_law, found 'manning'"},
    {"unknown wall ghost pressure",
     "scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
     "fluid: {spacing: 0.01, wall_ghost_pressure: adami, water: [{from: [0, 0], to: [0.3, 0.1]}]}\n",
     "bad.yaml:3:45: fluid.wall_ghost_pressure: expected one of taylor, body_force, found 'adami'"},
    {"negative viscosity",
     "scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
     "fluid: {spacing: 0.01, kinematic_viscosity: -1e-6, water: [{from: [0, 0], to: [0.3, 0.1]}]}\n",
     "bad.yaml:3:45: fluid.kinematic_viscosity: expected a number > 0 and <= 1 (m^2/s), found '-1e-6'"},
    {"first rank's share above one",
     "scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
     "fluid: {spacing: 0.01, first_rank_share: 1.5, water: [{from: [0, 0], to: [0.3, 0.1]}]}\n",
     "bad.yaml:3:42: fluid.first_rank_share: expected a number > 0 and <= 1, found '1.5'"},
    {"unknown plate orientation",
     "scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0], orientation: upside_down, time_step: "
     "0.001}\n",
     "bad.yaml:2:43: structure.orientation: expected one of standing, hanging, found 'upside_down'"},
    {"incompressible rubber",
     "scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0], poisson_ratio: 0.5}\n",
     "bad.yaml:2:45: structure.poisson_ratio: expected a number > -1 and <= 0.499, found '0.5'"},
    {"nearly incompressible rubber",
     "scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0], poisson_ratio: 0.49999999}\n",
     "bad.yaml:2:45: structure.poisson_ratio: expected a number > -1 and <= 0.499, found '0.49999999'"},
    {"a liquid denser than any",
     "scene: {name: s, end_time: 1}\nfluid: {spacing: 0.01, density: 1e308, water: [{from: [0, 0], to: [0.3, "
     "0.1]}]}\n",
     "bad.yaml:2:33: fluid.density: expected a number > 0 and <= 20000 (kg/m^3), found '1e308'"},
    {"cable without area",
     "scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0]}\n"
     "cables: [{name: a, anchor: [0, 0.01], node: top_left, area: 0, modulus: 1e6, density: 1000}]\n",
     "bad.yaml:3:61: cables[0].area: expected a number > 0 and <= 0.01 (m^2), found '0'"},
    {"layer outside eq. 23's range", "scene: {name: s, end_time: 1}\ncoupling: {ssosd: {layer_ratio: 60}}\n",
     "bad.yaml:2:33: coupling.ssosd.layer_ratio: expected a number in [5, 50], found '60'"},
    {"interface added mass out of range", "scene: {name: s, end_time: 1}\ncoupling: {added_mass_layer: 5}\n",
     "bad.yaml:2:30: coupling.added_mass_layer: expected a number in [0, 4] (dx), found '5'"},
    {"free-surface mark not a boolean",
     "scene: {name: s, end_time: 1}\ncoupling: {plate_wall_free_surface: maybe}\n",
     "bad.yaml:2:37: coupling.plate_wall_free_surface: expected true or false, found 'maybe'"},
    {"unknown interface added mass", "scene: {name: s, end_time: 1}\ncoupling: {added_mass: implicit}\n",
     "bad.yaml:2:24: coupling.added_mass: expected one of acoustic, layer, none, found 'implicit'"},
    {"unknown plate-water exchange",
     "scene: {name: s, end_time: 1}\ncoupling: {plate_wall_exchange: converged}\n",
     "bad.yaml:2:33: coupling.plate_wall_exchange: expected one of extrapolated, lagged, implicit, found "
     "'converged'"},
    {"broken YAML", "scene: {name: s, end_time: 1\n",
     "bad.yaml:2:1: not valid YAML: end of map flow not found"},
    {"not a mapping", "- a\n- b\n",
     "bad.yaml: a scene is a YAML mapping of sections (scene:, fluid:, ...), found something else"},
    {"a section twice", "scene: {name: s, end_time: 1}\nscene: {name: t, end_time: 2}\n",
     "bad.yaml:2: key 'scene' appears twice in the same section (which one was meant?)"},
    {"a key twice", "scene: {name: s, end_time: 1, end_time: 2}\n",
     "bad.yaml:1: key 'scene.end_time' appears twice in the same section (which one was meant?)"},
    {"a key twice in a list item",
     "scene: {name: s, end_time: 1}\nprobes:\n  - {name: a, name: b, kind: ground_acceleration}\n",
     "bad.yaml:3: key 'probes[0].name' appears twice in the same section (which one was meant?)"},
};

std::string halfeti_binary() {
  return std::string(HALFETI_BINARY_DIR) + "/src/app/halfeti";
}

int run_and_capture(const std::string& args, std::string& stderr_text) {
  const std::string err = std::string(HALFETI_BINARY_DIR) + "/check_stderr.txt";
  const int raw = std::system((halfeti_binary() + " " + args + " >/dev/null 2>" + err).c_str());
  std::ifstream in(err);
  stderr_text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

}  // namespace

TEST(SceneErrors, EachMalformedSceneGetsItsMessage) {
  for (const auto& c : kCases) {
    try {
      scene::parse_scene(c.text, "bad.yaml", {}, *app::scene_schema());
      ADD_FAILURE() << c.what << ": accepted";
    } catch (const UserError& e) {
      EXPECT_EQ(std::string(e.what()), c.message) << c.what;
    }
  }
  EXPECT_NO_THROW(scene::parse_scene(kGood, "good.yaml", {}, *app::scene_schema()));
}

TEST(SceneErrors, CheckCommandAnswersOneLineAndExitsTwo) {
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/scene_error_cases";
  io::make_directories(dir);
  for (const auto& c : kCases) {
    const std::string path = dir + "/bad.yaml";
    std::ofstream(path) << c.text;
    std::string err;
    const int status = run_and_capture("check " + path, err);
    EXPECT_EQ(status, 2) << c.what;
    // One line, prefixed, naming the file as given on the command line.
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << c.what << ": " << err;
    std::string expected = c.message;
    expected.replace(0, std::string("bad.yaml").size(), path);
    EXPECT_EQ(err, "halfeti: error: " + expected + "\n") << c.what;
  }
}

TEST(SceneErrors, EverySchemaErrorIsReportedInOnePass) {
  // Four errors in three sections and a list item: all four, one line each, in the order of the text.
  const char* text =
      "scene: {name: s, end_time: -1}\n"
      "tank: {length: 0.3, heigth: 0.4}\n"
      "probes:\n"
      "  - {kind: ground_acceleration}\n"
      "  - {name: b, kind: ground_acceleration, every: 2}\n"
      "output: {probe_interval: 0}\n";
  try {
    scene::parse_scene(text, "bad.yaml", {}, *app::scene_schema());
    ADD_FAILURE() << "accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bad.yaml:1:28: scene.end_time: expected a number > 0 and <= 10000 (s), found '-1'\n"
              "bad.yaml:2:21: unknown key 'tank.heigth'; did you mean 'height'?\n"
              "bad.yaml:4:5: probes[0].name: required key missing: expected a string\n"
              "bad.yaml:5:42: unknown key 'probes[1].every' for kind 'ground_acceleration'; expected one of: "
              "name, kind\n"
              "bad.yaml:6:26: output.probe_interval: expected a number > 0 (s), found '0'");
  }
  // A --set override's error comes first, then the text's.
  try {
    scene::parse_scene("scene: {name: s, end_time: 1}\ntank: {length: -1, height: 0.4}\n", "bad.yaml",
                       {"scene.end_time=0"}, *app::scene_schema());
    ADD_FAILURE() << "accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--set scene.end_time=0: scene.end_time: expected a number > 0 and <= 10000 (s), found '0'\n"
              "bad.yaml:2:16: tank.length: expected a number > 0 and <= 100 (m), found '-1'");
  }
  // Repeated keys: every one.
  try {
    scene::parse_scene("scene: {name: s, name: t, end_time: 1}\ntank: {length: 1, length: 2}\n", "bad.yaml",
                       {}, *app::scene_schema());
    ADD_FAILURE() << "accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bad.yaml:1: key 'scene.name' appears twice in the same section (which one was meant?)\n"
              "bad.yaml:2: key 'tank.length' appears twice in the same section (which one was meant?)");
  }
}

TEST(SceneErrors, ManyErrorsAreCappedWithACount) {
  // 25 probes without a name: the first 20 lines, then one line with the count.
  std::string text = "scene: {name: s, end_time: 1}\nprobes:\n";
  for (int i = 0; i < 25; ++i) text += "  - {kind: ground_acceleration}\n";
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/scene_error_many";
  io::make_directories(dir);
  const std::string path = dir + "/bad.yaml";
  std::ofstream(path) << text;
  std::string err;
  EXPECT_EQ(run_and_capture("check " + path, err), 2);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 21) << err;
  EXPECT_NE(err.find("halfeti: error: " + path + ":3:5: probes[0].name: required key missing"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("halfeti: error: " + path + ":22:5: probes[19].name: required key missing"),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find("probes[20]"), std::string::npos) << err;
  EXPECT_NE(err.find("halfeti: error: " + path + ": 5 more errors not shown (25 in all)\n"),
            std::string::npos)
      << err;
}

TEST(SceneErrors, MaxMemoryRefusesAnOversizedScene) {
  // The paper's tank at dx 1.5 mm needs about 65 MB on a rank (run_size.cpp's figures): refused under 10 MB,
  // accepted under 1 GB; a malformed size is an error naming the option.
  const std::string scene = std::string(HALFETI_SOURCE_DIR) + "/inputs/paper/cosine_free.yaml";
  std::string err;
  EXPECT_EQ(run_and_capture("check " + scene + " --max-memory 10M", err), 2);
  EXPECT_NE(err.find("fluid.spacing: the run would need"), std::string::npos) << err;
  EXPECT_NE(err.find("above --max-memory 0.01 GB"), std::string::npos) << err;
  EXPECT_EQ(run_and_capture("check " + scene + " --max-memory 1GiB", err), 0) << err;
  EXPECT_EQ(run_and_capture("check " + scene + " --max-memory lots", err), 2);
  EXPECT_EQ(err, "halfeti: error: --max-memory takes a memory size such as 8G, 512M or 2GiB, got 'lots'\n");
}

TEST(SceneErrors, ChecksAcrossKeysNameTheFileAndKey) {
  // Errors found after the schema (a key that depends on another) still name the scene file and the key path.
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/scene_cross_cases";
  io::make_directories(dir);
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0], time_step: 0.001}\n"
       "cables: [{name: a, anchor: [0, 0.01], node: nowhere, area: 1e-6, modulus: 1e6, density: 1000, "
       "initial_stress: 1e3}]\n",
       "cables[0].node: no plate node named 'nowhere'"},
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "fluid: {spacing: 0.01, water: [{from: [0, 0], to: [0.5, 0.1]}]}\n",
       "fluid.water[0]: water from [0, 0] to [0.5, 0.1] does not fit in the tank"},
      {"scene: {name: s, end_time: 1}\nprobes: [{name: p, kind: displacement, node: top_left, component: "
       "x}]\n",
       "probes[0]: this probe reads the plate, but the scene has no `structure:` section"},
      {"scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0]}\n",
       "structure.time_step: required when the scene has no `fluid:`"},
      {"scene: {name: s, end_time: 1}\nexcitation: {kind: record, file: missing.csv}\n",
       "cannot open accelerogram"},
      {"scene: {name: s, end_time: 1}\nexcitation: {kind: record, file: .}\n",
       "is a folder, not a record file"},
      // A standing mode needs at least two surface samples per half wave.
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "fluid: {spacing: 0.01, water: [{from: [0, 0], to: [0.3, 0.1]}]}\n"
       "probes: [{name: m, kind: surface_mode, mode: 5, samples: 8}]\n",
       "probes[0].samples: 8 samples cannot resolve mode 5 (at least 2 per half wave: 10)"},
      // A hanging plate (a gate) reaches down from its clamp: below the floor it does not fit; its nodes have the
      // tank frame's names, so the standing plate's top_right is unknown.
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "structure: {base: [0.15, 0.05], orientation: hanging, height: 0.08, time_step: 0.001}\n",
       "structure: the plate (base [0.15, 0.05], 0.003 x 0.08 m) does not fit in the tank"},
      {"scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0.1], orientation: hanging, time_step: "
       "0.001}\n"
       "probes: [{name: p, kind: displacement, node: top_right, component: x}]\n",
       "probes[0].node: no plate node named 'top_right'"},
      // The plate-water coupling's probes need water and a plate; the contact has no suction to split off.
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "fluid: {spacing: 0.005, water: [{from: [0, 0], to: [0.3, 0.1]}]}\nstructure: {base: [0.15, 0]}\n"
       "probes: [{name: c, kind: plate_load, part: contact, sign: push, component: x}]\n",
       "probes[0].sign: 'push' splits the plate-wall part only; the contact only pushes"},
      // The converged exchange replaces the interface added mass; it needs the plate in the water's sums.
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "fluid: {spacing: 0.005, water: [{from: [0, 0], to: [0.3, 0.1]}]}\nstructure: {base: [0.15, 0]}\n"
       "coupling: {plate_wall_exchange: implicit}\n",
       "coupling.added_mass: with plate_wall_exchange: implicit the water's response is converged within the "
       "step"},
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "fluid: {spacing: 0.005, water: [{from: [0, 0], to: [0.3, 0.1]}]}\nstructure: {base: [0.15, 0]}\n"
       "coupling: {plate_wall_exchange: implicit, added_mass: none, plate_wall: false}\n",
       "coupling.plate_wall_exchange: implicit converges the plate-wall exchange; it needs "
       "coupling.plate_wall: true"},
      // A cable's anchor is on the tank: not outside it, not in mid-water.
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\nstructure: {base: [0.15, 0], "
       "time_step: 0.001}\n"
       "cables: [{name: a, anchor: [-1e300, 0.01], node: top_left, area: 1e-6, modulus: 1e6, density: 1000, "
       "initial_stress: 1e3}]\n",
       "cables[0].anchor: [-1e+300, 0.01] m is not on the tank's floor or a side wall"},
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\nstructure: {base: [0.15, 0], "
       "time_step: 0.001}\n"
       "cables: [{name: a, anchor: [0.1, 0.2], node: top_left, area: 1e-6, modulus: 1e6, density: 1000, "
       "initial_stress: 1e3}]\n",
       "cables[0].anchor: [0.1, 0.2] m is not on the tank's floor or a side wall"},
      // Water blocks: twice over the same place, or a surface wave the lattice cannot show.
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "fluid: {spacing: 0.01, water: [{from: [0, 0], to: [0.2, 0.1]}, {from: [0.1, 0], to: [0.3, 0.1]}]}\n",
       "fluid.water[1]: water from [0.1, 0] to [0.3, 0.1] overlaps fluid.water[0]"},
      {"scene: {name: s, end_time: 1}\ntank: {length: 0.3, height: 0.4}\n"
       "fluid: {spacing: 0.01, water: [{from: [0, 0], to: [0.3, 0.1], surface_amplitude: 0.002}]}\n",
       "fluid.water[0].surface_amplitude: 0.002 m is below half the spacing (0.005 m)"},
      // The name names the output folder: a path there would write outside out/.
      {"scene: {name: ../../etc, end_time: 1}\n",
       "scene.name '../../etc': letters, digits, '_', '-' and '.' only (it names the folder out/<name>)"},
      {"scene: {name: s, end_time: 1}\nstructure: {base: [0.15, 0], time_step: 0.001}\n"
       "probes: [{name: w, kind: plate_load_work}]\n",
       "probes[0]: this probe reads the plate-water coupling, but the scene has no water"},
  };
  for (const auto& c : cases) {
    const std::string path = dir + "/cross.yaml";
    std::ofstream(path) << c.text;
    std::string err;
    EXPECT_EQ(run_and_capture("check " + path, err), 2) << c.message;
    EXPECT_EQ(err.rfind("halfeti: error: " + path + ": ", 0), 0u) << err;
    EXPECT_NE(err.find(c.message), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  }
}
