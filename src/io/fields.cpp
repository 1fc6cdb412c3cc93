#include "halfeti/io/fields.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sys/stat.h>

#include "halfeti/core/error.hpp"

namespace halfeti::io {

namespace {

// Owns one HDF5 identifier and closes it with the matching H5*close.
class H5Id {
 public:
  H5Id(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) HALFETI_USER_ERROR("HDF5: " << what << " failed");
  }
  ~H5Id() {
    if (id_ >= 0) close_(id_);
  }
  H5Id(const H5Id&) = delete;
  H5Id& operator=(const H5Id&) = delete;
  operator hid_t() const { return id_; }  // NOLINT(google-explicit-constructor)

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void h5check(herr_t status, const std::string& what) {
  if (status < 0) HALFETI_USER_ERROR("HDF5: " << what << " failed");
}

void quiet_hdf5() {
  static bool done = false;
  if (!done) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // our messages name what failed; no HDF5 error stacks
    done = true;
  }
}

// Writes one 1-D dataset collectively: this rank's `count` values at `offset` of `total`.
template <class T>
void write_slab(hid_t file, const std::string& name, hid_t type, const T* data, long long offset, long long count,
                long long total) {
  const hsize_t dims[1] = {static_cast<hsize_t>(total)};
  H5Id space(H5Screate_simple(1, dims, nullptr), H5Sclose, "dataspace for " + name);
  H5Id dset(H5Dcreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
            "create dataset " + name);
  const hsize_t start[1] = {static_cast<hsize_t>(offset)}, cnt[1] = {static_cast<hsize_t>(count)};
  H5Id filespace(H5Dget_space(dset), H5Sclose, "file space of " + name);
  H5Id memspace(H5Screate_simple(1, cnt, nullptr), H5Sclose, "memory space of " + name);
  if (count > 0) {
    h5check(H5Sselect_hyperslab(filespace, H5S_SELECT_SET, start, nullptr, cnt, nullptr), "select " + name);
  } else {
    h5check(H5Sselect_none(filespace), "select none " + name);
    h5check(H5Sselect_none(memspace), "select none " + name);
  }
  H5Id xfer(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "transfer list");
  h5check(H5Pset_dxpl_mpio(xfer, H5FD_MPIO_COLLECTIVE), "collective transfer");
  h5check(H5Dwrite(dset, type, memspace, filespace, xfer, data), "write " + name);
}

template <class T>
std::vector<T> read_all(hid_t file, const std::string& name, hid_t type) {
  H5Id dset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  H5Id space(H5Dget_space(dset), H5Sclose, "space of " + name);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<size_t>(std::max<hssize_t>(n, 0)));
  if (n > 0) h5check(H5Dread(dset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  return out;
}

std::string base_name(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? path : path.substr(p + 1);
}

}  // namespace

FieldSeries::FieldSeries(MPI_Comm comm, std::string dir, std::string name)
    : comm_(comm), dir_(std::move(dir)), name_(std::move(name)) {
  quiet_hdf5();
  xdmf_path_ = dir_ + "/" + name_ + ".xdmf";
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank == 0) ::mkdir(dir_.c_str(), 0755);
  MPI_Barrier(comm_);
}

