#include "halfeti/io/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::io {

double value_at(const Curve& c, double t) {
  if (c.t.empty() || c.t.size() != c.v.size())
    HALFETI_USER_ERROR("metrics: an empty curve (or t and v differ in length)");
  const auto it = std::lower_bound(c.t.begin(), c.t.end(), t);
  if (it == c.t.begin()) return c.v.front();
  if (it == c.t.end()) return c.v.back();
  const std::size_t k = static_cast<std::size_t>(it - c.t.begin());
  if (c.t[k] == t) return c.v[k];
  const double f = (t - c.t[k - 1]) / (c.t[k] - c.t[k - 1]);
  return (1.0 - f) * c.v[k - 1] + f * c.v[k];
}

namespace {
// Sum over the reference's samples in the window of f(run(t_k), reference_k), and their count.
template <class F>
double mean_over_reference(const Curve& run, const Curve& reference, const Window& w, F f) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < reference.t.size(); ++k) {
    const double t = reference.t[k];
    if (!w.contains(t)) continue;
    if (run.t.empty() || t < run.t.front() || t > run.t.back())
      HALFETI_USER_ERROR("metrics: the run (t = " << (run.t.empty() ? 0.0 : run.t.front()) << " ... "
                                                  << (run.t.empty() ? 0.0 : run.t.back())
                                                  << " s) does not cover the reference's sample at t = " << t
                                                  << " s");
    sum += f(value_at(run, t), reference.v[k], t);
    ++n;
  }
  if (n == 0)
    HALFETI_USER_ERROR("metrics: no reference sample in the window [" << w.from << ", " << w.to << "] s");
  return sum / static_cast<double>(n);
}
}  // namespace

double rms_error(const Curve& run, const Curve& reference, const Window& w) {
  return std::sqrt(mean_over_reference(run, reference, w,
                                       [](double r, double ref, double) { return (r - ref) * (r - ref); }));
}

double rms_relative_error(const Curve& run, const Curve& reference, const Window& w) {
  return std::sqrt(mean_over_reference(run, reference, w, [](double r, double ref, double t) {
    if (ref == 0.0)
      HALFETI_USER_ERROR("metrics: a relative error at t = " << t << " s, where the reference is 0");
    return (r - ref) * (r - ref) / (ref * ref);
  }));
}

Peak peak(const Curve& c, const Window& w, bool absolute) {
  Peak p;
  bool found = false;
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    if (!w.contains(c.t[k])) continue;
    const double v = absolute ? std::abs(c.v[k]) : c.v[k];
    if (!found || v > p.value) {
      p = {v, c.t[k]};
      found = true;
    }
  }
  if (!found) HALFETI_USER_ERROR("metrics: no sample in the window [" << w.from << ", " << w.to << "] s");
  return p;
}

double mean_value(const Curve& c, const Window& w) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < c.t.size(); ++k)
    if (w.contains(c.t[k])) {
      sum += c.v[k];
      ++n;
    }
  if (n == 0) HALFETI_USER_ERROR("metrics: no sample in the window [" << w.from << ", " << w.to << "] s");
  return sum / static_cast<double>(n);
}

Curve running_mean(const Curve& c, double width) {
  if (!(width > 0.0)) HALFETI_USER_ERROR("metrics: a running mean needs a width > 0, found " << width);
  Curve out{c.t, std::vector<double>(c.v.size())};
  // Two pointers over the sorted times: [lo, hi) holds the samples within t_k +- width / 2.
  std::size_t lo = 0, hi = 0;
  double sum = 0.0;
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    while (hi < c.t.size() && c.t[hi] <= c.t[k] + 0.5 * width) sum += c.v[hi++];
    while (c.t[lo] < c.t[k] - 0.5 * width) sum -= c.v[lo++];
    out.v[k] = sum / static_cast<double>(hi - lo);
  }
  return out;
}

double noise(const Curve& c, double width, const Window& w) {
  return rms_error(c, running_mean(c, width), w);  // the running mean shares the curve's samples
}

double crossing_frequency(const Curve& c, const Window& w, double level) {
  const double mean = std::isnan(level) ? mean_value(c, w) : level;
  std::vector<double> crossings;
  for (std::size_t k = 1; k < c.t.size(); ++k) {
    if (!w.contains(c.t[k - 1]) || !w.contains(c.t[k])) continue;
    const double a = c.v[k - 1] - mean, b = c.v[k] - mean;
    if (a < 0.0 && b >= 0.0) crossings.push_back(c.t[k - 1] + (c.t[k] - c.t[k - 1]) * (-a) / (b - a));
  }
  if (crossings.size() < 2)
    HALFETI_USER_ERROR("metrics: " << crossings.size() << " upward crossing(s) of the mean in the window ["
                                   << w.from << ", " << w.to << "] s; a frequency needs two or more");
  return static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
}

