#include "halfeti/io/checkpoint.hpp"

#include <dirent.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"
#include "halfeti/io/fields.hpp"
#include "hdf5_file.hpp"

namespace halfeti::io {

namespace {

constexpr double kFormat = 1.0;  // the layout below; a reader refuses another
constexpr const char* kPrefix = "checkpoint_";

// Rank 0's names and sizes, known to every rank (datasets are created collectively).
template <class Map>
std::vector<std::pair<std::string, long long>> shared_layout(MPI_Comm comm, const Map& m) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string names;
  std::vector<long long> sizes;
  for (const auto& [name, values] : m) {
    names += name + '\n';
    sizes.push_back(static_cast<long long>(values.size()));
  }
  long long counts[2] = {static_cast<long long>(names.size()), static_cast<long long>(sizes.size())};
  MPI_Bcast(counts, 2, MPI_LONG_LONG, 0, comm);
  names.resize(static_cast<std::size_t>(counts[0]));
  sizes.resize(static_cast<std::size_t>(counts[1]));
  MPI_Bcast(names.data(), static_cast<int>(counts[0]), MPI_CHAR, 0, comm);
  MPI_Bcast(sizes.data(), static_cast<int>(counts[1]), MPI_LONG_LONG, 0, comm);
  std::vector<std::pair<std::string, long long>> out;
  std::size_t start = 0;
  for (long long s : sizes) {
    const std::size_t end = names.find('\n', start);
    out.emplace_back(names.substr(start, end - start), s);
    start = end + 1;
  }
  return out;
}

}  // namespace

std::string checkpoint_file_name(long long steps) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s%012lld.h5", kPrefix, steps);
  return buf;
}

