#include "halfeti/io/fields.hpp"

#include <hdf5.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "halfeti/core/collective.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/core/files.hpp"
#include "hdf5_file.hpp"

namespace halfeti::io {

namespace {

const char* center_name(Center c) {
  return c == Center::kCell ? "cell" : "node";
}

}  // namespace

FieldSeries::FieldSeries(MPI_Comm comm, std::string dir, std::string name)
    : comm_(comm), dir_(std::move(dir)), name_(std::move(name)) {
  h5::quiet();
  xdmf_path_ = dir_ + "/" + name_ + ".xdmf";
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank == 0) ::mkdir(dir_.c_str(), 0755);
  MPI_Barrier(comm_);
}

std::string FieldSeries::write(double time, std::size_t n_local, const double* x, const double* y,
                               const std::vector<Field>& fields, const CellBlock* cells) {
  using h5::Id;
  using h5::Use;
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%06d.h5", frames());
  const std::string file_name = name_ + buf;
  const std::string path = dir_ + "/" + file_name, partial = path + ".partial";

  long long local[2] = {static_cast<long long>(n_local),
                        cells ? static_cast<long long>(cells->n_local_cells) : 0};
  long long offset[2] = {0, 0}, total[2] = {0, 0};
  MPI_Exscan(local, offset, 2, MPI_LONG_LONG, MPI_SUM, comm_);
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank == 0) offset[0] = offset[1] = 0;  // MPI_Exscan leaves rank 0's buffer undefined
  MPI_Allreduce(local, total, 2, MPI_LONG_LONG, MPI_SUM, comm_);

  // Written under a temporary name and renamed when complete: a file of the series is whole or absent.
  Frame frame{time, file_name, total[0], 0, {}, {}, "Polyvertex", 1};
  try {
    h5::CollectiveWrites collective(comm_, partial);
    Id file(h5::create_collective(comm_, partial), H5Fclose, Use::kWrite, "create '" + partial + "'");
    h5::write_attribute(file, "time", time, partial);
    h5::write_slab(file, "x", H5T_NATIVE_DOUBLE, x, offset[0], local[0], total[0], partial);
    h5::write_slab(file, "y", H5T_NATIVE_DOUBLE, y, offset[0], local[0], total[0], partial);
    for (const auto& f : fields) {
      HALFETI_CHECK(f.name != "x" && f.name != "y" && f.name != "cells",
                    "field name '" << f.name << "' is reserved");
      HALFETI_CHECK(!f.is_integer || f.components == 1, "integer field '" << f.name << "' has one component");
      HALFETI_CHECK(f.components == 1 || f.components == 3, "field '" << f.name << "': 1 or 3 components");
      HALFETI_CHECK(f.center == Center::kNode || cells, "cell field '" << f.name << "' without cells");
      const int row = f.center == Center::kCell ? 1 : 0;
      if (f.is_integer)
        h5::write_slab(file, f.name, H5T_NATIVE_INT64, f.integer, offset[row], local[row], total[row],
                       partial);
      else
        h5::write_slab(file, f.name, H5T_NATIVE_DOUBLE, f.real, offset[row], local[row], total[row], partial,
                       f.components);
      h5::write_dataset_attribute(file, f.name, "unit", f.unit, partial);
      h5::write_dataset_attribute(file, f.name, "center", center_name(f.center), partial);
      frame.names.push_back(f.name);
      frame.layouts.push_back({f.unit, f.components, f.center, f.is_integer});
    }
    std::string order;  // the fields in their order of writing, for readers (HDF5 lists them by name)
    for (const auto& n : frame.names) order += (order.empty() ? "" : ",") + n;
    h5::write_attribute(file, "fields", order, partial);
    if (cells) {
      const long long npc = cells->nodes_per_cell;
      h5::write_slab(file, "cells", H5T_NATIVE_INT64, cells->connectivity, offset[1], local[1], total[1],
                     partial,
                     static_cast<int>(npc));  // one row per cell, as the XDMF states it
      frame.n_cells = total[1];
      frame.topology = cells->xdmf_topology;
      frame.nodes_per_cell = cells->nodes_per_cell;
      h5::write_attribute(file, "topology", frame.topology, partial);  // for resume() and readers
      h5::write_attribute(file, "nodes_per_cell", static_cast<double>(frame.nodes_per_cell), partial);
    }
    errno = 0;
    file.close("close '" + partial + "'");
  } catch (const IoError&) {
    if (rank == 0) std::remove(partial.c_str());  // no half-written file is left behind
    throw;
  }
  rename_on_root(comm_, partial, path);
  frames_.push_back(frame);
  collective_outcome(comm_, 0, rank == 0,
                     [&] { write_xdmf(); });  // rank 0 writes; a failure stops every rank
  return path;
}

