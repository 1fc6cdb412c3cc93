// The error metrics' one home (io/metrics.hpp) on synthetic curves whose answers are known in closed form, and
// `halfeti compare` (io/compare_tool.hpp) on a probes file and a reference file written here.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "halfeti/core/error.hpp"
#include "halfeti/io/compare_tool.hpp"
#include "halfeti/io/json.hpp"
#include "halfeti/io/metrics.hpp"
#include "halfeti/io/run_log.hpp"

using namespace halfeti;
using io::Curve;
using io::Window;

namespace {
constexpr double kPi = 3.14159265358979323846;

Curve sampled(double (*f)(double), double t0, double t1, int n) {
  Curve c;
  for (int k = 0; k <= n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    c.t.push_back(t);
    c.v.push_back(f(t));
  }
  return c;
}
double sine_2hz(double t) {
  return std::sin(2.0 * kPi * 2.0 * t);
}
double line(double t) {
  return 3.0 * t + 1.0;
}
}  // namespace

TEST(Metrics, ValueAtIsLinearBetweenSamplesAndHeldBeyondTheEnds) {
  const Curve c = sampled(line, 0.0, 1.0, 10);
  EXPECT_NEAR(io::value_at(c, 0.55), line(0.55), 1e-14);
  EXPECT_EQ(io::value_at(c, -5.0), line(0.0));
  EXPECT_EQ(io::value_at(c, 7.0), line(1.0));
  EXPECT_THROW(io::value_at(Curve{}, 0.0), UserError);
}

TEST(Metrics, RmsOfAConstantOffsetIsTheOffsetAndCountsOnlyTheWindow) {
  const Curve run = sampled(line, 0.0, 1.0, 100);
  Curve ref = sampled(line, 0.0, 1.0, 7);
  for (double& v : ref.v) v -= 0.25;
  EXPECT_NEAR(io::rms_error(run, ref), 0.25, 1e-12);
  // The last sample moved by +1 (run - reference = -0.75 there); the window holds only t = 1.0.
  ref.v[7] += 1.0;
  EXPECT_NEAR(io::rms_error(run, ref, Window{0.9, 1.0}), 0.75, 1e-12);
  EXPECT_NEAR(io::rms_error(run, ref), std::sqrt((7 * 0.25 * 0.25 + 0.75 * 0.75) / 8), 1e-12);
  EXPECT_THROW(io::rms_error(run, ref, Window{2.0, 3.0}), UserError);  // no reference sample there
  // Relative: a run 10 % above the reference everywhere.
  Curve high = run;
  for (double& v : high.v) v *= 1.1;
  EXPECT_NEAR(io::rms_relative_error(high, sampled(line, 0.0, 1.0, 7)), 0.1, 1e-12);
  Curve short_run = sampled(line, 0.0, 0.5, 10);
  EXPECT_THROW(io::rms_error(short_run, ref), UserError);  // the run does not reach t = 1
}

TEST(Metrics, PeakAndItsTimeAndTheCrossingFrequencyOfASine) {
  const Curve c = sampled(sine_2hz, 0.0, 2.0, 4000);
  const io::Peak p = io::peak(c);
  EXPECT_NEAR(p.value, 1.0, 1e-6);
  EXPECT_NEAR(p.time, 0.125, 5e-4);  // the first maximum at a quarter period
  EXPECT_NEAR(io::peak(c, {}, true).value, 1.0, 1e-6);
  EXPECT_NEAR(io::peak(c, Window{0.3, 0.4}).time, 0.3, 1e-12);  // falling there: the window's first sample
  // Four whole periods: upward crossings at 0.5, 1.0, 1.5 (and t = 0 is not a crossing from below).
  EXPECT_NEAR(io::crossing_frequency(c), 2.0, 1e-3);
  EXPECT_THROW(io::crossing_frequency(c, Window{0.0, 0.4}), UserError);  // one period has one crossing
  EXPECT_NEAR(io::crossing_frequency(c, {}, 0.5), 2.0, 1e-3);            // a stated level instead of the mean
  EXPECT_NEAR(io::mean_value(sampled(line, 0.0, 1.0, 10)), 2.5, 1e-12);
}

TEST(Metrics, ByNameAgainstAReferenceIsTheDifference) {
  const Curve run = sampled(sine_2hz, 0.0, 2.0, 4000);
  Curve ref = run;
  for (double& v : ref.v) v *= 0.5;
  EXPECT_NEAR(io::metric("peak", run, &ref), 0.5, 1e-6);
  EXPECT_NEAR(io::metric("peak", run, nullptr), 1.0, 1e-6);
  EXPECT_NEAR(io::metric("frequency", run, &ref), 0.0, 1e-9);
  EXPECT_THROW(io::metric("rms", run, nullptr), UserError);
  EXPECT_THROW(io::metric_needs_reference("wobble"), UserError);
}

