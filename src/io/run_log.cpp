#include "halfeti/io/run_log.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "halfeti/core/error.hpp"

namespace halfeti::io {

RunLog::RunLog(const std::string& path, bool writer, bool echo) : writer_(writer), echo_(echo) {
  if (!writer_ || path.empty()) return;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) HALFETI_USER_ERROR("cannot write the log '" << path << "': " << std::strerror(errno));
}

RunLog::~RunLog() {
  if (file_) std::fclose(file_);
}

void RunLog::line(const std::string& text) {
  if (!writer_) return;
  if (echo_) {
    std::fputs(text.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
  }
  if (file_) {
    std::fputs(text.c_str(), file_);
    std::fputc('\n', file_);
    std::fflush(file_);
  }
}

void make_directories(const std::string& path) {
  if (path.empty()) return;
  std::string partial;
  size_t pos = 0;
  while (pos != std::string::npos) {
    pos = path.find('/', pos + 1);
    partial = path.substr(0, pos);
    if (partial.empty()) continue;
    if (::mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST)
      HALFETI_USER_ERROR("cannot create directory '" << partial << "': " << std::strerror(errno));
  }
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    HALFETI_USER_ERROR("'" << path << "' exists and is not a directory");
}

}  // namespace halfeti::io
