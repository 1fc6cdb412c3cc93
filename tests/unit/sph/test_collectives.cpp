// The water's step and the whole communicator: a step may call only the collectives its design counts on
// (docs/scaling.md), because each one costs 2 log2(P) latencies on P ranks and is where every rank waits for the
// slowest. Counted by wrapping the MPI calls in this test binary (the profiling interface: each wrapper counts and
// calls the PMPI_ function; the libraries are static, so their calls come here).
#include <gtest/gtest.h>
#include <mpi.h>

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
int MPI_Gather(const void* s, int sn, MPI_Datatype st, void* r, int rn, MPI_Datatype rt, int root, MPI_Comm c) {
  ++others;
  return PMPI_Gather(s, sn, st, r, rn, rt, root, c);
}
}

// A dam break in a small tank (water moving, crossing the ranks' borders every few steps), no events: a step calls
// two all-reductions (the time step's maxima; the health checks' findings, joined into one) and, on more than one
// rank, the migration's non-blocking barrier (the consensus that finds who sends to whom); nothing else over the
// communicator. Before the health checks were joined a step made seven all-reductions.
TEST(Collectives, AWaterStepCallsTwoAllReductionsAndOneBarrier) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
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
  EXPECT_EQ(ibarriers, size > 1 ? kSteps : 0);
  EXPECT_EQ(others, 0);
}
