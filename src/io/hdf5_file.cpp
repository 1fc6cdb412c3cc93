#include "hdf5_file.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "halfeti/core/error.hpp"

namespace halfeti::io::h5 {

void fail(Use use, const std::string& what) {
  if (use == Use::kRead) HALFETI_USER_ERROR("HDF5: " << what << " failed");
  const int reason = errno;
  if (reason != 0) HALFETI_IO_ERROR("HDF5: " << what << " failed: " << std::strerror(reason));
  HALFETI_IO_ERROR("HDF5: " << what << " failed");
}

void quiet() {
  static bool done = false;
  if (!done) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    done = true;
  }
}

hid_t mpio_access(MPI_Comm comm) {
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl < 0) fail(Use::kWrite, "file access list");
  if (H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL) < 0) {
    H5Pclose(fapl);
    fail(Use::kWrite, "MPI-IO file access");
  }
  return fapl;
}

void write_slab(hid_t where, const std::string& name, hid_t type, const void* data, long long offset,
                long long count, long long total, const std::string& file) {
  const std::string what = "write " + name + " to '" + file + "'";
  const hsize_t dims[1] = {static_cast<hsize_t>(total)};
  Id space(H5Screate_simple(1, dims, nullptr), H5Sclose, Use::kWrite, "dataspace for " + name);
  errno = 0;
  Id dset(H5Dcreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
          Use::kWrite, "create dataset " + name + " in '" + file + "'");
  if (total == 0) return;  // an empty dataset: nothing to transfer
  const hsize_t start[1] = {static_cast<hsize_t>(offset)}, cnt[1] = {static_cast<hsize_t>(count)};
  Id filespace(H5Dget_space(dset), H5Sclose, Use::kWrite, "file space of " + name);
  Id memspace(H5Screate_simple(1, cnt, nullptr), H5Sclose, Use::kWrite, "memory space of " + name);
  if (count > 0) {
    check(H5Sselect_hyperslab(filespace, H5S_SELECT_SET, start, nullptr, cnt, nullptr), Use::kWrite,
          "select " + name);
  } else {
    check(H5Sselect_none(filespace), Use::kWrite, "select none " + name);
    check(H5Sselect_none(memspace), Use::kWrite, "select none " + name);
  }
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

void write_attribute(hid_t where, const std::string& name, const std::string& value, const std::string& file) {
  Id type(H5Tcopy(H5T_C_S1), H5Tclose, Use::kWrite, "string type");
  check(H5Tset_size(type, value.empty() ? 1 : value.size()), Use::kWrite, "string size");
  Id space(H5Screate(H5S_SCALAR), H5Sclose, Use::kWrite, "scalar space");
  Id attr(H5Acreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, Use::kWrite,
          "attribute " + name + " of '" + file + "'");
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  check(H5Awrite(attr, type, padded.data()), Use::kWrite, "write " + name + " to '" + file + "'");
}

double read_double_attribute(hid_t where, const std::string& name, const std::string& file) {
  Id attr(H5Aopen(where, name.c_str(), H5P_DEFAULT), H5Aclose, Use::kRead, "attribute " + name + " of '" + file + "'");
  double value = 0.0;
  check(H5Aread(attr, H5T_NATIVE_DOUBLE, &value), Use::kRead, "read " + name + " of '" + file + "'");
  return value;
}

std::string read_string_attribute(hid_t where, const std::string& name, const std::string& file) {
  Id attr(H5Aopen(where, name.c_str(), H5P_DEFAULT), H5Aclose, Use::kRead, "attribute " + name + " of '" + file + "'");
  Id type(H5Aget_type(attr), H5Tclose, Use::kRead, "type of " + name);
  const std::size_t n = H5Tget_size(type);
  std::string value(n, '\0');
  check(H5Aread(attr, type, value.data()), Use::kRead, "read " + name + " of '" + file + "'");
  return value.substr(0, value.find('\0'));
}

template <class T>
std::vector<T> read_all(hid_t where, const std::string& name, hid_t type, const std::string& file) {
  Id dset(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose, Use::kRead,
          "open dataset " + name + " of '" + file + "'");
  Id space(H5Dget_space(dset), H5Sclose, Use::kRead, "space of " + name);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<size_t>(n > 0 ? n : 0));
  if (n > 0) check(H5Dread(dset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), Use::kRead, "read " + name);
  return out;
}

template std::vector<double> read_all<double>(hid_t, const std::string&, hid_t, const std::string&);
template std::vector<std::int64_t> read_all<std::int64_t>(hid_t, const std::string&, hid_t, const std::string&);
template std::vector<char> read_all<char>(hid_t, const std::string&, hid_t, const std::string&);

}  // namespace halfeti::io::h5
