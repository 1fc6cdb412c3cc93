// Interface search, gather by global id, and the hand-back of corrections by owner rank and local index.
#include "halfeti/coupling/interface_exchange.hpp"

#include <algorithm>
#include <cmath>

#include "halfeti/core/error.hpp"
#include "halfeti/coupling/ssosd.hpp"
#include "halfeti/parallel/gather.hpp"

namespace halfeti::coupling {

void Corrections::reset(std::size_t count) {
  for (auto* v : {&dx, &dy, &dvx, &dvy, &drho, &fx, &fy}) v->assign(count, 0.0);
  touched.clear();
}

std::vector<Invader> find_local_invaders(const InterfaceParticles& p, const SurfacePolyline& surface,
                                         double layer, double reach, int rank) {
  std::vector<Invader> out;
  if (surface.segment_count() == 0) return out;
  // An invader is within max(layer, depth inside) of the surface: runs of segments farther away are skipped.
  const SurfaceSearch search(surface, std::max(layer, reach));
  for (std::size_t i = 0; i < p.count; ++i) {
    const Eigen::Vector2d x(p.x[i], p.y[i]);
    const ContactPoint c = search.closest_within_reach(x);
    if (c.segment < 0 || !is_invader(c.projection.gap, layer)) continue;
    out.push_back(Invader{p.gid[i], p.x[i], p.y[i], p.vx[i], p.vy[i], p.mass[i], rank, static_cast<int>(i)});
  }
  return out;
}

std::vector<Invader> gather_invaders(MPI_Comm comm, int root, const std::vector<Invader>& local) {
  std::vector<Invader> all = parallel::gather_to_root(comm, root, local);
  // Principle 5: the structure sees its invaders in global id order whatever the decomposition.
  std::sort(all.begin(), all.end(), [](const Invader& a, const Invader& b) { return a.gid < b.gid; });
  return all;
}

namespace {
struct CorrectionMessage {
  int local;
  InvaderCorrection c;
};
}  // namespace

void scatter_corrections(MPI_Comm comm, int root, const std::vector<Invader>& gathered,
                         const std::vector<InvaderCorrection>& corrections,
                         const InterfaceParticles& particles, Corrections& out) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::vector<int> counts(size, 0), displs(size, 0);
  std::vector<CorrectionMessage> send;
  if (rank == root) {
    HALFETI_CHECK(gathered.size() == corrections.size(), "one correction per invader expected");
    std::vector<std::vector<CorrectionMessage>> by_rank(size);
    for (std::size_t k = 0; k < gathered.size(); ++k)
      by_rank[gathered[k].owner].push_back({gathered[k].local, corrections[k]});
    for (int r = 0; r < size; ++r) {
      displs[r] = static_cast<int>(send.size() * sizeof(CorrectionMessage));
      counts[r] = static_cast<int>(by_rank[r].size() * sizeof(CorrectionMessage));
      send.insert(send.end(), by_rank[r].begin(), by_rank[r].end());
    }
  }
  int bytes = 0;
  MPI_Scatter(counts.data(), 1, MPI_INT, &bytes, 1, MPI_INT, root, comm);
  std::vector<CorrectionMessage> mine(static_cast<std::size_t>(bytes) / sizeof(CorrectionMessage));
  MPI_Scatterv(send.data(), counts.data(), displs.data(), MPI_BYTE, mine.data(), bytes, MPI_BYTE, root, comm);

  out.reset(particles.count);
  for (const auto& m : mine) {
    HALFETI_CHECK(m.local >= 0 && static_cast<std::size_t>(m.local) < particles.count,
                  "correction for local particle " << m.local << " of " << particles.count);
    const std::size_t i = static_cast<std::size_t>(m.local);
    out.dx[i] = m.c.dx;
    out.dy[i] = m.c.dy;
    out.dvx[i] = m.c.dvx;
    out.dvy[i] = m.c.dvy;
    out.fx[i] = m.c.fx;
    out.fy[i] = m.c.fy;
    // Eq. 24 for the density: the relocated particle takes the value at its new place to first order.
    if (particles.grad_rho != nullptr)
      out.drho[i] = m.c.dx * particles.grad_rho[2 * i] + m.c.dy * particles.grad_rho[2 * i + 1];
    out.touched.push_back(m.local);
  }
  std::sort(out.touched.begin(), out.touched.end());
}

}  // namespace halfeti::coupling
