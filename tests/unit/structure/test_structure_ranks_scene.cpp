// structure.ranks through the program: a plate in air solved on a communicator of two ranks (METIS halves of the
// mesh, MUMPS) gives the probes of the same run with the structure on one rank; a rank count the run cannot give,
// and more than one structure rank in a scene with water, are one clear error each (exit status 2). Also the
// q4_eas element through the scene key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "halfeti/io/checkpoint.hpp"
#include "run_scene.hpp"

using namespace halfeti;

namespace {

const std::string kScene = test::source_path("tests/unit/structure/data/plate_in_air_ranks.yaml");

}  // namespace

TEST(StructureRanksScene, TwoStructureRanksGiveTheProbesOfOne) {
  const std::string one = test::binary_path("structure_ranks_scene_1"),
                    two = test::binary_path("structure_ranks_scene_2");
  ASSERT_EQ(test::run_scene(kScene, one, "--set structure.ranks=1", 2), 0)
      << test::read_text(one + ".stderr");
  ASSERT_EQ(test::run_scene(kScene, two, "--set structure.ranks=2", 2), 0)
      << test::read_text(two + ".stderr");
  EXPECT_NE(test::read_text(two + "/log.txt").find("ranks = 2"), std::string::npos);
  const auto a = io::read_probe_csv(one + "/probes.csv"), b = io::read_probe_csv(two + "/probes.csv");
  // The static start bends the plate by ~18 % of its height, then 40 dynamic steps: the same run, summed in a
  // different order and factorised by MUMPS instead of PETSc's Cholesky. Every probe agrees to 1e-7 of its
  // largest magnitude (the CSV keeps 9 significant digits).
  for (const char* name :
       {"tip_x", "tip_y", "strain_energy", "kinetic_energy", "von_mises", "right_stress"}) {
    const auto x = a.column(name), y = b.column(name);
    ASSERT_EQ(x.size(), 21u) << name;
    ASSERT_EQ(y.size(), x.size()) << name;
    double scale = 0.0;
    for (double v : x) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0) << name;
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_NEAR(x[i], y[i], 1e-7 * scale) << name << " at row " << i;
  }
  EXPECT_GT(a.column("tip_x")[0], 0.1 * 0.08);  // a large deflection, not a trivial state
  // Outputs are written once: the plate's field series holds one copy of the nodes on either rank count, and so
  // does its checkpoint state.
  EXPECT_EQ(test::read_text(one + "/fields/plate.xdmf"), test::read_text(two + "/fields/plate.xdmf"));
  const auto c1 = io::list_checkpoints(one + "/checkpoints"), c2 = io::list_checkpoints(two + "/checkpoints");
  ASSERT_EQ(c1.size(), 1u);
  ASSERT_EQ(c2.size(), 1u);
  EXPECT_EQ(io::read_checkpoint(c1[0]).blocks.at("plate").size(),
            io::read_checkpoint(c2[0]).blocks.at("plate").size());
}

TEST(StructureRanksScene, MoreRanksThanTheRunIsOneError) {
  const std::string out = test::binary_path("structure_ranks_scene_3");
  EXPECT_EQ(test::run_scene(kScene, out, "--set structure.ranks=3", 2), 2);
  const std::string err = test::read_text(out + ".stderr");
  EXPECT_NE(err.find("structure.ranks: 3 ranks for the structure, but the run has 2 MPI rank(s)"),
            std::string::npos)
      << err;
  // Said once (rank 0), not once per rank; mpirun's own report of the exit status may follow.
  EXPECT_EQ(err.find("halfeti: error:"), err.rfind("halfeti: error:")) << err;
}

TEST(StructureRanksScene, CoupledScenesNeedOneStructureRank) {
  const std::string out = test::binary_path("structure_ranks_scene_coupled");
  // Checked before the rank count: one rank is enough to see it.
  EXPECT_EQ(test::run_scene(test::source_path("inputs/validation/still_plate.yaml"), out,
                            "--set structure.ranks=2 --set scene.end_time=0.001"),
            2);
  const std::string err = test::read_text(out + ".stderr");
  EXPECT_NE(err.find("structure.ranks: 2: scenes with water (coupled) need structure.ranks: 1"),
            std::string::npos)
      << err;
}

// structure.element: q4_eas through the program: the cable-bent plate of the scene on the paper's 2 x 60 layout
// with both elements. Tolerance 1 % of each probe's largest magnitude: the two discretisations differ by their
// errors (small tip load: Q9 -0.40 %, Q4-EAS -0.67 % from beam theory; measured here 0.06 % on the tip, 0.16 % on
// the strain energy). The maximum von Mises stress is sampled at different points (3x3 against 2x2) and is not
// compared. An odd count across is one error.
TEST(StructureRanksScene, Q4EasElementGivesTheProbesOfQ9) {
  const std::string q9 = test::binary_path("structure_scene_q9"),
                    q4 = test::binary_path("structure_scene_q4_eas");
  ASSERT_EQ(test::run_scene(kScene, q9, "--set structure.cells_along=60"), 0)
      << test::read_text(q9 + ".stderr");
  ASSERT_EQ(test::run_scene(kScene, q4, "--set structure.cells_along=60 --set structure.element=q4_eas"), 0)
      << test::read_text(q4 + ".stderr");
  EXPECT_NE(test::read_text(q4 + "/log.txt").find("2 x 60 Q4-EAS (120 elements, 366 dofs)"),
            std::string::npos);
  const auto a = io::read_probe_csv(q9 + "/probes.csv"), b = io::read_probe_csv(q4 + "/probes.csv");
  for (const char* name : {"tip_x", "tip_y", "strain_energy", "right_stress"}) {
    const auto x = a.column(name), y = b.column(name);
    ASSERT_EQ(y.size(), x.size()) << name;
    double scale = 0.0;
    for (double v : x) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_NEAR(x[i], y[i], 1e-2 * scale) << name << " at row " << i;
  }
  const std::string odd = test::binary_path("structure_scene_q4_odd");
  EXPECT_EQ(test::run_scene(kScene, odd, "--set structure.element=q4_eas --set structure.cells_across=1"), 2);
  EXPECT_NE(
      test::read_text(odd + ".stderr").find("structure.cells_across: 1 must be even with element: q4_eas"),
      std::string::npos)
      << test::read_text(odd + ".stderr");
}

TEST(StructureRanksScene, AnUnusedPetscOptionIsNamed) {
  // A misspelt option after `--` changes nothing: the run says which options nothing read.
  const std::string out = test::binary_path("structure_ranks_scene_petsc");
  ASSERT_EQ(test::run_scene(kScene, out, "--set structure.ranks=1 -- -structure_ksp_tpye gmres", 1), 0)
      << test::read_text(out + ".stderr");
  const std::string err = test::read_text(out + ".stderr");
  EXPECT_NE(err.find("halfeti: warning: PETSc options given after '--' that nothing used"), std::string::npos)
      << err;
  EXPECT_NE(err.find("-structure_ksp_tpye"), std::string::npos) << err;
}
