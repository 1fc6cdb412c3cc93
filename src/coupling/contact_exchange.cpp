// The converged plate-water exchange's verdict on one evaluation of the water's load (docs/coupling.md, section 16):
// ContactCoupling::converge_exchange, kept apart from the coupled step it repeats.
#include <cstdio>

#include "halfeti/core/error.hpp"
#include "halfeti/coupling/contact_coupling.hpp"

namespace halfeti::coupling {

ExchangeIterate ContactCoupling::converge_exchange(const std::vector<sph::PlateWallLoad>& local) {
  HALFETI_CHECK(params_.implicit_exchange(), "converge_exchange() belongs to plate_wall_exchange: implicit");
  ScopedTimer timer(timers_, "exchange");
  const std::vector<Eigen::Vector2d> load = gather_point_loads(local, false);
  ExchangeIterate out;
  out.iteration = exchange_iteration_++;
  double verdict[2] = {0.0, 0.0};  // residual, converged
  if (rank_ == root_) {
    const auto n = static_cast<Eigen::Index>(loads_.size());
    Eigen::VectorXd in(2 * n), produced(2 * n);
    for (Eigen::Index k = 0; k < n; ++k) {
      in.segment<2>(2 * k) = loads_[static_cast<std::size_t>(k)]->force();
      produced.segment<2>(2 * k) = load[static_cast<std::size_t>(k)];
    }
    verdict[0] = InterfaceQuasiNewton::residual_ratio(in, produced);
    if (params_.trace) {  // --trace coupling: each evaluation, and the surface point whose load changed most
      Eigen::Index worst = 0;
      (produced - in).cwiseAbs().maxCoeff(&worst);
      const auto point = static_cast<std::size_t>(worst / 2);
      std::fprintf(
          stderr,
          "exchange_trace k=%d residual=%.3e invaders=%d |F_out|=%.4g worst point %zu at (%.5f, %.5f): "
          "in %.4g out %.4g\n",
          out.iteration, verdict[0], last_.invaders, produced.norm(), point, surface_.points[point].x(),
          surface_.points[point].y(), in(worst), produced(worst));
    }
    // The water's load is piecewise smooth in the plate's motion: a particle within round-off of a face is water on
    // one side and the contact's on the other, and its ghost load (up to half the plate's total, measured on the
    // paper's plate) switches with it. Where that keeps the exchange from converging, the iteration stops after
    // kStall evaluations without a new best, or at max_iterations, and the step is taken with the best iterate
    // (evaluated once more when it was not the last).
    constexpr int kStall = 3;
    if (out.iteration == 0 || verdict[0] < best_residual_) {
      best_residual_ = verdict[0];
      best_iteration_ = out.iteration;
      best_input_ = in;
    }
    if (returning_to_best_ || verdict[0] <= params_.implicit.tolerance) {
      verdict[1] = 1.0;  // accept
    } else if (exchange_iteration_ >= params_.implicit.max_iterations ||
               out.iteration - best_iteration_ >= kStall) {
      if (best_iteration_ == out.iteration) {
        verdict[1] = 1.0;
      } else {
        returning_to_best_ = true;
        for (Eigen::Index k = 0; k < n; ++k)
          loads_[static_cast<std::size_t>(k)]->set_force(best_input_.segment<2>(2 * k));
      }
    } else {
      const Eigen::VectorXd next = accelerator_.next(in, produced);
      for (Eigen::Index k = 0; k < n; ++k)
        loads_[static_cast<std::size_t>(k)]->set_force(next.segment<2>(2 * k));
    }
    if (verdict[1] != 0.0) returning_to_best_ = false;
  }
  MPI_Bcast(verdict, 2, MPI_DOUBLE, root_, comm_.get());
  out.residual = verdict[0];
  out.accepted = verdict[1] != 0.0;
  out.converged = verdict[0] <= params_.implicit.tolerance;
  return out;
}

}  // namespace halfeti::coupling
