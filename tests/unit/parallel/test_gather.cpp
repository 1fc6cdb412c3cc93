// Gathers to one rank (parallel/gather.hpp) and the mesh partition (parallel/mesh_partition.hpp), on 1-4 ranks:
// the root receives every rank's records in rank order, whatever their counts (none on some ranks); the sum that
// ordered_sum forms from them is the same bits whatever the split; METIS splits a plate's element strip into
// balanced parts of neighbouring elements.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "halfeti/parallel/gather.hpp"
#include "halfeti/parallel/mesh_partition.hpp"
#include "halfeti/parallel/ordered_reduce.hpp"

using namespace halfeti;

namespace {
struct Record {
  std::int64_t gid;
  int rank;
  double value;
};

int rank_of(MPI_Comm comm) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}
int size_of(MPI_Comm comm) {
  int s = 1;
  MPI_Comm_size(comm, &s);
  return s;
}
}  // namespace

TEST(GatherToRoot, ConcatenatesEveryRanksRecordsInRankOrder) {
  const int rank = rank_of(MPI_COMM_WORLD), size = size_of(MPI_COMM_WORLD);
  for (int root = 0; root < size; ++root) {
    // Rank r sends 2 r records (rank 0 none): uneven counts, an empty contribution.
    std::vector<Record> mine;
    for (int k = 0; k < 2 * rank; ++k) mine.push_back({100 * rank + k, rank, 0.5 * k});
    const std::vector<Record> all = parallel::gather_to_root(MPI_COMM_WORLD, root, mine);
    if (rank != root) {
      EXPECT_TRUE(all.empty());
      continue;
    }
    std::size_t expected = 0;
    for (int r = 0; r < size; ++r) expected += 2 * r;
    ASSERT_EQ(all.size(), expected);
    std::size_t at = 0;
    for (int r = 0; r < size; ++r)
      for (int k = 0; k < 2 * r; ++k, ++at) {
        EXPECT_EQ(all[at].gid, 100 * r + k);
        EXPECT_EQ(all[at].rank, r);
        EXPECT_EQ(all[at].value, 0.5 * k);
      }
  }
}

TEST(OrderedSum, SameBitsWhateverTheSplit) {
  // 1000 terms of very different magnitudes, dealt to the ranks round-robin: a plain sum's bits depend on the
  // order; the ordered sum must equal the serial sum in gid order exactly.
  const int rank = rank_of(MPI_COMM_WORLD), size = size_of(MPI_COMM_WORLD);
  const int n = 1000;
  // The terms are computed once: the same expression compiled twice may be contracted differently (FMA).
  std::vector<double> term(n);
  for (int i = 0; i < n; ++i) term[i] = (i % 7 == 0 ? 1e8 : 1.0) * std::sin(0.37 * i) + 1e-8 * i;
  std::vector<std::int64_t> gids;
  std::vector<double> values;
  for (int i = n - 1; i >= 0; --i)  // each rank lists its terms backwards: the gather must sort them
    if (i % size == rank) {
      gids.push_back(i);
      values.push_back(term[i]);
      values.push_back(-2.0 * term[i]);
    }
  const std::vector<double> sums = parallel::ordered_sum(MPI_COMM_WORLD, gids, values, 2);
  double serial[2] = {0.0, 0.0};
  for (int i = 0; i < n; ++i) {
    serial[0] += term[i];
    serial[1] += -2.0 * term[i];
  }
  ASSERT_EQ(sums.size(), 2u);
  EXPECT_EQ(sums[0], serial[0]);
  EXPECT_EQ(sums[1], serial[1]);
}

TEST(MeshPartition, SplitsAStripIntoBalancedParts) {
  // A plate's 2 x 20 strip of quadrilaterals (node (i, j) = j * 3 + i), corners listed as the plate lists them.
  const int across = 2, along = 20, ne = across * along, nn = (across + 1) * (along + 1);
  std::vector<int> start{0}, nodes;
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < across; ++i) {
      const int a = j * (across + 1) + i;
      for (int v : {a, a + 1, a + across + 2, a + across + 1}) nodes.push_back(v);
      start.push_back(static_cast<int>(nodes.size()));
    }
  for (int parts : {2, 3, 4}) {
    const std::vector<int> part = parallel::partition_mesh_dual(start, nodes, nn, 2, parts);
    ASSERT_EQ(static_cast<int>(part.size()), ne);
    std::vector<int> count(parts, 0);
    for (int p : part) {
      ASSERT_GE(p, 0);
      ASSERT_LT(p, parts);
      ++count[p];
    }
    // METIS's default imbalance tolerance is 3 % for this call; on 40 elements allow one element more.
    const int most = *std::max_element(count.begin(), count.end());
    EXPECT_LE(most, (ne + parts - 1) / parts + 1) << parts << " parts";
    EXPECT_GT(*std::min_element(count.begin(), count.end()), 0) << parts << " parts";
    // Reproducible: the same call gives the same parts.
    EXPECT_EQ(parallel::partition_mesh_dual(start, nodes, nn, 2, parts), part);
  }
}