void FieldSeries::resume(double time) {
  // Rank 0 reads the series' files in order and keeps those at or before `time` (within round-off of it), removing
  // the later ones; the others keep the count, which names the next file.
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  frames_.clear();
  int kept = 0;
  collective_outcome(comm_, 0, rank == 0, [&] {
    for (int k = 0;; ++k) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "_%06d.h5", k);
      const std::string file_name = name_ + buf, path = dir_ + "/" + file_name;
      if (!path_exists(path)) break;
      if (static_cast<int>(frames_.size()) == k) {
        const FieldFrameData d = read_field_file(path);
        if (d.time <= time * (1.0 + 1e-12) + 1e-300) {
          Frame f{d.time, file_name, static_cast<long long>(d.x.size()), 0, d.names, d.info, "Polyvertex", 1};
          if (!d.cells.empty()) {
            f.topology = d.topology;
            f.nodes_per_cell = d.nodes_per_cell;
            f.n_cells = static_cast<long long>(d.cells.size()) / d.nodes_per_cell;
          }
          frames_.push_back(f);
          continue;
        }
      }
      std::remove(path.c_str());  // a frame after the restart: the continued run writes its own
    }
    kept = static_cast<int>(frames_.size());
    write_xdmf();
  });
  MPI_Bcast(&kept, 1, MPI_INT, 0, comm_);
  if (rank != 0) frames_.resize(static_cast<std::size_t>(kept), Frame{0.0, "", 0, 0, {}, {}, "", 1});
}

void FieldSeries::write_xdmf() const {
  const std::string tmp = xdmf_path_ + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) HALFETI_IO_ERROR("cannot write '" << tmp << "': " << std::strerror(errno));
    out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
        << "  <Grid Name=\"" << name_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames_) {
      const auto item = [&](const std::string& ds, long long n, const char* type, int precision) {
        out << "     <DataItem Dimensions=\"" << n << "\" NumberType=\"" << type << "\" Precision=\""
            << precision << "\" Format=\"HDF\">" << f.file << ":/" << ds << "</DataItem>\n";
      };
      out << "   <Grid Name=\"" << name_ << "\" GridType=\"Uniform\">\n";
      char t[40];
      std::snprintf(t, sizeof t, "%.9g", f.time);
      out << "    <Time Value=\"" << t << "\"/>\n";
      if (f.n_cells > 0) {
        out << "    <Topology TopologyType=\"" << f.topology << "\" NumberOfElements=\"" << f.n_cells << "\""
            << " NodesPerElement=\"" << f.nodes_per_cell << "\">\n";
        out << "     <DataItem Dimensions=\"" << f.n_cells << " " << f.nodes_per_cell
            << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << f.file << ":/cells</DataItem>\n";
        out << "    </Topology>\n";
      } else {
        out << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << f.n_points
            << "\" NodesPerElement=\"1\"/>\n";
      }
      out << "    <Geometry GeometryType=\"X_Y\">\n";
      item("x", f.n_points, "Float", 8);
      item("y", f.n_points, "Float", 8);
      out << "    </Geometry>\n";
      for (std::size_t k = 0; k < f.names.size(); ++k) {
        const FieldLayout& a = f.layouts[k];
        const std::string& name = f.names[k];
        const long long rows = a.center == Center::kCell ? f.n_cells : f.n_points;
        out << "    <Attribute Name=\"" << name << "\" AttributeType=\""
            << (a.components == 3 ? "Vector" : "Scalar") << "\" Center=\""
            << (a.center == Center::kCell ? "Cell" : "Node") << "\">\n";
        if (!a.unit.empty()) out << "     <Information Name=\"unit\" Value=\"" << a.unit << "\"/>\n";
        out << "     <DataItem Dimensions=\"" << rows;
        if (a.components > 1) out << " " << a.components;
        out << "\" NumberType=\"" << (a.integer ? "Int" : "Float") << "\" Precision=\"8\" Format=\"HDF\">"
            << f.file << ":/" << name << "</DataItem>\n";
        out << "    </Attribute>\n";
      }
      out << "   </Grid>\n";
    }
    out << "  </Grid>\n </Domain>\n</Xdmf>\n";
    out.flush();
    if (!out) HALFETI_IO_ERROR("cannot write '" << tmp << "': " << std::strerror(errno));
  }
  if (std::rename(tmp.c_str(), xdmf_path_.c_str()) != 0)
    HALFETI_IO_ERROR("cannot rename '" << tmp << "' to '" << xdmf_path_ << "': " << std::strerror(errno));
}