void write_checkpoint(MPI_Comm comm, const std::string& path, const Checkpoint& c) {
  using h5::Id;
  using h5::Use;
  h5::quiet();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::string partial = path + ".partial";
  const ParticleArrays& p = c.particles;
  long long local = static_cast<long long>(p.gid.size()), offset = 0, total = 0;
  MPI_Exscan(&local, &offset, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (rank == 0) offset = 0;
  MPI_Allreduce(&local, &total, 1, MPI_LONG_LONG, MPI_SUM, comm);
  const auto blocks = shared_layout(comm, c.blocks);
  const auto texts = shared_layout(comm, c.texts);
  try {
    h5::CollectiveWrites collective(comm, partial);
    Id file(h5::create_collective(comm, partial), H5Fclose, Use::kWrite, "create '" + partial + "'");
    h5::write_attribute(file, "halfeti_checkpoint", kFormat, partial);
    h5::write_attribute(file, "time", c.time, partial);
    h5::write_attribute(file, "steps", static_cast<double>(c.steps), partial);
    h5::write_attribute(file, "ranks", static_cast<double>(c.ranks), partial);
    {
      Id group(H5Gcreate2(file, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, Use::kWrite,
               "group particles in '" + partial + "'");
      h5::write_slab(group, "gid", H5T_NATIVE_INT64, p.gid.data(), offset, local, total, partial);
      const std::pair<const char*, const std::vector<double>*> arrays[] = {
          {"x", &p.x}, {"y", &p.y}, {"vx", &p.vx}, {"vy", &p.vy}, {"rho", &p.rho}, {"mass", &p.mass}};
      for (const auto& [name, v] : arrays) {
        HALFETI_CHECK(static_cast<long long>(v->size()) == local,
                      "checkpoint: " << name << " has " << v->size() << " values for " << local);
        h5::write_slab(group, name, H5T_NATIVE_DOUBLE, v->data(), offset, local, total, partial);
      }
    }
    // Replicated state: rank 0's values, the datasets created by every rank.
    const auto rank0_group = [&](const char* group_name, const auto& layout, const auto& values, hid_t type) {
      Id group(H5Gcreate2(file, group_name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, Use::kWrite,
               std::string("group ") + group_name + " in '" + partial + "'");
      for (const auto& [name, size] : layout) {
        const auto it = values.find(name);
        HALFETI_CHECK(it != values.end(),
                      "checkpoint " << group_name << " '" << name << "' missing on rank " << rank);
        h5::write_slab(group, name, type, it->second.data(), 0, rank == 0 ? size : 0, size, partial);
      }
    };
    rank0_group("blocks", blocks, c.blocks, H5T_NATIVE_DOUBLE);
    rank0_group("texts", texts, c.texts, H5T_NATIVE_CHAR);
    errno = 0;
    file.close("close '" + partial + "'");
  } catch (const IoError&) {
    if (rank == 0) std::remove(partial.c_str());  // no half-written checkpoint is left behind
    throw;
  }
  rename_on_root(comm, partial, path);
}

Checkpoint read_checkpoint(const std::string& path) {
  using h5::Id;
  using h5::Use;
  h5::quiet();
  if (!is_regular_file(path)) HALFETI_USER_ERROR("restart: no checkpoint file '" << path << "'");
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, Use::kRead, "open '" + path + "'");
  if (H5Aexists(file, "halfeti_checkpoint") <= 0)
    HALFETI_USER_ERROR("restart: '" << path << "' is not a halfeti checkpoint (a field file?)");
  const double format = h5::read_double_attribute(file, "halfeti_checkpoint", path);
  if (format != kFormat)
    HALFETI_USER_ERROR("restart: '" << path << "' has checkpoint format " << format << ", this halfeti reads "
                                    << kFormat);
  Checkpoint c;
  c.time = h5::read_double_attribute(file, "time", path);
  c.steps = static_cast<long long>(h5::read_double_attribute(file, "steps", path));
  c.ranks = static_cast<int>(h5::read_double_attribute(file, "ranks", path));
  {
    Id group(H5Gopen2(file, "particles", H5P_DEFAULT), H5Gclose, Use::kRead,
             "group particles of '" + path + "'");
    ParticleArrays& p = c.particles;
    p.gid = h5::read_all<std::int64_t>(group, "gid", H5T_NATIVE_INT64, path);
    const std::pair<const char*, std::vector<double>*> arrays[] = {
        {"x", &p.x}, {"y", &p.y}, {"vx", &p.vx}, {"vy", &p.vy}, {"rho", &p.rho}, {"mass", &p.mass}};
    for (const auto& [name, v] : arrays) {
      *v = h5::read_all<double>(group, name, H5T_NATIVE_DOUBLE, path);
      if (v->size() != p.gid.size())
        HALFETI_USER_ERROR("restart: '" << path << "': particles/" << name << " has " << v->size()
                                        << " values for " << p.gid.size() << " particles");
    }
  }
  for (const char* kind : {"blocks", "texts"}) {
    Id group(H5Gopen2(file, kind, H5P_DEFAULT), H5Gclose, Use::kRead,
             std::string("group ") + kind + " of '" + path + "'");
    H5G_info_t info;
    h5::check(H5Gget_info(group, &info), Use::kRead, "group info of '" + path + "'");
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      char name[256];
      H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
      if (std::string(kind) == "blocks") {
        c.blocks[name] = h5::read_all<double>(group, name, H5T_NATIVE_DOUBLE, path);
      } else {
        const std::vector<char> t = h5::read_all<char>(group, name, H5T_NATIVE_CHAR, path);
        c.texts[name] = std::string(t.begin(), t.end());
      }
    }
  }
  return c;
}

std::vector<std::string> list_checkpoints(const std::string& dir) {
  std::vector<std::string> out;
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return out;
  const std::string prefix = kPrefix, suffix = ".h5";
  while (const dirent* e = ::readdir(d)) {
    const std::string n = e->d_name;
    if (n.size() > prefix.size() + suffix.size() && n.rfind(prefix, 0) == 0 &&
        n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
      out.push_back(dir + "/" + n);
  }
  ::closedir(d);
  std::sort(out.begin(), out.end());  // the step is zero-padded: name order is step order
  return out;
}

std::string resolve_checkpoint(const std::string& path) {
  if (is_regular_file(path)) return path;
  if (!is_directory(path))
    HALFETI_USER_ERROR("restart: '" << path << "' is neither a checkpoint nor a folder");
  for (const std::string& dir : {path + "/checkpoints", path}) {
    const auto all = list_checkpoints(dir);
    if (!all.empty()) return all.back();
  }
  HALFETI_USER_ERROR("restart: no checkpoint (" << kPrefix << "*.h5) in '" << path
                                                << "' or its checkpoints/");
}

}  // namespace halfeti::io
