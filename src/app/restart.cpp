#include "halfeti/app/restart.hpp"

#include <dirent.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "halfeti/core/collective.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"
#include "halfeti/io/run_log.hpp"

namespace halfeti::app {

namespace {
constexpr std::size_t kMaxOutputPath = 200;  // characters of a file's absolute path (see prepare_run_folder)

void flatten(const YAML::Node& n, const std::string& path, std::map<std::string, std::string>& out) {
  switch (n.Type()) {
    case YAML::NodeType::Map:
      if (n.size() == 0) out[path] = "{}";
      for (const auto& kv : n)
        flatten(kv.second,
                path.empty() ? kv.first.as<std::string>() : path + "." + kv.first.as<std::string>(), out);
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

// Two resolved values are the same if their text is, or if both are numbers of the same value: the checkpoint holds
// the value as the scene wrote it ("0.00182500"), a continued run may give it as --set writes it ("0.001825").
bool same_value(const std::string& a, const std::string& b) {
  if (a == b) return true;
  const auto number = [](const std::string& s, double& v) {
    if (s.empty()) return false;
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
  };
  double x = 0.0, y = 0.0;
  return number(a, x) && number(b, y) && x == y;
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
    if (!same_value(it->second, value)) return key + " (checkpoint " + it->second + ", now " + value + ")";
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
      const auto ends = [&](const std::string& s) {
        return n.size() > s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0;
      };
      if (ends(".h5") || ends(".xdmf") || ends(".partial") || ends(".tmp"))
        out.push_back(dir + "/" + sub + "/" + n);
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

std::unique_ptr<io::Checkpoint> read_restart(const std::string& restart, const scene::Scene& scene,
                                             std::string& checkpoint_path) {
  checkpoint_path = io::resolve_checkpoint(restart);
  auto checkpoint = std::make_unique<io::Checkpoint>(io::read_checkpoint(checkpoint_path));
  const auto scene_text = checkpoint->texts.find("scene");
  if (scene_text == checkpoint->texts.end())
    HALFETI_USER_ERROR("restart: '" << checkpoint_path << "' holds no scene");
  const std::string changed = changed_physics_key(scene_text->second, scene.resolved_text());
  if (!changed.empty())
    HALFETI_USER_ERROR(
        scene.file << ": the scene changes " << changed << " from the checkpoint '" << checkpoint_path
                   << "'; a continued run may change only scene.end_time, scene.description and "
                      "output.*");
  const double end = scene.root().section("scene").real("end_time");
  if (!(checkpoint->time < end))
    HALFETI_USER_ERROR("restart: the checkpoint is at t = " << checkpoint->time
                                                            << " s, not before scene.end_time = " << end
                                                            << " s (raise it with --set scene.end_time=...)");
  return checkpoint;
}

bool prepare_run_folder(MPI_Comm comm, const std::string& out_dir, const io::Checkpoint* checkpoint,
                        const std::string& checkpoint_path, bool overwrite) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  bool continuing = false;
  collective_outcome(comm, 0, rank == 0, [&] {
    // Open MPI 4.1's MPI-IO (under parallel HDF5) builds a lock file's name in a fixed buffer and aborts the
    // process on file paths past about 235 characters; the longest file written is a checkpoint.
    std::string absolute = out_dir;
    if (absolute.empty() || absolute[0] != '/') {
      char cwd[PATH_MAX];
      absolute = std::string(getcwd(cwd, sizeof cwd) ? cwd : "") + "/" + out_dir;
    }
    const std::string longest = absolute + "/checkpoints/" + io::checkpoint_file_name(0);
    if (longest.size() > kMaxOutputPath)
      HALFETI_USER_ERROR(
          "--out '" << out_dir << "': the checkpoints' paths would be " << longest.size()
                    << " characters long; MPI-IO aborts on paths past about 235, so this program "
                       "keeps them within "
                    << kMaxOutputPath << " (choose a shorter output folder)");
    for (const char* sub : {"", "/fields", "/checkpoints"}) io::make_directories(out_dir + sub);
    continuing = checkpoint && same_folder(out_dir, run_folder_of(checkpoint_path));
    if (continuing) {
      // Checkpoints after the one continued from belong to the run being replaced.
      for (const auto& f : io::list_checkpoints(out_dir + "/checkpoints"))
        if (f > out_dir + "/checkpoints/" + io::checkpoint_file_name(checkpoint->steps))
          std::remove(f.c_str());
      return;
    }
    const auto earlier = run_outputs(out_dir);
    if (earlier.empty()) return;
    if (!overwrite)
      HALFETI_USER_ERROR("'" << out_dir << "' holds the outputs of another run (" << earlier.front()
                             << (earlier.size() > 1 ? ", ..." : "")
                             << "); give --overwrite to replace them, --restart " << out_dir
                             << " to continue that run, or another --out");
    for (const auto& f : earlier)
      if (std::remove(f.c_str()) != 0)
        HALFETI_IO_ERROR("--overwrite: cannot remove '" << f << "': " << std::strerror(errno));
  });
  int flag = continuing ? 1 : 0;
  MPI_Bcast(&flag, 1, MPI_INT, 0, comm);
  return flag != 0;
}

}  // namespace halfeti::app
