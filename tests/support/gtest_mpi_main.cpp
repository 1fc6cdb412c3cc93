// GoogleTest main for halfeti tests: initialises MPI (or PETSc, which initialises MPI), runs every test on every
// rank, prints only rank 0's report, and fails the whole run if any rank failed.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdio>

#ifdef HALFETI_TEST_WITH_PETSC
#include <petscsys.h>
#endif

int main(int argc, char** argv) {
#ifdef HALFETI_TEST_WITH_PETSC
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0) return 1;
#else
  MPI_Init(&argc, &argv);
#endif
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int local_failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
  int failed_ranks = 0;
  MPI_Allreduce(&local_failed, &failed_ranks, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0 && failed_ranks > 0 && !local_failed)
    std::fprintf(stderr, "%d rank(s) other than rank 0 failed a test\n", failed_ranks);
#ifdef HALFETI_TEST_WITH_PETSC
  PetscFinalize();
#else
  MPI_Finalize();
#endif
  return failed_ranks > 0 ? 1 : 0;
}
