// Error metrics of a probe's curve against a reference: the one home for the validation tests, `halfeti compare`
// and the studies (tools/study). A curve is (t, v) with t increasing; between samples it is linear, beyond its ends
// it holds its end values.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace halfeti::io {

struct Curve {
  std::vector<double> t, v;
};

// The time range a metric looks at (inclusive).
struct Window {
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
  bool contains(double t) const { return t >= from && t <= to; }
};

// The curve's value at t (linear between samples, held beyond the ends). UserError on an empty curve.
double value_at(const Curve& c, double t);

// RMS of run(t_k) - reference(t_k) over the reference's samples t_k in the window (the run interpolated at them).
// UserError if no reference sample lies in the window or the run does not cover the window's samples.
double rms_error(const Curve& run, const Curve& reference, const Window& w = {});

// RMS of (run(t_k) - reference(t_k)) / reference(t_k): each sample's error relative to the reference's value there
// (UserError where a reference value is 0).
double rms_relative_error(const Curve& run, const Curve& reference, const Window& w = {});

// The largest value (or largest |value|) of the curve's samples in the window, and its time.
struct Peak {
  double value = 0.0, time = 0.0;
};
Peak peak(const Curve& c, const Window& w = {}, bool absolute = false);

// Frequency [Hz] from the upward crossings of `level` (NaN: the curve's mean over the window; each crossing's time
// interpolated linearly): (n - 1) / (last - first) over n >= 2 crossings. UserError with fewer than two.
double crossing_frequency(const Curve& c, const Window& w = {},
                          double level = std::numeric_limits<double>::quiet_NaN());

// Mean of the curve's samples in the window (a static value). UserError when none lies in it.
double mean_value(const Curve& c, const Window& w = {});

// The curve's centred running mean: at each sample t_k the mean of the samples within t_k +- width / 2 (fewer at
// the curve's ends); a sensor's low-pass, whose first zero lies at 1 / width. UserError unless width > 0.
Curve running_mean(const Curve& c, double width);

// Noise: the RMS over the window's samples of the curve minus its centred running mean of `width` (the mean taken
// over the whole curve, so the window's edges see samples beyond them), i.e. roughly the part of the signal above
// 1 / width. UserError unless width > 0 or when no sample lies in the window.
double noise(const Curve& c, double width, const Window& w = {});

// The metrics by name, for a study's file and `halfeti compare`: "rms" and "rms_relative" (need a reference), "peak", "peak_abs",
// "peak_time", "frequency", "mean", "noise", and their errors against a reference curve's own value ("peak",
// "peak_time", "frequency", "mean", "noise" with a reference: run's minus reference's). smooth > 0: the run's
// curve is first replaced by its running mean of that width (the reference is not smoothed); "noise" needs it,
// as the width its running mean is taken over, and measures the part the smoothing removes.
bool metric_needs_reference(const std::string& name);  // UserError naming the metric if it is unknown
double metric(const std::string& name, const Curve& run, const Curve* reference, const Window& w = {},
              double smooth = 0.0);
const std::vector<std::string>& metric_names();

// A column pair of a reference data file (inputs/validation/data: '#' comment lines naming the provenance, a
// header row, comma-separated numbers), chosen by header name (empty: the first, the second); `time_scale` and `value_scale` turn its units into
// the probe's (t = time_scale * column, v = value_scale * column). UserError naming the file and the column.
Curve read_reference(const std::string& path, const std::string& time_column, const std::string& value_column,
                     double time_scale = 1.0, double value_scale = 1.0);

}  // namespace halfeti::io
