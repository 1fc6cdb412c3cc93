// `halfeti compare`: one error metric of a run's probe against a reference (io/metrics.hpp), as JSON, for the
// studies (tools/study) and a user's own scripts.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace halfeti::io {

std::string compare_tool_usage();
// Writes {"probe", "metric", "value", "scale", "relative", ...} to `out`; UserError on bad arguments or data.
int run_compare_tool(const std::vector<std::string>& args, std::ostream& out);

}  // namespace halfeti::io
