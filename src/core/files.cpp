#include "halfeti/core/files.hpp"

#include <sys/stat.h>

namespace halfeti {

namespace {
bool stat_of(const std::string& path, struct stat& st) {
  return ::stat(path.c_str(), &st) == 0;
}
}  // namespace

bool path_exists(const std::string& path) {
  struct stat st {};
  return stat_of(path, st);
}

bool is_directory(const std::string& path) {
  struct stat st {};
  return stat_of(path, st) && S_ISDIR(st.st_mode);
}

bool is_regular_file(const std::string& path) {
  struct stat st {};
  return stat_of(path, st) && S_ISREG(st.st_mode);
}

std::string directory_of(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? std::string(".") : path.substr(0, p);
}

std::string base_name(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? path : path.substr(p + 1);
}

}  // namespace halfeti
