// `halfeti cable` design tool: one cable set between two points, reported as JSON.
#include "halfeti/cable/cable_tool.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <optional>

#include "halfeti/cable/cable_set.hpp"
#include "halfeti/cable/catenary.hpp"
#include "halfeti/core/error.hpp"

namespace halfeti::cable {
namespace {

double parse_number(const std::string& option, const std::string& text, const char* expected) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(value))
    HALFETI_USER_ERROR("halfeti cable: " << option << " expects " << expected << ", got '" << text << "'");
  return value;
}

Eigen::Vector2d parse_point(const std::string& option, const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    HALFETI_USER_ERROR("halfeti cable: " << option << " expects a point X,Y in metres, got '" << text << "'");
  return {parse_number(option, text.substr(0, comma), "a point X,Y in metres"),
          parse_number(option, text.substr(comma + 1), "a point X,Y in metres")};
}

double positive(const std::string& option, double value, const char* what) {
  if (!(value > 0.0))
    HALFETI_USER_ERROR("halfeti cable: " << option << " expects " << what << ", got " << value);
  return value;
}

struct ToolInput {
  Eigen::Vector2d from, to;
  CableSet set;
  std::optional<double> unstretched_length;
  std::optional<double> tension_stress;
};

ToolInput parse(const std::vector<std::string>& args) {
  static const std::map<std::string, const char*> kOptions = {{"--from", "a point X,Y"},
                                                              {"--to", "a point X,Y"},
                                                              {"--modulus", "E in Pa"},
                                                              {"--area", "A in m^2"},
                                                              {"--density", "rho in kg/m^3"},
                                                              {"--count", "a whole number N >= 1"},
                                                              {"--depth", "B in m"},
                                                              {"--gravity", "g in m/s^2"},
                                                              {"--submerged-in", "rho_w in kg/m^3"},
                                                              {"--unstretched-length", "L0 in m"},
                                                              {"--tension-stress", "S in Pa"}};
  std::map<std::string, std::string> given;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& option = args[i];
    const auto known = kOptions.find(option);
    if (known == kOptions.end())
      HALFETI_USER_ERROR("halfeti cable: unknown option '" << option << "' (see halfeti cable --help)");
    if (i + 1 >= args.size() || (args[i + 1].rfind("--", 0) == 0 && kOptions.count(args[i + 1])))
      HALFETI_USER_ERROR("halfeti cable: " << option << " expects a value (" << known->second << ")");
    if (given.count(option)) HALFETI_USER_ERROR("halfeti cable: " << option << " is given twice");
    given[option] = args[++i];
  }
  for (const char* required : {"--from", "--to", "--modulus", "--area", "--density"})
    if (!given.count(required))
      HALFETI_USER_ERROR("halfeti cable: " << required << " is required (" << kOptions.at(required) << ")");
  const bool has_l0 = given.count("--unstretched-length") > 0;
  const bool has_s = given.count("--tension-stress") > 0;
  if (has_l0 == has_s)
    HALFETI_USER_ERROR("halfeti cable: give exactly one of --unstretched-length L0 and --tension-stress S");

  ToolInput in;
  in.from = parse_point("--from", given["--from"]);
  in.to = parse_point("--to", given["--to"]);
  if ((in.to - in.from).norm() == 0.0)
    HALFETI_USER_ERROR("halfeti cable: --from and --to are the same point");
  in.set.modulus =
      positive("--modulus", parse_number("--modulus", given["--modulus"], "E in Pa"), "E > 0 in Pa");
  in.set.area = positive("--area", parse_number("--area", given["--area"], "A in m^2"), "A > 0 in m^2");
  in.set.density = parse_number("--density", given["--density"], "rho in kg/m^3");
  if (!(in.set.density >= 0.0))
    HALFETI_USER_ERROR("halfeti cable: --density expects rho >= 0 in kg/m^3, got " << in.set.density);
  if (given.count("--count")) {
    const double n = parse_number("--count", given["--count"], "a whole number N >= 1");
    if (!(n >= 1.0) || n != std::floor(n) || n > 1e9)
      HALFETI_USER_ERROR("halfeti cable: --count expects a whole number N >= 1, got " << given["--count"]);
    in.set.count = static_cast<int>(n);
  }
  if (given.count("--depth"))
    in.set.depth = positive("--depth", parse_number("--depth", given["--depth"], "B in m"), "B > 0 in m");
  if (given.count("--gravity")) {
    in.set.gravity = parse_number("--gravity", given["--gravity"], "g in m/s^2");
    if (!(in.set.gravity >= 0.0))
      HALFETI_USER_ERROR("halfeti cable: --gravity expects g >= 0 in m/s^2, got " << in.set.gravity);
  }
  if (given.count("--submerged-in")) {
    in.set.fluid_density = parse_number("--submerged-in", given["--submerged-in"], "rho_w in kg/m^3");
    if (!(in.set.fluid_density >= 0.0))
      HALFETI_USER_ERROR("halfeti cable: --submerged-in expects rho_w >= 0 in kg/m^3, got "
                         << in.set.fluid_density);
  }
  if (has_l0)
    in.unstretched_length = positive(
        "--unstretched-length",
        parse_number("--unstretched-length", given["--unstretched-length"], "L0 in m"), "L0 > 0 in m");
  if (has_s)
    in.tension_stress =
        positive("--tension-stress", parse_number("--tension-stress", given["--tension-stress"], "S in Pa"),
                 "S > 0 in Pa");
  return in;
}

