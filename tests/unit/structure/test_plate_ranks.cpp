// The plate on several ranks (METIS partition, MPIAIJ, MUMPS) gives the same answer as one rank: a large
// static deflection, then dynamic steps under a tank acceleration. Each rank also solves the whole plate
// alone on PETSC_COMM_SELF as the reference.
#include <gtest/gtest.h>

#include <algorithm>

#include "halfeti/core/error.hpp"
#include "plate_fixtures.hpp"

namespace hs = halfeti::structure;

namespace {

struct PlateRun {
  Eigen::Vector2d static_tip, dynamic_tip;
  double strain_energy, kinetic_energy, max_von_mises;
  double energy_from_density, max_element_von_mises;  // from the per-element output fields
  int iterations;
};

PlateRun run(MPI_Comm comm, hs::ElementType element) {
  const auto p = hs::testing::paper_plate(2, 30, 0.45, element);
  hs::testing::ConstantGroundMotion ground(3.0);
  hs::PlateSolver s(comm, p, &ground);
  // A spring (a stand-in cable) from the top left corner to an anchor down and to the left.
  const int corner = s.mesh().node("top_left");
  hs::testing::AnchorSpring spring(corner, s.mesh().nodes[corner] + Eigen::Vector2d(-0.05, -0.05), 2.0);
  s.add_nodal_element(&spring);
  const double l = p.geometry.height;
  const double load = 0.5 * hs::testing::bending_stiffness(p) / (l * l);
  s.add_edge_load("top", Eigen::Vector2d(load / p.geometry.thickness, 0.0));
  PlateRun r;
  r.iterations = s.solve_static(0.0, 2).newton_iterations;
  const int tip = s.mesh().node("top_right");
  r.static_tip = s.displacement(tip);
  s.clear_loads();
  s.initialise_acceleration(0.0);
  for (int n = 0; n < 10; ++n) r.iterations += s.step(n * 1e-3, 1e-3).newton_iterations;
  r.dynamic_tip = s.displacement(tip);
  r.strain_energy = s.strain_energy();
  r.kinetic_energy = s.kinetic_energy();
  r.max_von_mises = s.max_von_mises();
  std::vector<double> von_mises, density;
  s.element_fields(von_mises, density);
  // The mesh is uniform: every element has the area thickness x height / element count.
  const double area = p.geometry.thickness * p.geometry.height / s.mesh().element_count();
  r.energy_from_density = 0.0;
  for (double e : density) r.energy_from_density += e * area;
  r.max_element_von_mises = *std::max_element(von_mises.begin(), von_mises.end());
  return r;
}

TEST(PlateRanks, SameAnswerOnOneAndSeveralRanks) {
  for (auto element : {hs::ElementType::kQ9, hs::ElementType::kQ4Eas}) {
    SCOPED_TRACE(hs::to_string(element));
    int size = 0;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    const PlateRun alone = run(PETSC_COMM_SELF, element);
    const PlateRun shared = run(PETSC_COMM_WORLD, element);
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank == 0)
      std::printf(
          "%s, ranks %d: static tip (%.12e, %.12e), after 10 steps (%.12e, %.12e), Newton iterations %d vs "
          "%d\n",
          hs::to_string(element).c_str(), size, shared.static_tip.x(), shared.static_tip.y(),
          shared.dynamic_tip.x(), shared.dynamic_tip.y(), shared.iterations, alone.iterations);
    EXPECT_GT(alone.static_tip.x(), 0.1 * 0.08);
    EXPECT_NEAR((shared.static_tip - alone.static_tip).norm(), 0.0, 1e-12);
    EXPECT_NEAR((shared.dynamic_tip - alone.dynamic_tip).norm(), 0.0, 1e-12);
    EXPECT_NEAR(shared.strain_energy, alone.strain_energy, 1e-10 * alone.strain_energy);
    EXPECT_NEAR(shared.kinetic_energy, alone.kinetic_energy, 1e-8 * alone.kinetic_energy);
    EXPECT_NEAR(shared.max_von_mises, alone.max_von_mises, 1e-8 * alone.max_von_mises);
    // The output's per-element fields: the energy densities integrate to the strain energy, the element means stay
    // below the largest point value (and above half of it in this bending), on any rank count.
    EXPECT_NEAR(shared.energy_from_density, shared.strain_energy, 1e-10 * shared.strain_energy);
    EXPECT_LE(shared.max_element_von_mises, shared.max_von_mises * (1 + 1e-12));
    EXPECT_GT(shared.max_element_von_mises, 0.5 * shared.max_von_mises);
    EXPECT_NEAR(shared.max_element_von_mises, alone.max_element_von_mises,
                1e-8 * alone.max_element_von_mises);
    // Sums in another order can move a convergence test across its threshold by one iteration.
    EXPECT_NEAR(shared.iterations, alone.iterations, 2);
  }
}

TEST(PlateRanks, PartitionOwnsEveryNodeOnce) {
  hs::StructureParameters p;
  p.geometry.cells_across = 2;
  p.geometry.cells_along = 12;
  hs::PlateSolver s(PETSC_COMM_WORLD, p);
  const auto& part = s.partition();
  int owned = part.owned_blocks, total = 0;
  MPI_Allreduce(&owned, &total, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(total, s.node_count());
  int elements = static_cast<int>(part.owned_elements.size()), all = 0;
  MPI_Allreduce(&elements, &all, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(all, static_cast<int>(s.mesh().elements.size()));
}

}  // namespace

namespace {

// An element inverted on one rank only (the crushed top elements belong to one METIS part) stops every rank with
// the same NumericalError instead of leaving the others waiting in the residual's reduction.
TEST(PlateRanks, InvertedElementStopsEveryRank) {
  hs::PlateSolver s(PETSC_COMM_WORLD, hs::testing::paper_plate(1, 10));
  s.add_edge_load("top", Eigen::Vector2d(0.0, -5e7));  // Pa: crushes the top elements in the first iterate
  std::string what;
  try {
    s.solve_static(0.0, 1);
  } catch (const halfeti::NumericalError& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("in element"), std::string::npos) << what;
  // The same message on every rank.
  int length = static_cast<int>(what.size()), longest = 0, shortest = 0;
  MPI_Allreduce(&length, &longest, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  MPI_Allreduce(&length, &shortest, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  EXPECT_EQ(longest, shortest);
}

}  // namespace
