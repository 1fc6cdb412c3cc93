#include "halfeti/core/health.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti {

HealthEvent health_event(double time, long long step, const std::string& kind, const std::string& message,
                         bool fatal) {
  HealthEvent e;
  e.time = time;
  e.step = step;
  e.kind = kind;
  e.message = message;
  e.fatal = fatal;
  return e;
}

bool health_worse(const std::string& kind, double a, double b) {
  if (std::isnan(b)) return !std::isnan(a);
  if (std::isnan(a)) return false;
  return kind == "spacing_collapse" ? a < b : a > b;
}

void health_observe(HealthEvent& e, double value, double time, long long step, double x, double y) {
  if (!health_worse(e.kind, value, e.worst)) return;
  e.worst = value;
  e.worst_time = time;
  e.worst_step = step;
  e.worst_x = x;
  e.worst_y = y;
}

HealthTally tally(const HealthLog& log) {
  HealthTally t;
  for (const auto& e : log) {
    HealthTally::Kind& k = t.kinds[e.kind];
    ++k.episodes;
    k.fatal = k.fatal || e.fatal;
    if (!e.fatal) ++t.warnings;
    if (!k.first) k.first = &e;
    if (!k.worst || health_worse(e.kind, e.worst, k.worst->worst)) k.worst = &e;
  }
  return t;
}

std::string warnings_line(const HealthTally& t) {
  if (t.warnings == 0) return "no warnings";
  std::ostringstream os;
  os << t.warnings << (t.warnings == 1 ? " warning (" : " warnings (");
  const char* sep = "";
  for (const auto& [kind, k] : t.kinds) {
    const int n = k.episodes - (k.fatal ? 1 : 0);
    if (n <= 0) continue;
    os << sep << kind << " " << n;
    sep = ", ";
  }
  os << ")";
  return os.str();
}

namespace {
constexpr int kFields = 10;  // tab-separated fields before the message
}

std::string encode_health_log(const HealthLog& log) {
  std::string out;
  for (const auto& e : log) {
    char head[320];
    std::snprintf(head, sizeof head, "%a\t%lld\t%d\t%a\t%a\t%lld\t%a\t%a\t", e.time, e.step, e.fatal ? 1 : 0,
                  e.worst, e.worst_time, e.worst_step, e.worst_x, e.worst_y);
    std::string message = e.message;
    for (char& c : message)
      if (c == '\n' || c == '\t') c = ' ';
    out += head + e.kind + "\t" + message + "\n";
  }
  return out;
}

HealthLog decode_health_log(const std::string& text) {
  HealthLog log;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::size_t start = 0;
    for (int k = 0; k < kFields - 1; ++k) {
      const std::size_t tab = line.find('\t', start);
      if (tab == std::string::npos)
        HALFETI_USER_ERROR("restart: a health-log line of the checkpoint is malformed");
      f.push_back(line.substr(start, tab - start));
      start = tab + 1;
    }
    const auto real = [](const std::string& s) { return std::strtod(s.c_str(), nullptr); };
    HealthEvent e;
    e.time = real(f[0]);
    e.step = std::strtoll(f[1].c_str(), nullptr, 10);
    e.fatal = f[2] == "1";
    e.worst = real(f[3]);
    e.worst_time = real(f[4]);
    e.worst_step = std::strtoll(f[5].c_str(), nullptr, 10);
    e.worst_x = real(f[6]);
    e.worst_y = real(f[7]);
    e.kind = f[8];
    e.message = line.substr(start);
    log.push_back(e);
  }
  return log;
}

}  // namespace halfeti
