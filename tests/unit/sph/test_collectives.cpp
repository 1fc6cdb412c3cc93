// The water's step and the whole communicator: a step may call only the collectives its design counts on
// (docs/scaling.md), because each one costs 2 log2(P) latencies on P ranks and is where every rank waits for the
// slowest. Counted by wrapping the MPI calls in this test binary (the profiling interface: each wrapper counts and
// calls the PMPI_ function; the libraries are static, so their calls come here).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdint>
#include <vector>

#include "halfeti/sph/fluid.hpp"

using namespace halfeti::sph;

namespace {
long allreduces = 0, ibarriers = 0, others = 0;  // this rank's calls
}  // namespace

extern "C" {
int MPI_Allreduce(const void* s, void* r, int n, MPI_Datatype t, MPI_Op o, MPI_Comm c) {
  ++allreduces;
  return PMPI_Allreduce(s, r, n, t, o, c);
}
int MPI_Ibarrier(MPI_Comm c, MPI_Request* q) {
  ++ibarriers;
  return PMPI_Ibarrier(c, q);
}
int MPI_Barrier(MPI_Comm c) {
  ++others;
  return PMPI_Barrier(c);
}
int MPI_Bcast(void* b, int n, MPI_Datatype t, int root, MPI_Comm c) {
  ++others;
  return PMPI_Bcast(b, n, t, root, c);
}
int MPI_Alltoall(const void* s, int sn, MPI_Datatype st, void* r, int rn, MPI_Datatype rt, MPI_Comm c) {
  ++others;
  return PMPI_Alltoall(s, sn, st, r, rn, rt, c);
}
int MPI_Allgather(const void* s, int sn, MPI_Datatype st, void* r, int rn, MPI_Datatype rt, MPI_Comm c) {
  ++others;
  return PMPI_Allgather(s, sn, st, r, rn, rt, c);
}
int MPI_Gather(const void* s, int sn, MPI_Datatype st, void* r, int rn, MPI_Datatype rt, int root,
               MPI_Comm c) {
  ++others;
  return PMPI_Gather(s, sn, st, r, rn, rt, root, c);
}
}

// A dam break in a small tank (water moving, crossing the ranks' borders every few steps), no events: a step calls
// two all-reductions (the time step's maxima; the health checks' findings, joined into one), nothing else over
// the communicator: the migration talks to the halo peers only, as no particle goes past them in a step. Before
// (to 6 Dec) a step made six all-reductions and, on more than one rank, a non-blocking barrier (the
// migration's consensus on who sends to whom).
TEST(Collectives, AWaterStepCallsTwoAllReductions) {
  FluidParams p;
  p.tank_length = 0.20;
  p.tank_height = 0.12;
  p.spacing = 0.004;
  p.water = {{0.0, 0.0, 0.08, 0.08, 0.0}};
  p.rebalance_interval = 0;  // a new partition is a collective of its own, at its interval
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  for (int s = 0; s < 3; ++s) fluid.step();  // the first steps may set things up
  ASSERT_TRUE(fluid.health_events().empty());
  allreduces = ibarriers = others = 0;
  constexpr int kSteps = 40;
  for (int s = 0; s < kSteps; ++s) fluid.step();
  ASSERT_TRUE(fluid.health_events().empty()) << "an event gathers more: the count below assumes none";
  EXPECT_EQ(allreduces, 2 * kSteps);
  EXPECT_EQ(ibarriers, 0);
  EXPECT_EQ(others, 0);
}

// A particle carried further than a cell in one step (here by the coupling's correction hook, from the water's left
// end to near its right end) can land on a rank that is not a halo peer of its own: the health scan sees it, and
// that step's migration finds its senders over the whole communicator (one non-blocking barrier) instead of
// swapping counts with the peers only. Every particle is then held once, the carried one where it was put.
TEST(Collectives, AParticleCarriedPastTheHaloPeersReachesItsRank) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  FluidParams p;
  p.tank_length = 0.60;
  p.tank_height = 0.10;
  p.spacing = 0.005;
  p.water = {{0.0, 0.0, 0.60, 0.04, 0.0}};
  p.rebalance_interval = 0;
  Fluid fluid(MPI_COMM_WORLD, p, nullptr);
  fluid.step();
  // The water's leftmost particle (lowest id among the leftmost) and the rank that owns it.
  struct {
    double x;
    int rank;
  } left{1e9, rank};
  int mine = -1;
  for (std::size_t i = 0; i < fluid.owned_count(); ++i)
    if (fluid.x()[i] < left.x) {
      left.x = fluid.x()[i];
      mine = static_cast<int>(i);
    }
  PMPI_Allreduce(MPI_IN_PLACE, &left, 1, MPI_DOUBLE_INT, MPI_MINLOC, MPI_COMM_WORLD);
  fluid.compute_forces();
  fluid.predict();
  const std::size_t n = fluid.owned_count();
  std::vector<double> dx(n, 0.0), dy(n, 0.0), zero(n, 0.0);
  std::vector<int> touched;
  std::int64_t carried = -1;
  const double target = 0.55 + 0.25 * p.spacing;  // off the lattice, well inside the water
  double carried_y = 0.0;
  if (rank == left.rank) {
    touched.push_back(mine);
    dx[mine] = target - fluid.x()[mine];
    carried = fluid.gid()[mine];
    carried_y = fluid.y()[mine];
  }
  PMPI_Bcast(&carried, 1, MPI_INT64_T, left.rank, MPI_COMM_WORLD);
  PMPI_Bcast(&carried_y, 1, MPI_DOUBLE, left.rank, MPI_COMM_WORLD);
  fluid.apply_corrections(touched, dx.data(), dy.data(), zero.data(), zero.data(), zero.data());
  allreduces = ibarriers = others = 0;
  ASSERT_NO_THROW(fluid.finish());
  // On 2 ranks the other rank is a peer (the two parts touch); on 3 the long strip of water is cut across into three
  // and its ends are not neighbours.
  if (size == 2) {
    EXPECT_EQ(ibarriers, 0);
  } else if (size == 3) {
    EXPECT_EQ(ibarriers, 1);
  }
  long held = static_cast<long>(fluid.owned_count()), found = 0;
  for (std::size_t i = 0; i < fluid.owned_count(); ++i)
    if (fluid.gid()[i] == carried) {
      ++found;
      EXPECT_EQ(fluid.x()[i], target);
      EXPECT_EQ(fluid.y()[i], carried_y);
    }
  PMPI_Allreduce(MPI_IN_PLACE, &held, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  PMPI_Allreduce(MPI_IN_PLACE, &found, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(held, fluid.global_count());
  EXPECT_EQ(found, 1);
  ASSERT_NO_THROW(fluid.step());  // and the water goes on
}
