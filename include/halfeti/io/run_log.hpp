// The run's log: progress and start-up lines to stdout and DIR/log.txt, written by rank 0 only.
#pragma once

#include <cstdio>
#include <string>

namespace halfeti::io {

class RunLog {
 public:
  RunLog() = default;
  // `writer` is true on the one rank that prints; `path` may be empty (stdout only).
  RunLog(const std::string& path, bool writer, bool echo = true);
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  void line(const std::string& text);
  bool writer() const { return writer_; }

 private:
  std::FILE* file_ = nullptr;
  bool writer_ = false;
  bool echo_ = true;
};

// Creates a directory and its parents (like mkdir -p); UserError naming the path if it cannot.
void make_directories(const std::string& path);

}  // namespace halfeti::io
