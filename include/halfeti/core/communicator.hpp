// RAII owner of a duplicated MPI communicator: each part (fluid, structure, output) talks on its own, so that
// messages of one never match receives of another. The destructor frees it.
#pragma once

#include <mpi.h>

namespace halfeti {

class Communicator {
 public:
  Communicator() = default;
  // Duplicates `parent` (collective over parent). MPI_COMM_NULL stays null (a rank outside a sub-communicator).
  explicit Communicator(MPI_Comm parent) {
    if (parent != MPI_COMM_NULL) MPI_Comm_dup(parent, &comm_);
  }
  // Takes ownership of a communicator already created (e.g. by MPI_Comm_split).
  static Communicator adopt(MPI_Comm owned) {
    Communicator c;
    c.comm_ = owned;
    return c;
  }
  ~Communicator() { release(); }
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;
  Communicator(Communicator&& o) noexcept : comm_(o.comm_) { o.comm_ = MPI_COMM_NULL; }
  Communicator& operator=(Communicator&& o) noexcept {
    if (this != &o) {
      release();
      comm_ = o.comm_;
      o.comm_ = MPI_COMM_NULL;
    }
    return *this;
  }

  MPI_Comm get() const { return comm_; }
  bool valid() const { return comm_ != MPI_COMM_NULL; }
  int rank() const {
    int r = -1;
    if (valid()) MPI_Comm_rank(comm_, &r);
    return r;
  }
  int size() const {
    int s = 0;
    if (valid()) MPI_Comm_size(comm_, &s);
    return s;
  }

 private:
  void release() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (comm_ != MPI_COMM_NULL && !finalized) MPI_Comm_free(&comm_);
    comm_ = MPI_COMM_NULL;
  }
  MPI_Comm comm_ = MPI_COMM_NULL;
};

}  // namespace halfeti