std::string FieldSeries::write(double time, std::size_t n_local, const double* x, const double* y,
                               const std::vector<PointField>& fields, const CellBlock* cells) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%06d.h5", frames());
  const std::string file_name = name_ + buf;
  const std::string path = dir_ + "/" + file_name;

  long long local[2] = {static_cast<long long>(n_local), cells ? static_cast<long long>(cells->n_local_cells) : 0};
  long long offset[2] = {0, 0}, total[2] = {0, 0};
  MPI_Exscan(local, offset, 2, MPI_LONG_LONG, MPI_SUM, comm_);
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank == 0) offset[0] = offset[1] = 0;  // MPI_Exscan leaves rank 0's buffer undefined
  MPI_Allreduce(local, total, 2, MPI_LONG_LONG, MPI_SUM, comm_);

  H5Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access list");
  h5check(H5Pset_fapl_mpio(fapl, comm_, MPI_INFO_NULL), "MPI-IO file access");
  H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose, "create '" + path + "'");

  {
    H5Id aspace(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
    H5Id attr(H5Acreate2(file, "time", H5T_NATIVE_DOUBLE, aspace, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "attr time");
    h5check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &time), "write time");
  }
  write_slab(file, "x", H5T_NATIVE_DOUBLE, x, offset[0], local[0], total[0]);
  write_slab(file, "y", H5T_NATIVE_DOUBLE, y, offset[0], local[0], total[0]);
  std::vector<std::string> names;
  for (const auto& f : fields) {
    HALFETI_CHECK(f.name != "x" && f.name != "y" && f.name != "cells", "field name '" << f.name << "' is reserved");
    write_slab(file, f.name, H5T_NATIVE_DOUBLE, f.values, offset[0], local[0], total[0]);
    names.push_back(f.name);
  }
  Frame frame{time, file_name, total[0], 0, names, "Polyvertex", 1};
  if (cells) {
    const long long npc = cells->nodes_per_cell;
    write_slab(file, "cells", H5T_NATIVE_INT64, cells->connectivity, offset[1] * npc, local[1] * npc, total[1] * npc);
    frame.n_cells = total[1];
    frame.topology = cells->xdmf_topology;
    frame.nodes_per_cell = cells->nodes_per_cell;
  }
  frames_.push_back(frame);
  if (rank == 0) write_xdmf();
  return path;
}

void FieldSeries::write_xdmf() const {
  const std::string tmp = xdmf_path_ + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) HALFETI_USER_ERROR("cannot write '" << xdmf_path_ << "'");
    out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
        << "  <Grid Name=\"" << name_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames_) {
      const auto item = [&](const std::string& ds, long long n, const char* type, int precision) {
        out << "     <DataItem Dimensions=\"" << n << "\" NumberType=\"" << type << "\" Precision=\"" << precision
            << "\" Format=\"HDF\">" << f.file << ":/" << ds << "</DataItem>\n";
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
      for (const auto& n : f.fields) {
        out << "    <Attribute Name=\"" << n << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
        item(n, f.n_points, "Float", 8);
        out << "    </Attribute>\n";
      }
      out << "   </Grid>\n";
    }
    out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  }
  std::rename(tmp.c_str(), xdmf_path_.c_str());
}

const std::vector<double>& FieldFrameData::field(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) HALFETI_USER_ERROR("field file has no field '" << name << "'");
  return values[static_cast<size_t>(it - names.begin())];
}

FieldFrameData read_field_file(const std::string& path) {
  quiet_hdf5();
  H5Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open '" + path + "'");
  FieldFrameData d;
  {
    H5Id attr(H5Aopen(file, "time", H5P_DEFAULT), H5Aclose, "attribute time of '" + base_name(path) + "'");
    h5check(H5Aread(attr, H5T_NATIVE_DOUBLE, &d.time), "read time");
  }
  d.x = read_all<double>(file, "x", H5T_NATIVE_DOUBLE);
  d.y = read_all<double>(file, "y", H5T_NATIVE_DOUBLE);
  hsize_t n_links = 0;
  H5G_info_t info;
  h5check(H5Gget_info(file, &info), "group info");
  n_links = info.nlinks;
  for (hsize_t i = 0; i < n_links; ++i) {
    char name[256];
    H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    const std::string n(name);
    if (n == "x" || n == "y") continue;
    if (n == "cells") {
      d.cells = read_all<std::int64_t>(file, "cells", H5T_NATIVE_INT64);
      continue;
    }
    d.names.push_back(n);
    d.values.push_back(read_all<double>(file, n, H5T_NATIVE_DOUBLE));
  }
  return d;
}

}  // namespace halfeti::io
