// The neighbour-only communication plan on 1-4 ranks: the same items in the same places as MPI_Alltoallv gives,
// for sparse patterns found by discovery (many rounds back to back, so a fast rank's next round cannot be taken
// for the last) and for symmetric peer sets; messages go to the ranks that receive something only.
#include <gtest/gtest.h>
#include <mpi.h>

#include <random>

#include "halfeti/parallel/comm_plan.hpp"
#include "halfeti/parallel/halo_plan.hpp"

using namespace halfeti::parallel;

namespace {
// Items rank r sends to rank d in round k: a sparse pattern (about half the pairs empty), the same on every rank.
int pattern(int round, int r, int d, int size) {
  std::mt19937 rng(static_cast<unsigned>(1000 * round + 31 * r + d));
  const int n = static_cast<int>(rng() % 7);
  return (rng() % 2 == 0 && size > 1) ? 0 : n;
}
double item(int round, int r, int d, int j, int c) {
  return 1e6 * round + 1e4 * r + 100 * d + j + 0.25 * c;
}
}  // namespace

TEST(CommPlan, DiscoveryGivesAlltoallvsLayoutRoundAfterRound) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  Traffic traffic;
  for (int round = 0; round < 200; ++round) {
    std::vector<int> counts(size), displs(size), rcounts(size), rdispls(size);
    std::vector<double> send;
    for (int d = 0; d < size; ++d) {
      counts[d] = pattern(round, rank, d, size);
      displs[d] = static_cast<int>(send.size() / 2);
      for (int j = 0; j < counts[d]; ++j)
        for (int c = 0; c < 2; ++c) send.push_back(item(round, rank, d, j, c));
    }
    const CommPlan plan = CommPlan::discover(MPI_COMM_WORLD, counts, &traffic);
    int total = 0;
    for (int r = 0; r < size; ++r) {
      rcounts[r] = pattern(round, r, rank, size);
      rdispls[r] = total;
      total += rcounts[r];
    }
    ASSERT_EQ(plan.recv_total(), static_cast<std::size_t>(total)) << "round " << round;
    std::vector<double> got(2 * total), want(2 * total);
    plan.exchange(send.data(), got.data(), 2, MPI_DOUBLE);
    for (int r = 0; r < size; ++r) {
      counts[r] *= 2, displs[r] *= 2, rcounts[r] *= 2, rdispls[r] *= 2;
    }
    MPI_Alltoallv(send.data(), counts.data(), displs.data(), MPI_DOUBLE, want.data(), rcounts.data(),
                  rdispls.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    ASSERT_EQ(got, want) << "round " << round;
  }
  // Two messages (the count and the data) to each other rank that receives something, nothing else.
  std::int64_t expected = 0;
  for (int round = 0; round < 200; ++round)
    for (int d = 0; d < size; ++d) expected += (d != rank && pattern(round, rank, d, size) > 0) ? 2 : 0;
  EXPECT_EQ(traffic.messages, expected);
}

TEST(CommPlan, HaloTalksToNeighbourRanksOnly) {
  // A strip of cells split into one block per rank: each rank's neighbours are the blocks beside it (at most 2),
  // whatever the rank count, and its halo messages a step are twice that (counts, then data).
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const CellGrid grid = CellGrid::covering(0.0, 0.0, 4.0 * size, 1.0, 0.25);
  std::vector<int> owner(grid.cell_count());
  for (int c = 0; c < grid.cell_count(); ++c) owner[c] = (c % grid.nx) * size / grid.nx;
  const std::vector<int> peers = neighbour_ranks(grid, owner, rank);
  std::vector<int> expected_peers;
  if (rank > 0) expected_peers.push_back(rank - 1);
  if (rank + 1 < size) expected_peers.push_back(rank + 1);
  EXPECT_EQ(peers, expected_peers);
  std::vector<int> cells;  // one particle in every owned cell
  for (int c = 0; c < grid.cell_count(); ++c)
    if (owner[c] == rank) cells.push_back(c);
  Traffic traffic;
  const HaloPlan plan(MPI_COMM_WORLD, grid, owner, cells, peers, &traffic);
  std::vector<double> field(cells.begin(), cells.end());
  plan.update(field, cells.size());
  EXPECT_EQ(traffic.messages, static_cast<std::int64_t>(2 * peers.size()));
  EXPECT_EQ(plan.ghost_count(),
            peers.size() * static_cast<std::size_t>(grid.ny));  // a column of cells a side
  for (std::size_t k = cells.size(); k < field.size();
       ++k) {  // ghosts: cells of the neighbours' edge columns
    const int c = static_cast<int>(field[k]);
    EXPECT_NE(owner[c], rank);
  }
}
