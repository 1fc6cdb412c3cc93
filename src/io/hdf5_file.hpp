// HDF5 helpers shared by the field series and the checkpoints (private to the io library): an owner for HDF5
// identifiers, checked calls whose failure names what failed and why, and the collective 1-D slab write and the
// whole-dataset read both file kinds are made of.
#pragma once

#include <hdf5.h>
#include <mpi.h>

#include <string>
#include <vector>

namespace halfeti::io::h5 {

// What a failed call was doing: writing an output (an I/O error, exit status 6, with the system's reason when it
// left one in errno) or reading a file the user named (bad input, exit status 2).
enum class Use { kWrite, kRead };
[[noreturn]] void fail(Use use, const std::string& what);

// While one lives, the write checks are collective over its communicator: a file written collectively has every
// rank make the same calls in the same order, and a call that fails on one rank (a full disk seen by the rank that
// writes a block) must fail on all, or the others wait in the next collective call forever.
class CollectiveWrites {
 public:
  // `file`: the path being written, for the reason of a failure (its file system's free space).
  CollectiveWrites(MPI_Comm comm, const std::string& file);
  ~CollectiveWrites();
  CollectiveWrites(const CollectiveWrites&) = delete;
  CollectiveWrites& operator=(const CollectiveWrites&) = delete;

 private:
  MPI_Comm previous_;
  std::string previous_file_;
};

void check(herr_t status, Use use, const std::string& what);

// Owns one HDF5 identifier and closes it with the matching H5*close.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t), Use use, const std::string& what) : id_(id), close_(close) {
    check(id_ < 0 ? -1 : 0, use, what);
  }
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id_; }  // NOLINT(google-explicit-constructor)
  // Closes now and checks the result (a file's close flushes it: a full disk shows here).
  void close(const std::string& what) {
    const hid_t id = id_;
    id_ = -1;
    check(close_(id), Use::kWrite, what);
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void quiet();  // no HDF5 error stacks on stderr: our messages name what failed

// Collective: this rank's `count` rows at row `offset` of a dataset of `total` rows, in `where` (a file or group):
// 1-D with one column, `total` x `columns` (row-major) with more.
void write_slab(hid_t where, const std::string& name, hid_t type, const void* data, long long offset,
                long long count, long long total, const std::string& file, int columns = 1);

// What a stored dataset is: its column count (1 for a 1-D dataset) and whether it holds integers.
struct DatasetShape {
  long long rows = 0;
  int columns = 1;
  bool integer = false;
};
DatasetShape dataset_shape(hid_t where, const std::string& name, const std::string& file);

template <class T>
std::vector<T> read_all(hid_t where, const std::string& name, hid_t type, const std::string& file);

// Scalar attributes of a file or group (writes are collective where the file is).
void write_attribute(hid_t where, const std::string& name, double value, const std::string& file);
void write_attribute(hid_t where, const std::string& name, const std::string& value, const std::string& file);
double read_double_attribute(hid_t where, const std::string& name, const std::string& file);
std::string read_string_attribute(hid_t where, const std::string& name, const std::string& file);
// A string attribute of the dataset `dataset` in `where` (collective where the file is), and its reading back
// ("" when the dataset has no such attribute).
void write_dataset_attribute(hid_t where, const std::string& dataset, const std::string& name,
                             const std::string& value, const std::string& file);
std::string read_dataset_attribute(hid_t where, const std::string& dataset, const std::string& name,
                                   const std::string& file);

// Creates (truncating) `path` for collective writing over MPI-IO; a negative id on failure (check it with Id).
hid_t create_collective(MPI_Comm comm, const std::string& path);

}  // namespace halfeti::io::h5