const std::vector<double>& FieldFrameData::field(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) HALFETI_USER_ERROR("field file has no field '" << name << "'");
  return values[static_cast<size_t>(it - names.begin())];
}

const FieldFrameData::Info& FieldFrameData::field_info(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) HALFETI_USER_ERROR("field file has no field '" << name << "'");
  return info[static_cast<size_t>(it - names.begin())];
}

FieldFrameData read_field_file(const std::string& path) {
  using h5::Id;
  using h5::Use;
  h5::quiet();
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, Use::kRead, "open '" + path + "'");
  FieldFrameData d;
  d.time = h5::read_double_attribute(file, "time", path);
  d.x = h5::read_all<double>(file, "x", H5T_NATIVE_DOUBLE, path);
  d.y = h5::read_all<double>(file, "y", H5T_NATIVE_DOUBLE, path);
  H5G_info_t info;
  h5::check(H5Gget_info(file, &info), Use::kRead, "group info of '" + path + "'");
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256];
    H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    const std::string n(name);
    if (n == "x" || n == "y") continue;
    if (n == "cells") {
      d.cells = h5::read_all<std::int64_t>(file, "cells", H5T_NATIVE_INT64, path);
      continue;
    }
    const h5::DatasetShape shape = h5::dataset_shape(file, n, path);
    FieldFrameData::Info fi;
    fi.unit = h5::read_dataset_attribute(file, n, "unit", path);
    fi.components = shape.columns;
    fi.center = h5::read_dataset_attribute(file, n, "center", path) == "cell" ? Center::kCell : Center::kNode;
    fi.integer = shape.integer;
    d.names.push_back(n);
    d.info.push_back(fi);
    if (shape.integer) {
      const auto ints = h5::read_all<std::int64_t>(file, n, H5T_NATIVE_INT64, path);
      d.values.emplace_back(ints.begin(), ints.end());
    } else {
      d.values.push_back(h5::read_all<double>(file, n, H5T_NATIVE_DOUBLE, path));
    }
  }
  if (H5Aexists(file, "fields") > 0) {  // the order of writing
    std::vector<std::string> names;
    std::vector<FieldFrameData::Info> infos;
    std::vector<std::vector<double>> values;
    const std::string order = h5::read_string_attribute(file, "fields", path);
    for (std::size_t start = 0; start < order.size();) {
      const std::size_t comma = std::min(order.find(',', start), order.size());
      const std::string n = order.substr(start, comma - start);
      const auto it = std::find(d.names.begin(), d.names.end(), n);
      if (it != d.names.end()) {
        const auto k = static_cast<std::size_t>(it - d.names.begin());
        names.push_back(n);
        infos.push_back(d.info[k]);
        values.push_back(std::move(d.values[k]));
      }
      start = comma + 1;
    }
    if (names.size() == d.names.size()) {
      d.names = std::move(names);
      d.info = std::move(infos);
      d.values = std::move(values);
    }
  }
  if (!d.cells.empty()) {
    d.topology = h5::read_string_attribute(file, "topology", path);
    d.nodes_per_cell = static_cast<int>(h5::read_double_attribute(file, "nodes_per_cell", path));
  }
  return d;
}

void rename_on_root(MPI_Comm comm, const std::string& from, const std::string& to) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int failed = 0;
  if (rank == 0 && std::rename(from.c_str(), to.c_str()) != 0) failed = errno;
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed != 0)
    HALFETI_IO_ERROR("cannot rename '" << from << "' to '" << to << "': " << std::strerror(failed));
}

}  // namespace halfeti::io
