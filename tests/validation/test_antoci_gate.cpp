// inputs/validation/antoci_gate.yaml through the program: the Antoci et al. (2007) rubber gate, clamped at its top,
// pushed open by a 0.14 m water column. Its free end's x and y displacement are compared with the experiment
// (inputs/validation/data/antoci_gate_exp_{x,y}.csv, relative to their first values, as digitised) at the measured
// times: the RMS error over the measured points, against a tolerance of the measured peak x (46.3 mm).
// ANTOCI_GATE_FULL selects the scene's own dx (1 mm); otherwise dx 2 mm. docs/coupling.md, section 14.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "halfeti/io/metrics.hpp"
#include "run_scene.hpp"

using namespace halfeti;

namespace {

// The measured series: time_s and the value relative to the first (as digitised).
io::Curve read_measured(const std::string& path) {
  return io::read_reference(path, "time_s",
                            path.find("_x.csv") != std::string::npos ? "disp_x_rel_m" : "disp_y_rel_m");
}

}  // namespace

TEST(AntociGate, FreeEndFollowsTheExperiment) {
#ifdef ANTOCI_GATE_FULL
  const std::string out = test::binary_path("validation_antoci_gate_full");
  const std::string args = "--set output.field_interval=0";
  const char* resolution = "dx 1 mm";
#else
  const std::string out = test::binary_path("validation_antoci_gate");
  const std::string args = "--set fluid.spacing=0.002 --set output.field_interval=0";
  const char* resolution = "dx 2 mm";
#endif
  ASSERT_EQ(test::run_scene(test::source_path("inputs/validation/antoci_gate.yaml"), out, args, 1), 0)
      << test::read_text(out + ".stderr");
  const auto probes = io::read_probe_csv(out + "/probes.csv");
  const auto time = probes.column("t");
  const double peak_measured = 0.0463;  // m, the measured peak x (antoci_gate_exp_x.csv)
  double rms[2] = {0.0, 0.0};
  const char* names[2] = {"tip_x", "tip_y"};
  const char* files[2] = {"inputs/validation/data/antoci_gate_exp_x.csv",
                          "inputs/validation/data/antoci_gate_exp_y.csv"};
  for (int c = 0; c < 2; ++c) {
    const io::Curve m = read_measured(test::source_path(files[c]));
    ASSERT_EQ(m.t.size(), 10u) << files[c];
    ASSERT_GE(time.back(), m.t.back()) << "the run must cover the measured points";
    const io::Curve raw{time, probes.column(names[c])};
    io::Curve u = raw;
    for (double& v : u.v) v -= io::value_at(raw, 0.0);  // relative to the start, as the measurement
    rms[c] = io::rms_error(u, m);
    const io::Peak peak = io::peak(raw);
    std::printf("antoci_gate %s: %s peak %.2f mm at %.3f s, RMS error %.2f mm (%.1f %% of 46.3 mm)\n",
                resolution, names[c], 1e3 * peak.value, peak.time, 1e3 * rms[c],
                100.0 * rms[c] / peak_measured);
  }
  // Issue #6's acceptance, an RMS error of at most 10 % of the measured peak in x and y, is NOT met (docs/coupling.md,
  // section 14: x 21.0 / 20.3 %, y 12.5 / 12.5 % at dx 2 / 1 mm; the gate opens to 36-40 mm, as the published SPH-FE
  // results, and closes back to 29 mm where the experiment stays at 37-43 mm). Printed here, asserted as a
  // regression guard a little above the measured errors.
  std::printf("antoci_gate %s: issue #6 acceptance (RMS <= 4.63 mm in x and y): %s\n", resolution,
              rms[0] <= 0.10 * peak_measured && rms[1] <= 0.10 * peak_measured ? "met" : "NOT met");
  EXPECT_LE(rms[0], 0.23 * peak_measured) << "x: regression guard";
  EXPECT_LE(rms[1], 0.14 * peak_measured) << "y: regression guard";
  // The gate must open: its peak within the published SPH-FE range (34-39 mm) widened by 10 %.
  const auto tip_x = probes.column("tip_x");
  const double peak_x = *std::max_element(tip_x.begin(), tip_x.end());
  EXPECT_GT(peak_x, 0.9 * 0.034);
  EXPECT_LT(peak_x, 1.1 * 0.039);
  // It runs to the end (warnings allowed: the outflow's jet under the gate clumps, docs/stability.md's monitors).
  EXPECT_NE(test::read_text(out + "/summary.json").find("\"exit_status\": \"ok"), std::string::npos);
}
