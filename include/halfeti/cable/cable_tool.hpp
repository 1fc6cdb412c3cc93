// `halfeti cable`: design one cable set (tension, sag, stiffness, or the unstretched length for a
// pretension).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace halfeti::cable {

// `args` are the arguments after `halfeti cable`. Prints JSON (or the usage for --help) to `out` and returns
// the exit status (0). Bad input throws halfeti::UserError naming the option.
int run_cable_tool(const std::vector<std::string>& args, std::ostream& out);

// The usage text printed by --help.
std::string cable_tool_usage();

}  // namespace halfeti::cable
