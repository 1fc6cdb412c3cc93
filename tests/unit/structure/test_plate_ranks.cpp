// The structure runs on one rank in this version: on one rank it builds, on more it refuses with a UserError
// that names structure.ranks.
#include <gtest/gtest.h>

#include "halfeti/core/error.hpp"
#include "halfeti/structure/plate_solver.hpp"

TEST(PlateRanks, OneRankRunsMoreAreRefused) {
  int size = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  halfeti::structure::StructureParameters p;
  p.geometry.cells_along = 4;
  p.geometry.cells_across = 1;
  if (size == 1) {
    halfeti::structure::PlateSolver s(PETSC_COMM_WORLD, p);
    EXPECT_EQ(s.solve_static(0.0, 1).newton_iterations > 0, true);
  } else {
    try {
      halfeti::structure::PlateSolver s(PETSC_COMM_WORLD, p);
      ADD_FAILURE() << "expected a UserError";
    } catch (const halfeti::UserError& e) {
      EXPECT_NE(std::string(e.what()).find("structure.ranks"), std::string::npos) << e.what();
    }
  }
}