TEST(Metrics, TheRunningMeanRemovesAWholePeriodAndTheNoiseIsWhatItRemoves) {
  // A line plus a sine of 21 ms period sampled every 1 ms: a running mean 20.5 ms wide holds 21 samples, one whole
  // period, so away from the ends it returns the line exactly (its centred mean) and the noise is the sine's RMS,
  // 0.3 / sqrt(2) (sampled over 38 whole periods: exact to round-off).
  Curve c;
  for (int k = 0; k <= 1000; ++k) {
    const double t = 0.001 * k;
    c.t.push_back(t);
    c.v.push_back(line(t) + 0.3 * std::sin(2.0 * kPi * t / 0.021));
  }
  const Curve m = io::running_mean(c, 0.0205);
  for (int k = 10; k <= 990; k += 70) EXPECT_NEAR(m.v[static_cast<std::size_t>(k)], line(c.t[k]), 1e-12) << k;
  EXPECT_NE(m.v[0], line(0.0));  // the ends average fewer samples: the first 11, not centred
  const Window w{0.1, 0.1 + 38 * 0.021 - 0.0005};
  EXPECT_NEAR(io::noise(c, 0.0205, w), 0.3 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(io::metric("noise", c, nullptr, w, 0.0205), 0.3 / std::sqrt(2.0), 1e-12);
  // Smoothed, the peak over the window is the line's at the window's last sample.
  EXPECT_NEAR(io::metric("peak", c, nullptr, Window{0.1, 0.9}, 0.0205), line(0.9), 1e-12);
  EXPECT_GT(io::metric("peak", c, nullptr, Window{0.1, 0.9}), line(0.9) + 0.25);  // raw: a crest of the sine
  // Against a reference: the run's noise minus the reference's (a clean line has none).
  const Curve clean = sampled(line, 0.0, 1.0, 1000);
  EXPECT_NEAR(io::metric("noise", c, &clean, w, 0.0205), 0.3 / std::sqrt(2.0), 1e-12);
  EXPECT_THROW(io::metric("noise", c, nullptr, w), UserError);  // no width
  EXPECT_THROW(io::running_mean(c, 0.0), UserError);
  EXPECT_THROW(io::metric("peak", c, nullptr, w, -1.0), UserError);
}

TEST(Metrics, ReferenceColumnsByNameWithScalesAndTheirErrors) {
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/io_metrics";
  io::make_directories(dir);
  std::ofstream(dir + "/ref.csv") << "# provenance line\nT_star,Z,other\n1, 2, 9\n2, 3, 9\n";
  const Curve c = io::read_reference(dir + "/ref.csv", "T_star", "Z", 0.5, 10.0);
  ASSERT_EQ(c.t.size(), 2u);
  EXPECT_EQ(c.t[1], 1.0);
  EXPECT_EQ(c.v[1], 30.0);
  EXPECT_THROW(io::read_reference(dir + "/ref.csv", "T_star", "missing"), UserError);
  EXPECT_THROW(io::read_reference(dir + "/none.csv", "", ""), UserError);
  std::ofstream(dir + "/bad.csv") << "t,v\n1,2\n0.5,x\n";
  try {
    io::read_reference(dir + "/bad.csv", "", "");
    FAIL() << "a malformed row must be refused";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:3: not a number"), std::string::npos) << e.what();
  }
}

TEST(Metrics, CompareToolPrintsTheMetricAsJson) {
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/io_metrics";
  io::make_directories(dir);
  std::ofstream(dir + "/probes.csv") << "t,x\n0,1\n1,2\n2,3\n";
  std::ofstream(dir + "/ref.csv") << "time,x\n0.5,0.25\n1.5,1.25\n";
  std::ostringstream out;
  ASSERT_EQ(io::run_compare_tool({dir, "--probe", "x", "--metric", "rms", "--reference", dir + "/ref.csv",
                                  "--subtract-initial", "--relative-to", "2"},
                                 out),
            0);
  // The run relative to its start is t; the reference is t - 0.25: RMS 0.25, relative 0.125.
  EXPECT_NE(out.str().find("\"value\": 0.25"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("\"relative\": 0.125"), std::string::npos) << out.str();
  // A closed form: the probe's peak 3 against 2.5, and its RMS about a constant 2 over its samples 1, 2, 3.
  std::ostringstream closed;
  ASSERT_EQ(
      io::run_compare_tool({dir, "--probe", "x", "--metric", "peak", "--reference-value", "2.5"}, closed), 0);
  EXPECT_NE(closed.str().find("\"value\": 0.5"), std::string::npos) << closed.str();
  std::ostringstream closed_rms;
  ASSERT_EQ(
      io::run_compare_tool({dir, "--probe", "x", "--metric", "rms", "--reference-value", "2"}, closed_rms),
      0);
  EXPECT_NE(closed_rms.str().find("\"value\": " + io::Json(std::sqrt(2.0 / 3.0)).dump()), std::string::npos)
      << closed_rms.str();
  // Smoothed over 2.5 s: 1.5, 2, 2.5 (the ends average two samples, the middle three); their mean is 2.
  std::ostringstream smoothed;
  ASSERT_EQ(io::run_compare_tool({dir, "--probe", "x", "--metric", "mean", "--smooth", "2.5"}, smoothed), 0);
  EXPECT_NE(smoothed.str().find("\"value\": 2,"), std::string::npos) << smoothed.str();
  // The noise against a closed form is the run's own (a constant has none): the line's 0, not 0 - 2.
  std::ostringstream closed_noise;
  ASSERT_EQ(io::run_compare_tool(
                {dir, "--probe", "x", "--metric", "noise", "--smooth", "2.5", "--reference-value", "2"},
                closed_noise),
            0);
  EXPECT_NE(closed_noise.str().find("\"value\": " + io::Json(std::sqrt(0.5 * 0.5 * 2.0 / 3.0)).dump()),
            std::string::npos)
      << closed_noise.str();
  std::ostringstream ignored;
  EXPECT_THROW(io::run_compare_tool({dir, "--probe", "x", "--metric", "noise"}, ignored), UserError);
  EXPECT_THROW(io::run_compare_tool({dir, "--probe", "y", "--metric", "peak"}, ignored), UserError);
  EXPECT_THROW(io::run_compare_tool({dir, "--probe", "x", "--metric", "rms"}, ignored), UserError);
  EXPECT_THROW(io::run_compare_tool({dir, "--probe", "x", "--metric", "peak", "--window", "1"}, ignored),
               UserError);
}
