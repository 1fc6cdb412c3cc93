#include "halfeti/app/restart.hpp"

#include <dirent.h>
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"

namespace halfeti::app {

namespace {

void flatten(const YAML::Node& n, const std::string& path, std::map<std::string, std::string>& out) {
  switch (n.Type()) {
    case YAML::NodeType::Map:
      if (n.size() == 0) out[path] = "{}";
      for (const auto& kv : n) flatten(kv.second, path.empty() ? kv.first.as<std::string>() : path + "." + kv.first.as<std::string>(), out);
      break;
    case YAML::NodeType::Sequence:
      out[path + ".size"] = std::to_string(n.size());
      for (std::size_t i = 0; i < n.size(); ++i) flatten(n[i], path + "." + std::to_string(i), out);
      break;
    case YAML::NodeType::Scalar:
      out[path] = n.Scalar();
      break;
    default:
      out[path] = "~";
  }
}

bool may_change(const std::string& key) {
  return key == "scene.end_time" || key == "scene.description" || key.rfind("output.", 0) == 0;
}


}  // namespace

std::string changed_physics_key(const std::string& saved_scene, const std::string& scene) {
  std::map<std::string, std::string> a, b;
  try {
    flatten(YAML::Load(saved_scene), "", a);
    flatten(YAML::Load(scene), "", b);
  } catch (const YAML::Exception& e) {
    HALFETI_USER_ERROR("restart: the checkpoint's scene does not parse: " << e.what());
  }
  for (const auto& [key, value] : b) {
    if (may_change(key)) continue;
    const auto it = a.find(key);
    if (it == a.end()) return key + " (not in the checkpoint's scene, now " + value + ")";
    if (it->second != value) return key + " (checkpoint " + it->second + ", now " + value + ")";
  }
  for (const auto& [key, value] : a)
    if (!may_change(key) && b.find(key) == b.end()) return key + " (checkpoint " + value + ", now absent)";
  return "";
}

std::string encode_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

std::vector<std::string> decode_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> run_outputs(const std::string& dir) {
  std::vector<std::string> out;
  for (const char* f : {"summary.json", "probes.csv", "probes.json", "log.txt", "scene.resolved.yaml"})
    if (path_exists(dir + "/" + f)) out.push_back(dir + "/" + f);
  for (const char* sub : {"fields", "checkpoints"}) {
    DIR* d = ::opendir((dir + "/" + sub).c_str());
    if (d == nullptr) continue;
    while (const dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      const auto ends = [&](const std::string& s) { return n.size() > s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0; };
      if (ends(".h5") || ends(".xdmf") || ends(".partial") || ends(".tmp")) out.push_back(dir + "/" + sub + "/" + n);
    }
    ::closedir(d);
  }
  return out;
}

std::vector<std::string> probe_rows_until(const std::string& path, const std::string& header, double t) {
  std::vector<std::string> rows;
  std::ifstream in(path);
  if (!in) return rows;
  std::string line;
  if (!std::getline(in, line)) return rows;
  if (line != header)
    HALFETI_USER_ERROR("restart: '" << path << "' has the columns '" << line << "', this scene's probes are '"
                                    << header << "'");
  const double limit = t + 1e-9 * std::max(1.0, std::abs(t));
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (std::strtod(line.c_str(), nullptr) > limit) break;
    rows.push_back(line);
  }
  return rows;
}

std::string run_folder_of(const std::string& checkpoint) {
  const std::string dir = directory_of(checkpoint);
  return base_name(dir) == "checkpoints" ? directory_of(dir) : dir;
}

bool same_folder(const std::string& a, const std::string& b) {
  char ra[PATH_MAX], rb[PATH_MAX];
  if (::realpath(a.c_str(), ra) == nullptr || ::realpath(b.c_str(), rb) == nullptr) return false;
  return std::strcmp(ra, rb) == 0;
}

}  // namespace halfeti::app
