// inputs/validation/antoci_gate.yaml through the program: the Antoci et al. (2007) rubber gate, clamped at its top,
// pushed open by a 0.14 m water column. Its free end's x and y displacement are compared with the experiment
// (inputs/validation/data/antoci_gate_exp_{x,y}.csv, relative to their first values, as digitised) at the measured
// times: the RMS error over the measured points must stay within a tolerance of the measured peak x (46.3 mm).
// ANTOCI_GATE_FULL selects the scene's own dx (1 mm); otherwise dx 2 mm. docs/coupling.md, section 14.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_scene.hpp"

using namespace halfeti;

namespace {

struct Series {
  std::vector<double> t, v;
};

// The measured series: '#' lines, a header row, then time_s, raw value, value relative to the first (used).
Series read_measured(const std::string& path) {
  std::ifstream in(path);
  Series s;
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    double t, raw, rel;
    if (row >> t >> raw >> rel) {
      s.t.push_back(t);
      s.v.push_back(rel);
    }
  }
  return s;
}

// Linear interpolation of a probe column at time t.
double at(const std::vector<double>& t, const std::vector<double>& v, double when) {
  const auto it = std::lower_bound(t.begin(), t.end(), when);
  if (it == t.begin()) return v.front();
  if (it == t.end()) return v.back();
  const std::size_t k = static_cast<std::size_t>(it - t.begin());
  const double f = (when - t[k - 1]) / (t[k] - t[k - 1]);
  return (1.0 - f) * v[k - 1] + f * v[k];
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
  const char* files[2] = {"inputs/validation/data/antoci_gate_exp_x.csv", "inputs/validation/data/antoci_gate_exp_y.csv"};
  for (int c = 0; c < 2; ++c) {
    const Series m = read_measured(test::source_path(files[c]));
    ASSERT_EQ(m.t.size(), 10u) << files[c];
    ASSERT_GE(time.back(), m.t.back()) << "the run must cover the measured points";
    const auto u = probes.column(names[c]);
    double sum = 0.0;
    for (std::size_t k = 0; k < m.t.size(); ++k) {
      const double e = at(time, u, m.t[k]) - at(time, u, 0.0) - m.v[k];
      sum += e * e;
    }
    rms[c] = std::sqrt(sum / static_cast<double>(m.t.size()));
    const auto peak = std::max_element(u.begin(), u.end());
    std::printf("antoci_gate %s: %s peak %.2f mm at %.3f s, RMS error %.2f mm (%.1f %% of 46.3 mm)\n", resolution,
                names[c], 1e3 * *peak, time[static_cast<std::size_t>(peak - u.begin())], 1e3 * rms[c],
                100.0 * rms[c] / peak_measured);
  }
  // Acceptance (issue #6): RMS error at most 10 % of the measured peak, x and y.
  EXPECT_LE(rms[0], 0.10 * peak_measured) << "x";
  EXPECT_LE(rms[1], 0.10 * peak_measured) << "y";
  EXPECT_NE(test::read_text(out + "/summary.json").find("\"exit_status\": \"ok\""), std::string::npos);
}
