// probes.csv: a `t` column, then one column per probe, named as in the scene. Rank 0 writes; values are passed in
// already reduced (probes are collective). Rows are flushed so that a run that stops leaves a readable file.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace halfeti::io {

class ProbeWriter {
 public:
  // Opens `path` and writes the header when `writer` is true (rank 0); other ranks hold a closed writer.
  // `carried_rows` (a restart's rows before the checkpoint, verbatim) follow the header. A failed open raises
  // IoError naming the file and the system's reason; a failed row is kept in failure() (the writer is one rank:
  // the run checks it collectively).
  ProbeWriter(const std::string& path, const std::vector<std::string>& names, bool writer,
              const std::vector<std::string>& carried_rows = {});
  static std::string header(const std::vector<std::string>& names);  // "t,name1,name2,..."
  ~ProbeWriter();
  ProbeWriter(const ProbeWriter&) = delete;
  ProbeWriter& operator=(const ProbeWriter&) = delete;

  void write(double t, const std::vector<double>& values);
  size_t columns() const { return names_.size(); }
  const std::string& failure() const { return failure_; }

 private:
  void flush();

  std::FILE* file_ = nullptr;
  std::string path_, failure_;
  std::vector<std::string> names_;
};

// probes.csv's sidecar, probes.json: every column (`t` first) with its unit and probe kind.
std::string probe_columns_json(const std::vector<std::string>& names, const std::vector<std::string>& units,
                               const std::vector<std::string>& kinds);

// Reads a probes.csv back (for tests and tools): column names and rows.
struct ProbeTable {
  std::vector<std::string> names;  // including "t"
  std::vector<std::vector<double>> rows;
  std::vector<double> column(const std::string& name) const;
};
ProbeTable read_probe_csv(const std::string& path);

}  // namespace halfeti::io
