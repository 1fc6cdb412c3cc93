// The run's log: progress and start-up lines to stdout and DIR/log.txt, written by rank 0 only.
#pragma once

#include <cstdio>
#include <string>

namespace halfeti::io {

class RunLog {
 public:
  RunLog() = default;
  // `writer` is true on the one rank that prints; `path` may be empty (stdout only).
  // append: continue an existing log (a restart into the run's folder). A failed open raises IoError; a failed
  // line is kept in failure() (the writer is one rank: the run checks it collectively) and ends the file's use.
  RunLog(const std::string& path, bool writer, bool echo = true, bool append = false);
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  void line(const std::string& text);
  // "warning: text" on stderr (also when progress is not echoed) and in the log file.
  void warning(const std::string& text);
  bool writer() const { return writer_; }
  const std::string& failure() const { return failure_; }

 private:
  void to_file(const std::string& text);

  std::FILE* file_ = nullptr;
  std::string path_, failure_;
  bool writer_ = false;
  bool echo_ = true;
};

// Creates a directory and its parents (like mkdir -p); UserError naming the path if it cannot.
void make_directories(const std::string& path);

// Writes `text` to path.tmp and renames it to path: the file is the old one or the new one, never half of either.
// IoError naming the file and the system's reason when it cannot.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace halfeti::io
