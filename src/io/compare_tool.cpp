#include "halfeti/io/compare_tool.hpp"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <optional>

#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"
#include "halfeti/io/json.hpp"
#include "halfeti/io/metrics.hpp"
#include "halfeti/io/probe_writer.hpp"

namespace halfeti::io {

std::string compare_tool_usage() {
  return R"(halfeti compare RUN --probe NAME --metric METRIC [options]

One error metric of a run's probe (RUN: a run folder or its probes.csv), printed as JSON.

  --metric M         rms, rms_relative (each sample's error over the reference's value; both need --reference),
                     peak, peak_abs, peak_time, frequency (upward crossings of the mean), mean, noise (RMS of
                     the probe minus its --smooth running mean); with --reference, peak/peak_abs/peak_time/
                     frequency/mean/noise are the run's minus the reference's
  --reference FILE   reference data (a '#'-commented CSV with a header row)
  --reference-value X  a closed-form reference, constant in time (rms, rms_relative, noise: a curve of X at the
                     run's own samples, whose noise is 0; the others: the run's metric minus X)
  --columns T,V      the reference's time and value columns, by header name (default: the first two)
  --reference-scale A,B  reference time and value in the probe's units: t = A * T, v = B * V (default 1,1)
  --probe-scale S    the probe's values times S before comparing (default 1)
  --subtract-initial the probe's first value subtracted (a displacement relative to the start)
  --window FROM,TO   the times looked at [s] (default: all)
  --smooth W         the probe replaced by its centred running mean over W seconds before the metric (a
                     sensor's low-pass); for noise, the running mean's width (required)
  --relative-to S    also print value / S as "relative" (a stated scale: a peak, a depth)
)";
}

namespace {

std::pair<double, double> two_numbers(const std::string& option, const std::string& text) {
  const std::size_t comma = text.find(',');
  char *e1 = nullptr, *e2 = nullptr;
  if (comma != std::string::npos) {
    const std::string a = text.substr(0, comma), b = text.substr(comma + 1);
    const double x = std::strtod(a.c_str(), &e1), y = std::strtod(b.c_str(), &e2);
    if (!a.empty() && !b.empty() && *e1 == '\0' && *e2 == '\0') return {x, y};
  }
  HALFETI_USER_ERROR("compare: " << option << " takes two numbers A,B, found '" << text << "'");
}

double number(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(x))
    HALFETI_USER_ERROR("compare: " << option << " takes a number, found '" << text << "'");
  return x;
}

}  // namespace

int run_compare_tool(const std::vector<std::string>& args, std::ostream& out) {
  for (const auto& a : args)
    if (a == "--help" || a == "-h") {
      out << compare_tool_usage();
      return 0;
    }
  std::string run, probe, name, reference, columns;
  double ts = 1.0, vs = 1.0, probe_scale = 1.0, smooth = 0.0;
  bool subtract_initial = false;
  Window window;
  std::optional<double> scale, reference_value;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) HALFETI_USER_ERROR("compare: option " << a << " needs a value");
      return args[++i];
    };
    if (a == "--probe")
      probe = value();
    else if (a == "--metric")
      name = value();
    else if (a == "--reference")
      reference = value();
    else if (a == "--columns")
      columns = value();
    else if (a == "--reference-scale")
      std::tie(ts, vs) = two_numbers(a, value());
    else if (a == "--probe-scale")
      probe_scale = number(a, value());
    else if (a == "--subtract-initial")
      subtract_initial = true;
    else if (a == "--window")
      std::tie(window.from, window.to) = two_numbers(a, value());
    else if (a == "--smooth")
      smooth = number(a, value());
    else if (a == "--relative-to")
      scale = number(a, value());
    else if (a == "--reference-value")
      reference_value = number(a, value());
    else if (!a.empty() && a[0] == '-')
      HALFETI_USER_ERROR("compare: unknown option '" << a << "' (halfeti compare --help)");
    else if (run.empty())
      run = a;
    else
      HALFETI_USER_ERROR("compare: one run only, found '" << run << "' and '" << a << "'");
  }
  if (run.empty()) HALFETI_USER_ERROR("compare: no run given (halfeti compare --help)");
  if (probe.empty()) HALFETI_USER_ERROR("compare: --probe NAME is required");
  if (name.empty()) HALFETI_USER_ERROR("compare: --metric is required");
  const bool needs = metric_needs_reference(name);
  if (needs && reference.empty() && !reference_value)
    HALFETI_USER_ERROR("compare: --metric " << name << " needs --reference FILE or --reference-value X");
  if (!reference.empty() && reference_value)
    HALFETI_USER_ERROR("compare: give --reference FILE or --reference-value X, not both");

  const std::string csv = is_directory(run) ? run + "/probes.csv" : run;
  if (!path_exists(csv)) HALFETI_USER_ERROR("compare: no probes file '" << csv << "'");
  const ProbeTable table = read_probe_csv(csv);
  bool known = false;
  for (const auto& n : table.names) known = known || n == probe;
  if (!known) {
    std::string all;
    for (std::size_t k = 1; k < table.names.size(); ++k) all += (all.empty() ? "" : ", ") + table.names[k];
    HALFETI_USER_ERROR("compare: '" << csv << "' has no probe '" << probe << "' (probes: " << all << ")");
  }
  Curve c{table.column("t"), table.column(probe)};
  if (c.t.empty()) HALFETI_USER_ERROR("compare: '" << csv << "' has no rows");
  const double first = c.v.front();
  for (double& v : c.v) v = probe_scale * (subtract_initial ? v - first : v);

  std::optional<Curve> ref;
  if (!reference.empty()) {
    std::string tc, vc;
    if (!columns.empty()) {
      const std::size_t comma = columns.find(',');
      if (comma == std::string::npos)
        HALFETI_USER_ERROR("compare: --columns takes T,V, found '" << columns << "'");
      tc = columns.substr(0, comma);
      vc = columns.substr(comma + 1);
    }
    ref = read_reference(reference, tc, vc, ts, vs);
  }
  double v = 0.0;
  // A closed form for rms, rms_relative and noise: a constant curve at the run's samples (its noise is 0).
  if (reference_value && (needs || name == "noise")) {
    ref = Curve{c.t, std::vector<double>(c.t.size(), *reference_value)};
    v = metric(name, c, &*ref, window, smooth);
  } else {
    v = metric(name, c, ref ? &*ref : nullptr, window, smooth) - (reference_value ? *reference_value : 0.0);
  }
  Json j = Json::object();
  j.set("run", run).set("probe", probe).set("metric", name).set("value", v);
  j.set("smooth", smooth > 0.0 ? Json(smooth) : Json());
  j.set("reference", !reference.empty() ? Json(reference)
                     : reference_value  ? Json(*reference_value)
                                        : Json());
  j.set("scale", scale ? Json(*scale) : Json());
  j.set("relative", scale && *scale != 0.0 ? Json(v / *scale) : Json());
  out << j.dump() << "\n";
  return 0;
}

}  // namespace halfeti::io
