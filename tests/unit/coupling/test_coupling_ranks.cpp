// The coupled step across ranks: the same invaders in global id order and bitwise the same corrections
// whatever the decomposition (np 1-4), against a reference computed on one rank in the same run; collective
// errors.
#include <gtest/gtest.h>
#include <mpi.h>
#include <petscsys.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include "coupling_fixtures.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/coupling/contact_coupling.hpp"

namespace hc = halfeti::coupling;
namespace hs = halfeti::structure;

namespace {

// Particles of one rank, with the arrays the fluid would hold.
struct Cloud {
  std::vector<std::int64_t> gid;
  std::vector<double> x, y, vx, vy, mass, grad;
  hc::InterfaceParticles view() const {
    hc::InterfaceParticles p;
    p.count = gid.size();
    p.gid = gid.data();
    p.x = x.data();
    p.y = y.data();
    p.vx = vx.data();
    p.vy = vy.data();
    p.mass = mass.data();
    p.grad_rho = grad.data();
    return p;
  }
  void apply(const hc::Corrections& c, double dt) {
    for (std::size_t i = 0; i < gid.size(); ++i) {
      x[i] += c.dx[i] + dt * (vx[i] + c.dvx[i]);  // correction, then the next step's drift
      y[i] += c.dy[i] + dt * (vy[i] + c.dvy[i]);
      vx[i] += c.dvx[i];
      vy[i] += c.dvy[i];
    }
  }
};

// Columns of water on both sides of the 3 mm plate: some past the faces, some in the SSOSD layer, most
// outside, all moving towards the plate. Particle g goes to rank (7 g) % size, stored in descending gid
// order.
Cloud make_cloud(int rank, int size) {
  Cloud c;
  const double half = 1.5e-3, dx = hc::testing::kSpacing;
  const double offsets[] = {4.8e-4, 4.95e-4, 1e-3, 2.5e-3};  // entering the 0.5 mm layer, outside
  std::int64_t g = 0;
  std::vector<std::int64_t> mine;
  for (int j = 0; j < 50; ++j)
    for (int side = 0; side < 2; ++side)
      for (double o : offsets) {
        const std::int64_t id = g++;
        if ((7 * id) % size != rank) continue;
        const double s = side == 0 ? 1.0 : -1.0;
        c.gid.push_back(id);
        c.x.push_back(s * (half + o));
        c.y.push_back(0.004 + j * dx);
        c.vx.push_back(-s * 0.3);
        c.vy.push_back(0.05 * std::sin(0.3 * j));
        c.mass.push_back(hc::testing::kParticleMass);
        c.grad.insert(c.grad.end(), {10.0 * s, 9810.0});
      }
  // Descending gid storage: the gather must sort.
  std::vector<std::size_t> order(c.gid.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = order.size() - 1 - i;
  Cloud r;
  for (std::size_t i : order) {
    r.gid.push_back(c.gid[i]);
    r.x.push_back(c.x[i]);
    r.y.push_back(c.y[i]);
    r.vx.push_back(c.vx[i]);
    r.vy.push_back(c.vy[i]);
    r.mass.push_back(c.mass[i]);
    r.grad.insert(r.grad.end(), {c.grad[2 * i], c.grad[2 * i + 1]});
  }
  return r;
}

using Record = std::array<double, 7>;  // dx, dy, dvx, dvy, drho, x, y (after the step)

// Runs `steps` coupled steps on comm and returns, on rank 0 of comm, every particle's record by gid.
std::map<std::int64_t, Record> run(MPI_Comm comm, int steps, std::vector<int>* invaders,
                                   const hc::CouplingParameters& params) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::unique_ptr<hs::PlateSolver> plate;
  if (rank == 0) plate = std::make_unique<hs::PlateSolver>(PETSC_COMM_SELF, hc::testing::plate(2, 20));
  hc::ContactCoupling coupling(comm, plate.get(), params);
  Cloud cloud = make_cloud(rank, size);
  hc::Corrections corr;
  const double dt = 1e-4;
  for (int n = 0; n < steps; ++n) {
    const auto& report = coupling.step(n * dt, dt, cloud.view(), corr);
    if (invaders) invaders->push_back(report.invaders);
    if (std::getenv("HALFETI_DEBUG") && rank == 0)
      std::printf("step %d: %d invaders, L = %.3e m, u_max %.3f, F = (%.3e, %.3e), max %.3e, newton %d\n", n,
                  report.invaders, report.layer, report.u_max, report.force_x, report.force_y,
                  report.max_force, report.newton_iterations);
    if (n + 1 < steps) cloud.apply(corr, dt);
  }
  // Gather records (gid + 7 doubles) to rank 0.
  std::vector<double> mine;
  for (std::size_t i = 0; i < cloud.gid.size(); ++i)
    mine.insert(mine.end(), {static_cast<double>(cloud.gid[i]), corr.dx[i], corr.dy[i], corr.dvx[i],
                             corr.dvy[i], corr.drho[i], cloud.x[i] + corr.dx[i], cloud.y[i] + corr.dy[i]});
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(size), displs(size);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  int total = 0;
  for (int r = 0; r < size; ++r) displs[r] = total, total += counts[r];
  std::vector<double> all(rank == 0 ? total : 0);
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm);
  std::map<std::int64_t, Record> out;
  for (std::size_t k = 0; k + 7 < all.size() + 1; k += 8) {
    Record r;
    std::copy(all.begin() + k + 1, all.begin() + k + 8, r.begin());
    out[static_cast<std::int64_t>(all[k])] = r;
  }
  return out;
}

}  // namespace

class SameCorrections : public ::testing::TestWithParam<int> {};

