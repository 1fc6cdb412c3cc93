// Runs the halfeti program on a scene (optionally under mpirun) from a test and reads what it wrote.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "halfeti/io/probe_writer.hpp"

namespace halfeti::test {

inline std::string source_path(const std::string& relative) { return std::string(HALFETI_SOURCE_DIR) + "/" + relative; }
inline std::string binary_path(const std::string& relative) { return std::string(HALFETI_BINARY_DIR) + "/" + relative; }

// Runs `halfeti run SCENE --out OUT ARGS` on `ranks` ranks (0: without mpirun); returns the exit status.
inline int run_scene(const std::string& scene, const std::string& out, const std::string& args = "", int ranks = 0) {
  std::string cmd;
  if (ranks > 0) cmd = source_path("tests/support/clean-mpirun") + " -n " + std::to_string(ranks) + " ";
  cmd += binary_path("src/app/halfeti") + " run " + scene + " --out " + out + " " + args + " >" + out +
         ".stdout 2>" + out + ".stderr";
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace halfeti::test
