#include "hdf5_file.hpp"

#include <sys/statvfs.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include "halfeti/core/error.hpp"

namespace halfeti::io::h5 {

namespace {
MPI_Comm g_collective = MPI_COMM_NULL;  // set by CollectiveWrites
std::string g_file;                     // the file it writes

// HDF5's drivers do not always leave errno set; a full file system is the common cause, and it can be seen.
std::string reason_of_failure() {
  if (errno != 0) return std::strerror(errno);
  if (g_file.empty()) return "";
  const auto slash = g_file.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : g_file.substr(0, slash);
  struct statvfs fs {};
  if (::statvfs(dir.c_str(), &fs) == 0 && static_cast<double>(fs.f_bavail) * fs.f_frsize < 1024.0 * 1024.0)
    return std::string(std::strerror(ENOSPC)) + " (less than 1 MiB free on the file system of '" + dir + "')";
  return "";
}
}  // namespace

void fail(Use use, const std::string& what) {
  if (use == Use::kRead) HALFETI_USER_ERROR("HDF5: " << what << " failed");
  const std::string reason = reason_of_failure();
  if (!reason.empty()) HALFETI_IO_ERROR("HDF5: " << what << " failed: " << reason);
  HALFETI_IO_ERROR("HDF5: " << what << " failed");
}

CollectiveWrites::CollectiveWrites(MPI_Comm comm, const std::string& file)
    : previous_(g_collective), previous_file_(g_file) {
  g_collective = comm;
  g_file = file;
}
CollectiveWrites::~CollectiveWrites() {
  g_collective = previous_;
  g_file = previous_file_;
}

void check(herr_t status, Use use, const std::string& what) {
  if (use == Use::kWrite && g_collective != MPI_COMM_NULL) {
    int outcome[2] = {status < 0 ? 1 : 0, status < 0 ? errno : 0};  // failed anywhere; the system's reason
    MPI_Allreduce(MPI_IN_PLACE, outcome, 2, MPI_INT, MPI_MAX, g_collective);
    if (outcome[0] == 0) return;
    errno = outcome[1];
    fail(use, what);
  }
  if (status < 0) fail(use, what);
}

void quiet() {
  static bool done = false;
  if (!done) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    done = true;
  }
}

hid_t create_collective(MPI_Comm comm, const std::string& path) {
  Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, Use::kWrite, "file access list");
  check(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL), Use::kWrite, "MPI-IO file access");
  errno = 0;
  return H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
}

void write_slab(hid_t where, const std::string& name, hid_t type, const void* data, long long offset,
                long long count, long long total, const std::string& file, int columns) {
  const std::string what = "write " + name + " to '" + file + "'";
  const int rank = columns > 1 ? 2 : 1;
  const hsize_t dims[2] = {static_cast<hsize_t>(total), static_cast<hsize_t>(columns)};
  Id space(H5Screate_simple(rank, dims, nullptr), H5Sclose, Use::kWrite, "dataspace for " + name);
  errno = 0;
  Id dset(H5Dcreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
          Use::kWrite, "create dataset " + name + " in '" + file + "'");
  if (total == 0) return;  // an empty dataset: nothing to transfer
  const hsize_t start[2] = {static_cast<hsize_t>(offset), 0},
                cnt[2] = {static_cast<hsize_t>(count), static_cast<hsize_t>(columns)};
  Id filespace(H5Dget_space(dset), H5Sclose, Use::kWrite, "file space of " + name);
  Id memspace(H5Screate_simple(rank, cnt, nullptr), H5Sclose, Use::kWrite, "memory space of " + name);
  // The same checks on every rank (they are collective under CollectiveWrites), whether it writes or not.
  const herr_t selected = count > 0
                              ? H5Sselect_hyperslab(filespace, H5S_SELECT_SET, start, nullptr, cnt, nullptr)
                              : std::min(H5Sselect_none(filespace), H5Sselect_none(memspace));
  check(selected, Use::kWrite, "select " + name);
  Id xfer(H5Pcreate(H5P_DATASET_XFER), H5Pclose, Use::kWrite, "transfer list");
  check(H5Pset_dxpl_mpio(xfer, H5FD_MPIO_COLLECTIVE), Use::kWrite, "collective transfer");
  errno = 0;
  check(H5Dwrite(dset, type, memspace, filespace, xfer, data), Use::kWrite, what);
}

