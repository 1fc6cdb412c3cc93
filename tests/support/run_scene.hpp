// Runs the halfeti program on a scene (optionally under mpirun) from a test and reads what it wrote.
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "halfeti/io/probe_writer.hpp"

namespace halfeti::test {

inline std::string source_path(const std::string& relative) {
  return std::string(HALFETI_SOURCE_DIR) + "/" + relative;
}
inline std::string binary_path(const std::string& relative) {
  return std::string(HALFETI_BINARY_DIR) + "/" + relative;
}

// Runs `halfeti run SCENE --out OUT --overwrite ARGS` on `ranks` ranks (0: without mpirun); returns the exit
// status. (--overwrite: a test's folder holds the test's previous run.)
inline int run_scene(const std::string& scene, const std::string& out, const std::string& args = "",
                     int ranks = 0) {
  std::string cmd;
  if (ranks > 0) cmd = source_path("tests/support/clean-mpirun") + " -n " + std::to_string(ranks) + " ";
  cmd += binary_path("src/app/halfeti") + " run " + scene + " --out " + out + " --overwrite " + args + " >" +
         out + ".stdout 2>" + out + ".stderr";
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// Linear interpolation of a probe column v(t) at `when` (held constant beyond the ends).
inline double interpolate(const std::vector<double>& t, const std::vector<double>& v, double when) {
  const auto it = std::lower_bound(t.begin(), t.end(), when);
  if (it == t.begin()) return v.front();
  if (it == t.end()) return v.back();
  const std::size_t k = static_cast<std::size_t>(it - t.begin());
  const double f = (when - t[k - 1]) / (t[k] - t[k - 1]);
  return (1.0 - f) * v[k - 1] + f * v[k];
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace halfeti::test
