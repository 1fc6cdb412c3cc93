// The command line of `halfeti`.
#pragma once

#include <string>
#include <vector>

namespace halfeti::app {

struct Command {
  enum class Kind { kRun, kCheck, kHelp, kVersion, kReference, kCable, kCompare };
  Kind kind = Kind::kHelp;
  std::string scene;                    // run, check
  std::vector<std::string> overrides;   // --set key.path=value
  std::string out_dir;                  // --out (default out/<scene name>)
  std::string restart;                  // --restart PATH
  bool overwrite = false;               // --overwrite
  double max_wall = 0.0;                // --max-wall SECONDS (0: none)
  double max_memory = 0.0;              // --max-memory SIZE in bytes per rank (0: the machine's memory)
  bool trace_coupling = false;          // --trace coupling
  std::vector<std::string> petsc_args;  // after --
  std::vector<std::string> tool_args;   // cable: everything after the word
};

// Parses argv (without the program name); throws UserError for a malformed command line.
Command parse_command_line(const std::vector<std::string>& args);

// "8G", "512MB", "2.5GiB", "3e9": a memory size in bytes (k, M, G, T decimal; Ki, Mi, Gi, Ti binary; an optional
// trailing B). Throws UserError naming `option` for anything else.
double parse_memory_size(const std::string& text, const char* option);

std::string usage_text();
std::string version_text();

}  // namespace halfeti::app
