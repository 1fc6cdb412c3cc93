// Reading accelerogram CSV files (e.g. inputs/records/elcentro_ns.csv).
#include <cmath>
#include <fstream>
#include <sstream>

#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"
#include "halfeti/excitation/ground_motion.hpp"

namespace halfeti::excitation {

namespace {
constexpr double kStandardGravity = 9.80665;
}

std::unique_ptr<GroundMotion> read_record_csv(const std::string& path, const std::string& units, double scale,
                                              double start, double end, double time_shift) {
  if (is_directory(path)) HALFETI_USER_ERROR("accelerogram '" << path << "' is a folder, not a record file");
  std::ifstream in(path);
  if (!in) HALFETI_USER_ERROR("cannot open accelerogram '" << path << "': no such file or not readable");
  double unit_factor = 1.0;
  if (units == "g")
    unit_factor = kStandardGravity;
  else if (units != "m/s2")
    HALFETI_USER_ERROR("accelerogram '" << path << "': units must be g or m/s2, found '" << units << "'");

  std::vector<double> t, a;
  std::string line;
  int line_no = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {  // one header row naming the columns
      header_seen = true;
      continue;
    }
    std::stringstream ss(line);
    std::string c0, c1;
    std::getline(ss, c0, ',');
    std::getline(ss, c1, ',');
    double ti = 0, ai = 0;
    try {
      size_t used0 = 0, used1 = 0;
      ti = std::stod(c0, &used0);
      ai = std::stod(c1, &used1);
    } catch (const std::exception&) {
      HALFETI_USER_ERROR(path << ":" << line_no << ": expected 'time, acceleration' numbers, found '" << line
                              << "'");
    }
    if (!std::isfinite(ti) || !std::isfinite(ai))
      HALFETI_USER_ERROR(path << ":" << line_no << ": non-finite value in '" << line << "'");
    if (!t.empty() && ti <= t.back())
      HALFETI_USER_ERROR(path << ":" << line_no << ": times must increase, found " << ti << " after "
                              << t.back());
    t.push_back(ti + time_shift);
    a.push_back(ai * unit_factor * scale);
  }
  if (t.size() < 2) HALFETI_USER_ERROR("accelerogram '" << path << "': fewer than two data rows");
  return make_record(std::move(t), std::move(a), start, end, path);
}

}  // namespace halfeti::excitation