TEST_P(SameCorrections, OnAnyNumberOfRanks) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  hc::CouplingParameters params;  // 0: tied, condensed (defaults)
  if (GetParam() == 1) {          // 1: frictionless, full saddle point with MUMPS
    params.constraint = hc::ContactConstraint::kNormal;
    params.solver = hc::ContactSolver::kSaddlePoint;
  }
  std::vector<int> invaders;
  const auto distributed = run(MPI_COMM_WORLD, 3, &invaders, params);
  for (int n : invaders) EXPECT_GT(n, 0);
  if (rank == 0) {
    std::vector<int> reference_invaders;
    const auto reference = run(MPI_COMM_SELF, 3, &reference_invaders, params);
    EXPECT_EQ(invaders, reference_invaders);
    ASSERT_EQ(distributed.size(), reference.size());
    int corrected = 0;
    for (const auto& [gid, rec] : reference) {
      const Record& other = distributed.at(gid);
      EXPECT_EQ(std::memcmp(rec.data(), other.data(), sizeof(Record)), 0) << "particle " << gid;  // bitwise
      if (rec[0] != 0.0 || rec[1] != 0.0) ++corrected;
    }
    EXPECT_GT(corrected, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(ContactCoupling, SameCorrections, ::testing::Values(0, 1));

TEST(ContactCoupling, ForcesOnParticlesAndOutlineOnEveryRank) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::unique_ptr<hs::PlateSolver> plate;
  if (rank == 0) plate = std::make_unique<hs::PlateSolver>(PETSC_COMM_SELF, hc::testing::plate(2, 20));
  hc::ContactCoupling coupling(MPI_COMM_WORLD, plate.get(), hc::CouplingParameters{});
  EXPECT_EQ(coupling.outline().size(), 2u * 40 + 4);  // 2 faces x 40 segments + 4 on the top
  Cloud cloud = make_cloud(rank, size);
  hc::Corrections corr;
  const auto& report = coupling.step(0.0, 1e-4, cloud.view(), corr);
  double sum[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < corr.fx.size(); ++i) sum[0] += corr.fx[i], sum[1] += corr.fy[i];
  MPI_Allreduce(MPI_IN_PLACE, sum, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_NEAR(sum[0], report.force_x, 1e-12 * report.max_force * report.invaders);
  EXPECT_NEAR(sum[1], report.force_y, 1e-12 * report.max_force * report.invaders);
  EXPECT_GT(report.layer, 0.0);
  // Both faces pushed: the horizontal forces nearly cancel, the plate barely moves as a whole.
  EXPECT_LT(std::abs(report.force_x), 0.2 * report.max_force * report.invaders);
  // The plate moved: the outline each rank holds is the new surface, identical on every rank.
  auto outline = coupling.outline();
  std::vector<double> flat;
  for (const auto& b : outline) flat.insert(flat.end(), {b.xa, b.ya, b.xb, b.yb});
  std::vector<double> root = flat;
  MPI_Bcast(root.data(), static_cast<int>(root.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  EXPECT_EQ(std::memcmp(root.data(), flat.data(), flat.size() * sizeof(double)), 0);
}

TEST(ContactCoupling, FailureIsRaisedOnEveryRankTogether) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::unique_ptr<hs::PlateSolver> plate;
  auto p = hc::testing::plate(2, 20);
  p.newton.max_iterations = 1;  // cannot converge a contact step in one iteration
  if (rank == 0) plate = std::make_unique<hs::PlateSolver>(PETSC_COMM_SELF, p);
  hc::ContactCoupling coupling(MPI_COMM_WORLD, plate.get(), hc::CouplingParameters{});
  Cloud cloud = make_cloud(rank, size);
  hc::Corrections corr;
  try {
    coupling.step(0.0, 1e-4, cloud.view(), corr);
    ADD_FAILURE() << "expected a NumericalError";
  } catch (const halfeti::NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("t = 0 -> 0.0001 s"), std::string::npos) << what;
    EXPECT_NE(what.find("did not converge"), std::string::npos) << what;
  }
}

TEST(ContactCoupling, UnilateralContactReleasesParticlesThePlateWouldPull) {
  // The plate moves away from the particles on its right face (v = -0.5 m/s): with bilateral contact the
  // layer's targets would pull them along (C . n < 0); the active set releases them instead.
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  for (bool unilateral : {true, false}) {
    std::unique_ptr<hs::PlateSolver> plate;
    if (rank == 0) {
      plate = std::make_unique<hs::PlateSolver>(PETSC_COMM_SELF, hc::testing::plate(2, 20));
      Eigen::VectorXd v = Eigen::VectorXd::Zero(plate->dof_count());
      for (int n = 0; n < plate->node_count(); ++n) v(2 * n) = -0.5 * plate->mesh().nodes[n].y() / 0.08;
      plate->set_state(Eigen::VectorXd::Zero(plate->dof_count()), v);
    }
    hc::CouplingParameters params;
    params.unilateral = unilateral;
    hc::ContactCoupling coupling(MPI_COMM_WORLD, plate.get(), params);
    Cloud cloud = make_cloud(rank, size);
    for (auto& vx : cloud.vx) vx = 0.0;  // water at rest
    hc::Corrections corr;
    const auto& report = coupling.step(0.0, 1e-4, cloud.view(), corr);
    int pulled = 0;
    for (std::size_t i = 0; i < corr.fx.size(); ++i) {
      const double outward = cloud.x[i] > 0 ? corr.fx[i] : -corr.fx[i];  // n = +x right, -x left
      if (outward < -1e-12) ++pulled;
    }
    MPI_Allreduce(MPI_IN_PLACE, &pulled, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    if (unilateral) {
      EXPECT_GT(report.released, 0);
      EXPECT_EQ(pulled, 0);
    } else {
      EXPECT_EQ(report.released, 0);
      EXPECT_GT(pulled, 0);
    }
  }
}
