#include "halfeti/io/run_log.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"

namespace halfeti::io {

RunLog::RunLog(const std::string& path, bool writer, bool echo, bool append)
    : path_(path), writer_(writer), echo_(echo) {
  if (!writer_ || path.empty()) return;
  file_ = std::fopen(path.c_str(), append ? "a" : "w");
  if (!file_) HALFETI_IO_ERROR("cannot write the log '" << path << "': " << std::strerror(errno));
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
  to_file(text);
}

void RunLog::warning(const std::string& text) {
  if (!writer_) return;
  const std::string line = "warning: " + text;
  std::fflush(stdout);  // after the progress lines already printed
  std::fputs(line.c_str(), stderr);
  std::fputc('\n', stderr);
  to_file(line);
}

void RunLog::to_file(const std::string& text) {
  if (file_) {
    std::fputs(text.c_str(), file_);
    std::fputc('\n', file_);
    if (std::fflush(file_) != 0 || std::ferror(file_)) {
      failure_ = "cannot write the log '" + path_ + "': " + std::strerror(errno);
      std::fclose(file_);
      file_ = nullptr;  // the run stops at the step's end (the caller checks failure() collectively)
    }
  }
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) HALFETI_IO_ERROR("cannot write '" << tmp << "': " << std::strerror(errno));
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  const int reason = errno;
  if (std::fclose(f) != 0 || !written) {
    std::remove(tmp.c_str());
    HALFETI_IO_ERROR("cannot write '" << path << "': " << std::strerror(written ? errno : reason));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    HALFETI_IO_ERROR("cannot rename '" << tmp << "' to '" << path << "': " << std::strerror(errno));
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
  if (!is_directory(path)) HALFETI_USER_ERROR("'" << path << "' exists and is not a directory");
}

}  // namespace halfeti::io
