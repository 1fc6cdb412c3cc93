// inputs/validation/dambreak_pressure.yaml through the program (issue #20, item 2): a dam break (column 2H x H,
// H = 0.6 m, dx = H/50) against the far-wall pressure at 0.2 H measured by Buchner (2002), read with the metrics of
// io/metrics.hpp as the study inputs/studies/dambreak_pressure.yaml reads it (docs/sph.md, "The wall pressure after
// a dam break's impact").
//  - The surge reaches the wall when the measurement says: the probe's 20 ms running mean first passes
//    0.1 rho g H within 0.2 of the data's t sqrt(g/H) = 2.49 (the first measured point past 0.1 after 2.3; before,
//    the sensor's noise of +-0.16 rho g H while the tank is dry there). The bound is the
//    surge front's own error: it leads Martin & Moyce's front by up to 8 % late in the run (docs/sph.md, dam
//    break), 8 % of the 2.5 units the water travels.
//  - The noise (RMS of the probe about its 20 ms running mean over t sqrt(g/H) = 3.0-5.5) and the impact peak of
//    the 20 ms mean are printed and held below regression guards (not the physics' bars): 0.2 rho g H (measured
//    0.169 at the commit that added them) and twice the measured 0.691 (+67 % measured). The data's own noise
//    over that window is 0: their digitised samples lie further apart than the running mean's width.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "halfeti/io/metrics.hpp"
#include "run_scene.hpp"

using namespace halfeti;

namespace {
constexpr double kH = 0.6, kG = 9.81, kRhoGH = 1000.0 * kG * kH;
const double kTimeUnit = std::sqrt(kH / kG);  // t = t* sqrt(H / g)
constexpr double kSmooth = 0.02;              // s, the running mean's width
}  // namespace

TEST(DambreakPressure, TheSurgeArrivesWhenMeasuredAndTheNoiseAndPeakAreMeasured) {
  const std::string scene = test::source_path("inputs/validation/dambreak_pressure.yaml");
  const std::string out = test::binary_path("validation_dambreak_pressure");
  ASSERT_EQ(test::run_scene(scene, out, "--set output.field_interval=0", 2), 0)
      << test::read_text(out + ".stderr");
  const auto probes = io::read_probe_csv(out + "/probes.csv");
  io::Curve p{probes.column("t"), probes.column("p_wall")};
  for (double& v : p.v) v /= kRhoGH;
  const io::Curve data =
      io::read_reference(test::source_path("inputs/validation/data/dambreak_buchner_2002_pressure_2d.csv"),
                         "t_star", "p_over_rhogH", kTimeUnit, 1.0);

  // Arrival: the first sample of the 20 ms mean past 0.1, against the data's first point past 0.1.
  const io::Curve mean = io::running_mean(p, kSmooth);
  double arrival = -1.0, measured = -1.0;
  for (std::size_t k = 0; k < mean.t.size() && arrival < 0.0; ++k)
    if (mean.v[k] > 0.1) arrival = mean.t[k] / kTimeUnit;
  for (std::size_t k = 0; k < data.t.size() && measured < 0.0; ++k)  // before 2.3: the sensor's +-0.16 noise
    if (data.t[k] > 2.3 * kTimeUnit && data.v[k] > 0.1) measured = data.t[k] / kTimeUnit;
  ASSERT_GT(arrival, 0.0) << "the water never reached the probe";
  std::printf("arrival t sqrt(g/H) = %.3f against the measured %.3f\n", arrival, measured);
  EXPECT_NEAR(arrival, measured, 0.2);

  const io::Window after{3.0 * kTimeUnit, 5.5 * kTimeUnit}, impact{2.3 * kTimeUnit, 3.3 * kTimeUnit};
  const double noise = io::metric("noise", p, &data, after, kSmooth);
  const double peak = io::peak(mean, impact).value, peak_measured = io::peak(data, impact).value;
  std::printf("noise about the 20 ms mean, t sqrt(g/H) 3.0-5.5: %.3f rho g H (the data's: %.3f)\n", noise,
              io::noise(data, kSmooth, after));
  std::printf("impact peak of the 20 ms mean %.3f against the measured %.3f (%+.0f %%), raw %.3f\n", peak,
              peak_measured, 100.0 * (peak / peak_measured - 1.0), io::peak(p, impact).value);
  EXPECT_LT(noise, 0.2);
  EXPECT_LT(peak, 2.0 * peak_measured);
}
