// What a path names on the file system, and its parts: the one home of these small questions for every module.
#pragma once

#include <string>

namespace halfeti {

bool path_exists(const std::string& path);
bool is_directory(const std::string& path);
bool is_regular_file(const std::string& path);
// "a/b/c.txt" -> "a/b"; a bare name -> "."
std::string directory_of(const std::string& path);
// "a/b/c.txt" -> "c.txt"
std::string base_name(const std::string& path);

}  // namespace halfeti