void write_end(std::ostream& out, const char* name, const CableSet& set, double tension) {
  out << "  \"" << name << "\": {\"tension_per_depth\": " << tension
      << ", \"tension_per_cable\": " << tension_per_cable(set, tension)
      << ", \"stress\": " << tension_stress(set, tension) << "},\n";
}

}  // namespace

std::string cable_tool_usage() {
  return "usage: halfeti cable --from X1,Y1 --to X2,Y2 --modulus E --area A --density RHO\n"
         "                     [--count N] [--depth B] [--gravity G] [--submerged-in RHO_W]\n"
         "                     (--unstretched-length L0 | --tension-stress S)\n"
         "\n"
         "Solves one elastic catenary cable set from --from (end 1, the anchor, s0 = 0) to --to (end 2, the\n"
         "structure) and prints JSON: end tensions (per unit depth [N/m], per real cable [N], stress [Pa]),\n"
         "tension components at --from, slack/taut state, sag, the unstretched length and the 4x4 tangent\n"
         "stiffness per unit depth in the order (x1, y1, x2, y2).\n"
         "  N real cables (default 1) of area A [m^2], modulus E [Pa] and density RHO [kg/m^3] span a depth "
         "B\n"
         "  (default 1 m): per unit depth EA' = N E A / B and w' = N (RHO - RHO_W) A g / B (RHO_W = 0 in "
         "air).\n"
         "  --tension-stress S finds the unstretched length L0 whose tension stress at --to is S.\n";
}

int run_cable_tool(const std::vector<std::string>& args, std::ostream& out) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      out << cable_tool_usage();
      return 0;
    }
  const ToolInput in = parse(args);
  const PerDepthCable per_depth = per_unit_depth(in.set);
  double l0 = 0.0;
  if (in.unstretched_length) {
    l0 = *in.unstretched_length;
  } else {
    const double tension = *in.tension_stress * per_depth.area;
    l0 = unstretched_length_for_end_tension(in.from, in.to, per_depth.axial_stiffness,
                                            per_depth.weight_per_length, tension);
  }
  const CatenarySolution s = solve_catenary(in.from, in.to, cable_properties(in.set, l0));

  out << std::setprecision(12);
  out << "{\n";
  out << "  \"from\": [" << in.from.x() << ", " << in.from.y() << "],\n";
  out << "  \"to\": [" << in.to.x() << ", " << in.to.y() << "],\n";
  out << "  \"count\": " << in.set.count << ",\n";
  out << "  \"depth\": " << in.set.depth << ",\n";
  out << "  \"axial_stiffness_per_depth\": " << per_depth.axial_stiffness << ",\n";
  out << "  \"weight_per_length_per_depth\": " << per_depth.weight_per_length << ",\n";
  out << "  \"unstretched_length\": " << l0 << ",\n";
  out << "  \"chord\": " << s.chord << ",\n";
  out << "  \"state\": \"" << to_string(s.state) << "\",\n";
  out << "  \"sag\": " << s.sag << ",\n";
  out << "  \"tension_components_from\": {\"Tx\": " << s.end_tension.x() << ", \"Ty\": " << s.end_tension.y()
      << "},\n";
  write_end(out, "tension_from", in.set, s.tension_start);
  write_end(out, "tension_to", in.set, s.tension_end);
  out << "  \"tangent_stiffness\": [";
  for (int i = 0; i < 4; ++i) {
    out << (i ? ",\n                        [" : "[");
    for (int j = 0; j < 4; ++j) out << (j ? ", " : "") << s.tangent(i, j);
    out << "]";
  }
  out << "],\n";
  out << "  \"units\": {\"tension_per_depth\": \"N/m\", \"tension_per_cable\": \"N\", \"stress\": \"Pa\", "
         "\"tangent_stiffness\": \"N/m per m (per unit depth), order x1 y1 x2 y2\", \"lengths\": \"m\"}\n";
  out << "}\n";
  return 0;
}

}  // namespace halfeti::cable
