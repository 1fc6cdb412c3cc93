#include "halfeti/parallel/comm_plan.hpp"

#include <algorithm>
#include <cstring>

#include "halfeti/core/error.hpp"

namespace halfeti::parallel {

namespace {
// Tags of the plan's point-to-point messages. The discovery's alternate between successive rounds, so that a rank
// still in round k (its barrier done but not yet tested) cannot take a faster rank's round k + 1 count as its own;
// every rank calls discover() in the same order, so the round counter agrees. Counts and data name their source,
// and MPI keeps messages of one source and tag in order.
constexpr int kTagCounts = 7101, kTagDiscover = 7102, kTagData = 7104;
int discover_round = 0;

void add_traffic(Traffic* t, std::int64_t messages, std::int64_t bytes, double wait) {
  if (!t) return;
  t->messages += messages;
  t->bytes += bytes;
  t->wait_seconds += wait;
}
}  // namespace

void CommPlan::finish_layout(int keep) {
  keep_ = keep;
  const auto lay = [&](std::vector<Link>& links, int& keep_offset, int& total) {
    int offset = 0;
    bool placed = false;
    for (auto& l : links) {
      if (!placed && l.rank > rank_) {
        keep_offset = offset;
        offset += keep;
        placed = true;
      }
      l.offset = offset;
      offset += l.count;
    }
    if (!placed) {
      keep_offset = offset;
      offset += keep;
    }
    total = offset;
  };
  lay(send_to_, keep_send_offset_, send_total_);
  lay(recv_from_, keep_recv_offset_, recv_total_);
}

CommPlan CommPlan::with_peers(MPI_Comm comm, const std::vector<int>& peers,
                              const std::vector<int>& send_counts, int keep, Traffic* traffic) {
  HALFETI_CHECK(peers.size() == send_counts.size(), "one send count per peer");
  HALFETI_CHECK(std::is_sorted(peers.begin(), peers.end()), "peers in increasing rank");
  CommPlan p;
  p.comm_ = comm;
  p.traffic_ = traffic;
  MPI_Comm_rank(comm, &p.rank_);
  const std::size_t n = peers.size();
  std::vector<int> recv_counts(n, 0);
  std::vector<MPI_Request> req(2 * n);
  for (std::size_t k = 0; k < n; ++k) {
    HALFETI_CHECK(peers[k] != p.rank_, "a rank is not its own peer");
    MPI_Irecv(&recv_counts[k], 1, MPI_INT, peers[k], kTagCounts, comm, &req[k]);
    MPI_Isend(&send_counts[k], 1, MPI_INT, peers[k], kTagCounts, comm, &req[n + k]);
  }
  const double t0 = MPI_Wtime();
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
  add_traffic(traffic, static_cast<std::int64_t>(n), static_cast<std::int64_t>(n * sizeof(int)),
              MPI_Wtime() - t0);
  for (std::size_t k = 0; k < n; ++k) {
    if (send_counts[k] > 0) p.send_to_.push_back({peers[k], send_counts[k], 0});
    if (recv_counts[k] > 0) p.recv_from_.push_back({peers[k], recv_counts[k], 0});
  }
  p.finish_layout(keep);
  return p;
}

CommPlan CommPlan::discover(MPI_Comm comm, const std::vector<int>& send_counts, Traffic* traffic) {
  CommPlan p;
  p.comm_ = comm;
  p.traffic_ = traffic;
  int size = 1;
  MPI_Comm_rank(comm, &p.rank_);
  MPI_Comm_size(comm, &size);
  HALFETI_CHECK(static_cast<int>(send_counts.size()) == size, "one send count per rank");
  const int tag = kTagDiscover + (discover_round++ & 1);
  std::vector<MPI_Request> sends;
  for (int r = 0; r < size; ++r)
    if (r != p.rank_ && send_counts[r] > 0) {
      p.send_to_.push_back({r, send_counts[r], 0});
      sends.emplace_back();
      MPI_Issend(&send_counts[r], 1, MPI_INT, r, tag, comm, &sends.back());
    }
  const double t0 = MPI_Wtime();
  MPI_Request barrier = MPI_REQUEST_NULL;
  bool barrier_started = false;
  for (;;) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag, comm, &arrived, &status);
    if (arrived) {
      int count = 0;
      MPI_Recv(&count, 1, MPI_INT, status.MPI_SOURCE, tag, comm, MPI_STATUS_IGNORE);
      p.recv_from_.push_back({status.MPI_SOURCE, count, 0});
      continue;
    }
    int done = 0;
    if (barrier_started) {
      MPI_Test(&barrier, &done, MPI_STATUS_IGNORE);
      if (done) break;
    } else {
      MPI_Testall(static_cast<int>(sends.size()), sends.data(), &done, MPI_STATUSES_IGNORE);
      if (done) {  // every count of ours has been taken: say so, and keep taking others' until all have
        MPI_Ibarrier(comm, &barrier);
        barrier_started = true;
      }
    }
  }
  add_traffic(traffic, static_cast<std::int64_t>(sends.size()),
              static_cast<std::int64_t>(sends.size() * sizeof(int)), MPI_Wtime() - t0);
  std::sort(p.recv_from_.begin(), p.recv_from_.end(),
            [](const Link& a, const Link& b) { return a.rank < b.rank; });
  p.finish_layout(send_counts[p.rank_]);
  return p;
}

void CommPlan::exchange(const void* send, void* recv, int ncomp, MPI_Datatype type) const {
  int type_size = 0;
  MPI_Type_size(type, &type_size);
  const std::size_t item = static_cast<std::size_t>(ncomp) * static_cast<std::size_t>(type_size);
  const char* s = static_cast<const char*>(send);
  char* r = static_cast<char*>(recv);
  std::vector<MPI_Request> req;
  req.reserve(send_to_.size() + recv_from_.size());
  for (const auto& l : recv_from_) {
    req.emplace_back();
    MPI_Irecv(r + l.offset * item, l.count * ncomp, type, l.rank, kTagData, comm_, &req.back());
  }
  std::int64_t bytes = 0;
  for (const auto& l : send_to_) {
    req.emplace_back();
    MPI_Isend(s + l.offset * item, l.count * ncomp, type, l.rank, kTagData, comm_, &req.back());
    bytes += static_cast<std::int64_t>(l.count) * static_cast<std::int64_t>(item);
  }
  if (keep_ > 0) std::memcpy(r + keep_recv_offset_ * item, s + keep_send_offset_ * item, keep_ * item);
  const double t0 = MPI_Wtime();
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
  add_traffic(traffic_, static_cast<std::int64_t>(send_to_.size()), bytes, MPI_Wtime() - t0);
}

}  // namespace halfeti::parallel