const std::vector<std::string>& metric_names() {
  static const std::vector<std::string> names = {"rms",       "rms_relative", "peak", "peak_abs",
                                                 "peak_time", "frequency",    "mean", "noise"};
  return names;
}

bool metric_needs_reference(const std::string& name) {
  const auto& n = metric_names();
  if (std::find(n.begin(), n.end(), name) == n.end()) {
    std::string all;
    for (const auto& m : n) all += (all.empty() ? "" : ", ") + m;
    HALFETI_USER_ERROR("metrics: unknown metric '" << name << "' (one of: " << all << ")");
  }
  return name == "rms" || name == "rms_relative";
}

double metric(const std::string& name, const Curve& run, const Curve* reference, const Window& w,
              double smooth) {
  if (metric_needs_reference(name) && !reference)
    HALFETI_USER_ERROR("metrics: '" << name << "' needs a reference curve");
  if (smooth < 0.0 || !std::isfinite(smooth))
    HALFETI_USER_ERROR("metrics: the smoothing width must be >= 0 s, found " << smooth);
  if (name == "noise") {
    if (smooth == 0.0)
      HALFETI_USER_ERROR("metrics: 'noise' needs a smoothing width (the running mean's) > 0");
    return reference ? noise(run, smooth, w) - noise(*reference, smooth, w) : noise(run, smooth, w);
  }
  if (smooth > 0.0) return metric(name, running_mean(run, smooth), reference, w);
  const auto of = [&](const Curve& c) {
    if (name == "peak") return peak(c, w).value;
    if (name == "peak_abs") return peak(c, w, true).value;
    if (name == "peak_time") return peak(c, w).time;
    if (name == "frequency") return crossing_frequency(c, w);
    return mean_value(c, w);  // "mean"
  };
  if (name == "rms") return rms_error(run, *reference, w);
  if (name == "rms_relative") return rms_relative_error(run, *reference, w);
  return reference ? of(run) - of(*reference) : of(run);
}

Curve read_reference(const std::string& path, const std::string& time_column, const std::string& value_column,
                     double time_scale, double value_scale) {
  std::ifstream in(path);
  if (!in) HALFETI_USER_ERROR("cannot open reference data '" << path << "'");
  std::string line;
  std::vector<std::string> header;
  int ti = -1, vi = -1, line_no = 0;
  Curve c;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');) {
      f.erase(0, f.find_first_not_of(" \t\r"));
      f.erase(f.find_last_not_of(" \t\r") + 1);
      fields.push_back(f);
    }
    if (header.empty()) {
      header = fields;
      for (std::size_t k = 0; k < header.size(); ++k) {
        if (header[k] == time_column) ti = static_cast<int>(k);
        if (header[k] == value_column) vi = static_cast<int>(k);
      }
      if (time_column.empty()) ti = 0;  // unnamed: the first two columns
      if (value_column.empty() && header.size() > 1) vi = 1;
      std::string names;
      for (const auto& h : header) names += (names.empty() ? "" : ", ") + h;
      if (ti < 0)
        HALFETI_USER_ERROR(path << ": no column '" << time_column << "' (columns: " << names << ")");
      if (vi < 0)
        HALFETI_USER_ERROR(path << ": no column '" << value_column << "' (columns: " << names << ")");
      continue;
    }
    const std::size_t need = static_cast<std::size_t>(std::max(ti, vi));
    char* end = nullptr;
    if (fields.size() <= need)
      HALFETI_USER_ERROR(path << ":" << line_no << ": " << fields.size() << " fields, the columns need "
                              << need + 1);
    const double t = std::strtod(fields[static_cast<std::size_t>(ti)].c_str(), &end);
    const bool t_ok = end && *end == '\0' && !fields[static_cast<std::size_t>(ti)].empty();
    const double v = std::strtod(fields[static_cast<std::size_t>(vi)].c_str(), &end);
    const bool v_ok = end && *end == '\0' && !fields[static_cast<std::size_t>(vi)].empty();
    if (!t_ok || !v_ok) HALFETI_USER_ERROR(path << ":" << line_no << ": not a number in '" << line << "'");
    if (!c.t.empty() && time_scale * t <= c.t.back())
      HALFETI_USER_ERROR(path << ":" << line_no << ": time " << t << " does not increase");
    c.t.push_back(time_scale * t);
    c.v.push_back(value_scale * v);
  }
  if (header.empty() || c.t.empty()) HALFETI_USER_ERROR(path << ": no data rows");
  return c;
}

}  // namespace halfeti::io
