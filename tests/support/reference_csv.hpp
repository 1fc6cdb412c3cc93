// Reference data files of inputs/validation/data: '#' comment lines (provenance), one header row, then rows of
// comma-separated numbers.
#pragma once

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace halfeti::test {

// The numeric rows of such a file; a row is cut at its first field that is not a number. Empty if the file is
// missing (the caller's assertion on the row count names it).
inline std::vector<std::vector<double>> read_reference_csv(const std::string& path) {
  std::vector<std::vector<double>> rows;
  std::ifstream in(path);
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream is(line);
    std::vector<double> row;
    for (double v; is >> v;) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

}  // namespace halfeti::test
