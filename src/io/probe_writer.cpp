#include "halfeti/io/probe_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "halfeti/core/error.hpp"
#include "halfeti/io/json.hpp"

namespace halfeti::io {

ProbeWriter::ProbeWriter(const std::string& path, const std::vector<std::string>& names, bool writer,
                         const std::vector<std::string>& carried_rows)
    : path_(path), names_(names) {
  for (const auto& n : names)
    HALFETI_CHECK(n.find(',') == std::string::npos && n != "t",
                  "probe name '" << n << "' cannot be a CSV column");
  if (!writer) return;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) HALFETI_IO_ERROR("cannot write probes to '" << path << "': " << std::strerror(errno));
  std::fputs(header(names).c_str(), file_);
  std::fputc('\n', file_);
  for (const auto& row : carried_rows) {
    std::fputs(row.c_str(), file_);
    std::fputc('\n', file_);
  }
  flush();
  if (!failure_.empty()) HALFETI_IO_ERROR(failure_);
}

std::string ProbeWriter::header(const std::vector<std::string>& names) {
  std::string h = "t";
  for (const auto& n : names) h += "," + n;
  return h;
}

void ProbeWriter::flush() {
  if (std::fflush(file_) == 0 && !std::ferror(file_)) return;
  failure_ = "cannot write probes to '" + path_ + "': " + std::strerror(errno);
  std::fclose(file_);
  file_ = nullptr;
}

ProbeWriter::~ProbeWriter() {
  if (file_) std::fclose(file_);
}

void ProbeWriter::write(double t, const std::vector<double>& values) {
  HALFETI_CHECK(values.size() == names_.size(),
                "probe row has " << values.size() << " values for " << names_.size() << " columns");
  if (!file_) return;
  std::fprintf(file_, "%.9g", t);
  for (double v : values) std::fprintf(file_, ",%.9g", v);
  std::fputc('\n', file_);
  flush();
}

std::string probe_columns_json(const std::vector<std::string>& names, const std::vector<std::string>& units,
                               const std::vector<std::string>& kinds) {
  HALFETI_CHECK(names.size() == units.size() && names.size() == kinds.size(),
                "probe columns without units or kinds");
  Json columns = Json::array();
  columns.push(Json::object().set("name", "t").set("unit", "s").set("kind", "time"));
  for (std::size_t k = 0; k < names.size(); ++k)
    columns.push(Json::object().set("name", names[k]).set("unit", units[k]).set("kind", kinds[k]));
  return Json::object().set("file", "probes.csv").set("columns", columns).dump() + "\n";
}

std::vector<double> ProbeTable::column(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  HALFETI_CHECK(it != names.end(), "no probe column '" << name << "'");
  const size_t j = static_cast<size_t>(it - names.begin());
  std::vector<double> out;
  for (const auto& r : rows) out.push_back(r.at(j));
  return out;
}

ProbeTable read_probe_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) HALFETI_USER_ERROR("cannot open probe file '" << path << "'");
  ProbeTable t;
  std::string line;
  if (!std::getline(in, line)) HALFETI_USER_ERROR("probe file '" << path << "' is empty");
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) t.names.push_back(c);
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::vector<double> row;
    for (std::string c; std::getline(ls, c, ',');) row.push_back(std::stod(c));
    if (row.size() != t.names.size())
      HALFETI_USER_ERROR("probe file '" << path << "': ragged row '" << line << "'");
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace halfeti::io
