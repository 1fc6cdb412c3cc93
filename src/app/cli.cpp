#include "halfeti/app/cli.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "halfeti/core/error.hpp"
#include "halfeti/core/version.hpp"

namespace halfeti::app {

std::string usage_text() {
  return R"(halfeti: submerged elastic plate, cables and sloshing water under earthquakes (delta-SPH + FE + contact)

usage:
  halfeti run SCENE.yaml [--set key.path=value ...] [--out DIR] [--restart PATH] [--overwrite]
              [--max-wall SECONDS] [--trace coupling] [-- PETSc options]
              [--max-memory SIZE]
  halfeti check SCENE.yaml [--set key.path=value ...] [--max-memory SIZE]
  halfeti cable --from X1,Y1 --to X2,Y2 --modulus E --area A --density RHO
                (--unstretched-length L0 | --tension-stress S) [...]   (halfeti cable --help)
  halfeti compare RUN --probe NAME --metric METRIC [--reference FILE ...]   (halfeti compare --help)
  halfeti reference        print the scene reference (Markdown)
  halfeti --help | --version

run      runs the scene; outputs go to DIR (default out/<scene.name>): probes.csv, summary.json, log.txt,
         scene.resolved.yaml, fields/ (HDF5 + XDMF) and checkpoints/.
check    checks the scene (keys, types, ranges, files it names) and prints the resolved scene.
compare  one error metric of a run's probe against reference data (RMS, peak, frequency, ...), as JSON.
--set    overrides one key before checking, e.g. --set fluid.spacing=0.002 --set probes.0.at=[0.3,0.005]
--restart  continues a run from a checkpoint file, or from the latest checkpoint of a run folder; the scene (with
         the same --set) may change only scene.end_time, scene.description and output.*. Into the run's own
         folder (--out the same) it continues probes.csv, the fields and log.txt; bit for bit the run that never
         stopped, on any number of ranks.
--overwrite  replaces another run's outputs in DIR (a run refuses a folder that holds them otherwise)
--max-wall   stops at a step boundary, with a checkpoint, before SECONDS of wall time (as SIGTERM, SIGINT and
         SIGUSR1 do at any time), with exit status 5
--max-memory  refuses (exit status 2) a scene whose estimated memory on its busiest rank exceeds SIZE (e.g. 8G,
         512M, 2GiB; default: the machine's memory); `check` prints the estimate
--trace coupling  a diagnostic line per coupled step and per invader on stderr (the contact's and the plate-wall
         forces, the fastest particle; docs/coupling.md's noise figures)

exit status: 0 success, 2 bad input (scene, file, option), 3 numerical failure, 4 internal error, 5 stopped by a
signal or --max-wall (resumable with --restart), 6 an output could not be written (disk full, permission).
)";
}

double parse_memory_size(const std::string& text, const char* option) {
  static const std::pair<const char*, double> kUnits[] = {{"", 1.0},
                                                          {"k", 1e3},
                                                          {"K", 1e3},
                                                          {"M", 1e6},
                                                          {"G", 1e9},
                                                          {"T", 1e12},
                                                          {"Ki", 1024.0},
                                                          {"Mi", 1024.0 * 1024.0},
                                                          {"Gi", 1073741824.0},
                                                          {"Ti", 1099511627776.0}};
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  std::string unit(end ? end : "");
  if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b')) unit.pop_back();
  double scale = 0.0;
  for (const auto& [name, factor] : kUnits)
    if (unit == name) scale = factor;
  const double bytes = number * scale;
  if (end == text.c_str() || scale == 0.0 || !(bytes >= 1.0) || !std::isfinite(bytes))
    HALFETI_USER_ERROR(option << " takes a memory size such as 8G, 512M or 2GiB, got '" << text << "'");
  return bytes;
}

std::string version_text() {
  return std::string("halfeti ") + kVersion + " (commit " + kGitCommit + ")";
}

Command parse_command_line(const std::vector<std::string>& args) {
  Command c;
  if (args.empty()) HALFETI_USER_ERROR("no command given; try 'halfeti --help'");
  const std::string& word = args[0];
  if (word == "--help" || word == "-h" || word == "help") {
    c.kind = Command::Kind::kHelp;
    return c;
  }
  if (word == "--version") {
    c.kind = Command::Kind::kVersion;
    return c;
  }
  if (word == "reference") {
    if (args.size() > 1)
      HALFETI_USER_ERROR("'halfeti reference' takes no arguments, found '" << args[1] << "'");
    c.kind = Command::Kind::kReference;
    return c;
  }
  if (word == "cable" || word == "compare") {
    c.kind = word == "cable" ? Command::Kind::kCable : Command::Kind::kCompare;
    c.tool_args.assign(args.begin() + 1, args.end());
    return c;
  }
  if (word == "run")
    c.kind = Command::Kind::kRun;
  else if (word == "check")
    c.kind = Command::Kind::kCheck;
  else
    HALFETI_USER_ERROR("unknown command '"
                       << word << "'; expected run, check, cable, compare, reference, --help or --version");

  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    const auto value = [&](const char* option) -> const std::string& {
      if (i + 1 >= args.size()) HALFETI_USER_ERROR("option " << option << " needs a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h") {  // `halfeti run --help`, `halfeti check --help`
      c = Command{};
      c.kind = Command::Kind::kHelp;
      return c;
    }
    if (a == "--") {
      if (c.kind != Command::Kind::kRun) HALFETI_USER_ERROR("PETSc options (after --) go with 'halfeti run'");
      c.petsc_args.assign(args.begin() + static_cast<long>(i) + 1, args.end());
      break;
    } else if (a == "--set") {
      c.overrides.push_back(value("--set"));
    } else if (a.rfind("--set=", 0) == 0) {
      c.overrides.push_back(a.substr(6));
    } else if (a == "--out" && c.kind == Command::Kind::kRun) {
      c.out_dir = value("--out");
    } else if (a == "--restart" && c.kind == Command::Kind::kRun) {
      c.restart = value("--restart");
    } else if (a == "--overwrite" && c.kind == Command::Kind::kRun) {
      c.overwrite = true;
    } else if (a == "--max-wall" && c.kind == Command::Kind::kRun) {
      const std::string& v = value("--max-wall");
      char* end = nullptr;
      c.max_wall = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !(c.max_wall > 0.0) || !std::isfinite(c.max_wall))
        HALFETI_USER_ERROR("--max-wall takes a positive number of seconds, got '" << v << "'");
    } else if (a == "--max-memory") {
      c.max_memory = parse_memory_size(value("--max-memory"), "--max-memory");
    } else if (a == "--trace" && c.kind == Command::Kind::kRun) {
      const std::string& v = value("--trace");
      if (v != "coupling")
        HALFETI_USER_ERROR("--trace takes 'coupling' (the one diagnostic trace), got '" << v << "'");
      c.trace_coupling = true;
    } else if (!a.empty() && a[0] == '-') {
      HALFETI_USER_ERROR("unknown option '" << a << "' for 'halfeti " << word << "'; try 'halfeti --help'");
    } else if (c.scene.empty()) {
      c.scene = a;
    } else {
      HALFETI_USER_ERROR("one scene per run: found '" << c.scene << "' and '" << a << "'");
    }
  }
  if (c.scene.empty())
    HALFETI_USER_ERROR("'halfeti " << word << "' needs a scene file, e.g. halfeti " << word
                                   << " inputs/validation/dambreak.yaml");
  return c;
}

}  // namespace halfeti::app
