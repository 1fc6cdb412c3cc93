// The one communication plan the halo and the migration share: how many items this rank sends to and receives
// from each rank it talks to, and the exchange itself, by point-to-point messages to those ranks only (no call
// over the whole communicator, so the cost grows with the neighbours, not with the ranks).
//
// Items arrive in the receive buffer grouped by source rank in increasing order (this rank's own items, if it
// keeps any, in its own rank's place): the layout an MPI_Alltoallv would give, so results do not depend on how
// the messages are timed.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace halfeti::parallel {

// Traffic of a rank, accumulated over the plans that carry a pointer to it: messages and bytes it sent (the
// counts' set-up included) and seconds spent waiting for messages to complete.
struct Traffic {
  std::int64_t messages = 0, bytes = 0;
  double wait_seconds = 0.0;
};

class CommPlan {
 public:
  CommPlan() = default;

  // Collective over `peers` (every rank that lists this one among its peers must be among this rank's):
  // `peers` are the ranks this one may exchange with (never itself), in increasing order, `send_counts[k]` the
  // items for peers[k], `keep` the items this rank sends to itself. The counts are swapped with the peers only.
  static CommPlan with_peers(MPI_Comm comm, const std::vector<int>& peers,
                             const std::vector<int>& send_counts, int keep, Traffic* traffic);
  // Collective over `comm`, but with messages to the destinations only: `send_counts[r]` items for rank r (the own
  // rank's entry is what it keeps). The sources are found by the non-blocking consensus of Hoefler, Siebert &
  // Lumsdaine (2010, "Scalable communication protocols for dynamic sparse data exchange", PPoPP): synchronous
  // sends of the counts, then a non-blocking barrier once they are matched.
  static CommPlan discover(MPI_Comm comm, const std::vector<int>& send_counts, Traffic* traffic);

  std::size_t send_total() const {
    return static_cast<std::size_t>(send_total_);
  }  // items, own ones included
  std::size_t recv_total() const {
    return static_cast<std::size_t>(recv_total_);
  }  // items, own ones included
  bool exchanges_anything() const { return !send_to_.empty() || !recv_from_.empty(); }

  // `send` holds send_total() items grouped by destination rank in increasing order (the own ones in the own
  // rank's place); `recv` receives recv_total() items, each item `ncomp` values of `type`.
  void exchange(const void* send, void* recv, int ncomp, MPI_Datatype type) const;

 private:
  struct Link {
    int rank, count, offset;  // items, and the first item's place in the buffer
  };
  void finish_layout(int keep);

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  std::vector<Link> send_to_, recv_from_;  // other ranks only, in increasing rank; counts > 0
  int keep_ = 0, keep_send_offset_ = 0, keep_recv_offset_ = 0;
  int send_total_ = 0, recv_total_ = 0;
  Traffic* traffic_ = nullptr;
};

}  // namespace halfeti::parallel