void write_attribute(hid_t where, const std::string& name, double value, const std::string& file) {
  Id space(H5Screate(H5S_SCALAR), H5Sclose, Use::kWrite, "scalar space");
  Id attr(H5Acreate2(where, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
          Use::kWrite, "attribute " + name + " of '" + file + "'");
  check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), Use::kWrite, "write " + name + " to '" + file + "'");
}

void write_attribute(hid_t where, const std::string& name, const std::string& value,
                     const std::string& file) {
  Id type(H5Tcopy(H5T_C_S1), H5Tclose, Use::kWrite, "string type");
  check(H5Tset_size(type, value.empty() ? 1 : value.size()), Use::kWrite, "string size");
  Id space(H5Screate(H5S_SCALAR), H5Sclose, Use::kWrite, "scalar space");
  Id attr(H5Acreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, Use::kWrite,
          "attribute " + name + " of '" + file + "'");
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  check(H5Awrite(attr, type, padded.data()), Use::kWrite, "write " + name + " to '" + file + "'");
}

double read_double_attribute(hid_t where, const std::string& name, const std::string& file) {
  Id attr(H5Aopen(where, name.c_str(), H5P_DEFAULT), H5Aclose, Use::kRead,
          "attribute " + name + " of '" + file + "'");
  double value = 0.0;
  check(H5Aread(attr, H5T_NATIVE_DOUBLE, &value), Use::kRead, "read " + name + " of '" + file + "'");
  return value;
}

std::string read_string_attribute(hid_t where, const std::string& name, const std::string& file) {
  Id attr(H5Aopen(where, name.c_str(), H5P_DEFAULT), H5Aclose, Use::kRead,
          "attribute " + name + " of '" + file + "'");
  Id type(H5Aget_type(attr), H5Tclose, Use::kRead, "type of " + name);
  const std::size_t n = H5Tget_size(type);
  std::string value(n, '\0');
  check(H5Aread(attr, type, value.data()), Use::kRead, "read " + name + " of '" + file + "'");
  return value.substr(0, value.find('\0'));
}

DatasetShape dataset_shape(hid_t where, const std::string& name, const std::string& file) {
  Id dset(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose, Use::kRead,
          "open dataset " + name + " of '" + file + "'");
  Id space(H5Dget_space(dset), H5Sclose, Use::kRead, "space of " + name);
  Id type(H5Dget_type(dset), H5Tclose, Use::kRead, "type of " + name);
  hsize_t dims[2] = {0, 1};
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > 2) fail(Use::kRead, "dataset " + name + " of '" + file + "' is neither 1-D nor 2-D");
  H5Sget_simple_extent_dims(space, dims, nullptr);
  return {static_cast<long long>(dims[0]), rank == 2 ? static_cast<int>(dims[1]) : 1,
          H5Tget_class(type) == H5T_INTEGER};
}

void write_dataset_attribute(hid_t where, const std::string& dataset, const std::string& name,
                             const std::string& value, const std::string& file) {
  Id dset(H5Dopen2(where, dataset.c_str(), H5P_DEFAULT), H5Dclose, Use::kWrite,
          "open dataset " + dataset + " of '" + file + "'");
  write_attribute(dset, name, value, file);
}

std::string read_dataset_attribute(hid_t where, const std::string& dataset, const std::string& name,
                                   const std::string& file) {
  Id dset(H5Dopen2(where, dataset.c_str(), H5P_DEFAULT), H5Dclose, Use::kRead,
          "open dataset " + dataset + " of '" + file + "'");
  if (H5Aexists(dset, name.c_str()) <= 0) return "";
  return read_string_attribute(dset, name, file);
}

template <class T>
std::vector<T> read_all(hid_t where, const std::string& name, hid_t type, const std::string& file) {
  Id dset(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose, Use::kRead,
          "open dataset " + name + " of '" + file + "'");
  Id space(H5Dget_space(dset), H5Sclose, Use::kRead, "space of " + name);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<size_t>(n > 0 ? n : 0));
  if (n > 0)
    check(H5Dread(dset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), Use::kRead, "read " + name);
  return out;
}

template std::vector<double> read_all<double>(hid_t, const std::string&, hid_t, const std::string&);
template std::vector<std::int64_t> read_all<std::int64_t>(hid_t, const std::string&, hid_t,
                                                          const std::string&);
template std::vector<char> read_all<char>(hid_t, const std::string&, hid_t, const std::string&);

}  // namespace halfeti::io::h5
