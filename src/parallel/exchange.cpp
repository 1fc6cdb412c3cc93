#include "halfeti/parallel/exchange.hpp"

namespace halfeti::parallel {

void exchange_items(MPI_Comm comm, const std::vector<int>& send_counts, const std::vector<int>& send_displs,
                    const std::vector<int>& recv_counts, const std::vector<int>& recv_displs, int ncomp,
                    const void* send, void* recv, MPI_Datatype type) {
  const int size = static_cast<int>(send_counts.size());
  std::vector<int> sc(size), sd(size), rc(size), rd(size);
  for (int r = 0; r < size; ++r) {
    sc[r] = send_counts[r] * ncomp;
    sd[r] = send_displs[r] * ncomp;
    rc[r] = recv_counts[r] * ncomp;
    rd[r] = recv_displs[r] * ncomp;
  }
  MPI_Alltoallv(send, sc.data(), sd.data(), type, recv, rc.data(), rd.data(), type, comm);
}

}  // namespace halfeti::parallel
