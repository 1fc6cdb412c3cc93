#include "halfeti/core/scene.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"

namespace halfeti::scene {

YAML::Node Node::at(const std::string& key) const {
  const YAML::Node n = yaml_[key];
  HALFETI_CHECK(n.IsDefined() && !n.IsNull(), "scene key '" << key_path(key) << "' read but not resolved");
  return n;
}

bool Node::has(const std::string& key) const {
  const YAML::Node n = yaml_[key];
  return n.IsDefined() && !n.IsNull();
}

double Node::real(const std::string& key) const {
  return at(key).as<double>();
}
long long Node::integer(const std::string& key) const {
  return at(key).as<long long>();
}
bool Node::boolean(const std::string& key) const {
  return at(key).as<bool>();
}
std::string Node::string(const std::string& key) const {
  return at(key).Scalar();
}

std::array<double, 2> Node::point(const std::string& key) const {
  const YAML::Node n = at(key);
  HALFETI_CHECK(n.IsSequence() && n.size() == 2, "scene key '" << key_path(key) << "' is not a point");
  return {n[0].as<double>(), n[1].as<double>()};
}

std::vector<double> Node::reals(const std::string& key) const {
  std::vector<double> out;
  for (const auto& v : at(key)) out.push_back(v.as<double>());
  return out;
}

Node Node::section(const std::string& key) const {
  return Node(at(key), key_path(key));
}

std::vector<Node> Node::list(const std::string& key) const {
  std::vector<Node> out;
  if (!has(key)) return out;
  const YAML::Node n = at(key);
  for (size_t i = 0; i < n.size(); ++i) out.emplace_back(n[i], key_path(key) + "[" + std::to_string(i) + "]");
  return out;
}

std::string Scene::resolved_text() const {
  YAML::Emitter e;
  e << resolved;
  return std::string(e.c_str()) + "\n";
}

namespace {
// yaml-cpp keeps every entry of a mapping that repeats a key (and its lookups find the first): a repeated key is
// an error here, as PyYAML in the tools would silently keep the last.
void find_duplicate_keys(const YAML::Node& n, const std::string& file, const std::string& path,
                         std::vector<std::string>& found) {
  if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i)
      find_duplicate_keys(n[i], file, path + "[" + std::to_string(i) + "]", found);
    return;
  }
  if (!n.IsMap()) return;
  std::vector<std::string> seen;
  for (const auto& kv : n) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("(a non-scalar key)");
    const std::string full = path.empty() ? key : path + "." + key;
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      found.push_back(file + ":" + std::to_string(kv.first.Mark().line + 1) + ": key '" + full +
                      "' appears twice in the same section (which one was meant?)");
    seen.push_back(key);
    find_duplicate_keys(kv.second, file, full, found);
  }
}

// Every repeated key of the scene, one line each (in the order of the text), as one UserError.
void reject_duplicate_keys(const YAML::Node& n, const std::string& file) {
  std::vector<std::string> found;
  find_duplicate_keys(n, file, "", found);
  if (found.empty()) return;
  std::string text;
  for (const auto& f : found) text += (text.empty() ? "" : "\n") + f;
  throw UserError(text);
}
}  // namespace

Scene parse_scene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides,
                  const Schema& schema) {
  YAML::Node raw;
  try {
    raw = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    HALFETI_USER_ERROR(file << ":" << e.mark.line + 1 << ":" << e.mark.column + 1
                            << ": not valid YAML: " << e.msg);
  }
  if (raw.IsDefined() && !raw.IsNull() && !raw.IsMap())
    HALFETI_USER_ERROR(
        file << ": a scene is a YAML mapping of sections (scene:, fluid:, ...), found something else");
  reject_duplicate_keys(raw, file);
  Origin origin{file, {}};
  Scene s;
  s.file = file;
  try {
    for (const auto& o : overrides) apply_override(raw, o, origin);
    s.resolved = resolve(raw, schema, origin);
  } catch (
      const YAML::Exception& e) {  // a shape the checks above did not foresee: still bad input, not a crash
    HALFETI_USER_ERROR(file << ": the scene's structure is not what its keys expect (" << e.msg << ")");
  }
  return s;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, const Schema& schema,
                 MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // Rank 0 sends either "ok" + the resolved text, or "error" + the message; the others rebuild the same outcome.
  int status = 0;
  std::string payload;
  if (rank == 0) {
    try {
      if (is_directory(path))
        HALFETI_USER_ERROR("scene file '" << path << "' is a folder; give the scene's .yaml file");
      std::ifstream in(path);
      if (!in) HALFETI_USER_ERROR("cannot open scene file '" << path << "': no such file or not readable");
      std::stringstream buf;
      buf << in.rdbuf();
      payload = parse_scene(buf.str(), path, overrides, schema).resolved_text();
    } catch (const UserError& e) {
      status = 1;
      payload = e.what();
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  long long n = static_cast<long long>(payload.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, comm);
  payload.resize(static_cast<size_t>(n));
  MPI_Bcast(payload.data(), static_cast<int>(n), MPI_CHAR, 0, comm);
  if (status != 0) throw UserError(payload);
  Scene s;
  s.file = path;
  s.resolved = YAML::Load(payload);
  return s;
}

}  // namespace halfeti::scene
