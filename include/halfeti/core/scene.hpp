// A resolved scene: the YAML tree after schema checking (every default filled), with typed read access, and the
// collective loader (rank 0 reads, checks and broadcasts; every rank gets the same scene or the same error).
#pragma once

#include <mpi.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <string>
#include <vector>

#include "halfeti/core/schema.hpp"

namespace halfeti::scene {

// Read access to one section of a resolved tree. Keys were checked by the schema, so a wrong read is a bug
// (InternalError), not a user error.
class Node {
 public:
  Node(YAML::Node yaml, std::string path) : yaml_(std::move(yaml)), path_(std::move(path)) {}

  bool has(const std::string& key) const;
  double real(const std::string& key) const;
  long long integer(const std::string& key) const;
  bool boolean(const std::string& key) const;
  std::string string(const std::string& key) const;
  std::array<double, 2> point(const std::string& key) const;
  std::vector<double> reals(const std::string& key) const;
  Node section(const std::string& key) const;
  std::vector<Node> list(const std::string& key) const;

  const std::string& path() const { return path_; }
  const YAML::Node& yaml() const { return yaml_; }
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

 private:
  YAML::Node at(const std::string& key) const;
  YAML::Node yaml_;
  std::string path_;
};

struct Scene {
  std::string file;     // where it was read from
  YAML::Node resolved;  // checked, defaults filled
  Node root() const { return Node(resolved, ""); }
  std::string resolved_text() const;  // YAML text that runs again as it is
};

// Parses scene text, applies --set overrides and resolves against `schema` (serial; throws UserError).
Scene parse_scene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides,
                  const Schema& schema);

// Reads the file on rank 0 of `comm`, parses and resolves it there, and broadcasts the result (or the error).
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, const Schema& schema,
                 MPI_Comm comm);

}  // namespace halfeti::scene
