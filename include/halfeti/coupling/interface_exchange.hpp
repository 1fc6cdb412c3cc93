// The interface between the distributed fluid and the structure's rank (DESIGN.md "One time step", steps 3
// and 5): each rank finds its owned particles in the intermediate layer or past the plate's surface, they are
// gathered to the structure's rank sorted by global id (so the contact solve sees the same list on any number
// of ranks), and the corrections go back to the owning ranks by (rank, local index).
#pragma once

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "halfeti/coupling/contact_kinematics.hpp"

namespace halfeti::coupling {

// What the coupling reads from the fluid: the owned particles of this rank, after the fluid's prediction to t
// + dt (views into the fluid's arrays; all of length count).
struct InterfaceParticles {
  std::size_t count = 0;
  const std::int64_t* gid = nullptr;
  const double* x = nullptr;
  const double* y = nullptr;
  const double* vx = nullptr;
  const double* vy = nullptr;
  const double* mass = nullptr;  // kg/m (per unit depth)
  const double* grad_rho =
      nullptr;  // renormalised density gradient (eq. 6), 2 per particle (x, y); may be null
};

// One particle in the contact solve, as gathered on the structure's rank.
struct Invader {
  std::int64_t gid = 0;
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0, mass = 0.0;
  int owner = 0;  // rank in the coupling communicator
  int local = 0;  // index among the owner's owned particles
};

// What the solve returns for one invader (in the gathered order).
struct InvaderCorrection {
  double dx = 0.0, dy = 0.0;    // m, relocation (contact + SSOSD, eq. 21-22)
  double dvx = 0.0, dvy = 0.0;  // m/s, C dt / m (the contact acceleration Delta C of eq. 4 over the step)
  double fx = 0.0, fy = 0.0;    // N/m, contact force C on the particle
};

// The fluid's side of step 5: one entry per owned particle, zero where the particle took no part.
struct Corrections {
  std::vector<double> dx, dy;    // m: add to the position
  std::vector<double> dvx, dvy;  // m/s: add to the velocity
  std::vector<double> drho;      // kg/m^3: add to the density (eq. 24: displacement . grad rho)
  std::vector<double> fx, fy;    // N/m: the contact force (diagnostics, probes)
  std::vector<int> touched;      // local indices of the particles that were corrected, ascending
  void reset(std::size_t count);
};

// Owned particles with gap < layer (layer > 0) or past the surface (layer = 0), by closest segment. reach
// bounds how far inside a particle can be (half the plate's thickness is enough; the coupling passes the
// thickness).
std::vector<Invader> find_local_invaders(const InterfaceParticles& particles, const SurfacePolyline& surface,
                                         double layer, double reach, int rank);

// Collective over comm: every rank's invaders on root, sorted by gid; empty on the other ranks.
std::vector<Invader> gather_invaders(MPI_Comm comm, int root, const std::vector<Invader>& local);

// Collective over comm: root holds gathered invaders and their corrections (same order); every rank fills
// `out` for its owned particles (out is reset to particles.count entries), including eq. 24's density
// correction.
void scatter_corrections(MPI_Comm comm, int root, const std::vector<Invader>& gathered,
                         const std::vector<InvaderCorrection>& corrections,
                         const InterfaceParticles& particles, Corrections& out);

}  // namespace halfeti::coupling
