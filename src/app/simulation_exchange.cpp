// The coupled step with the plate-water exchange converged within the step (coupling.plate_wall_exchange:
// implicit; docs/coupling.md, section 16). The explicit step hands the plate the water's load of the step's start
// (extrapolated) and the water the plate's motion of the step before: on a plate light against the water it moves
// (the paper's rubber plate with the trapezoidal rule), that lag feeds energy into the plate-water motion. Here:
//
//   forces at t_n with the plate at t_n (done by the last step, or now)      F_n, the water's rates
//   save the water, the plate, its cables and the coupling
//   F_in = 2 F_n - F_n-1
//   repeat:  water: kick, drift (its density held back)
//            plate + contact under F_in at t_n+1 (eq. 21)                    the plate at t_n+1
//            water: density with the faces' motion over the step, corrections, finish
//            forces at t_n+1 with the plate there                            F_out
//            |F_out - F_in| <= tol |F_out|: done (the forces serve the next step)
//            else F_in = IQN-ILS(F_in, F_out), everything put back, again
//   (a stalled iteration ends with its best iterate: ContactCoupling::converge_exchange)
//
// With the plate solved under F_n+1 the trapezoidal rule's step is the plate's own (its work the trapezoid of F_n
// and F_n+1), and the water's continuity sees the plate's actual motion: the exchange adds no energy of its own.
#include <sstream>

#include "halfeti/app/run_health.hpp"
#include "halfeti/app/simulation.hpp"
#include "halfeti/core/collective.hpp"
#include "halfeti/io/run_log.hpp"

namespace halfeti::app {

double Simulation::advance_coupled_implicit() {
  sph::Fluid& f = *parts_.fluid;
  coupling::ContactCoupling& c = *parts_.coupling;
  if (!f.forces_ready()) f.compute_forces();  // the first step, or after a restart (the same bits)
  const double t = f.time(), dt = f.dt();
  c.set_fluid_loads(f.plate_wall_loads(), dt);  // F_n; the first iterate 2 F_n - F_n-1
  if (parts_.plate) load_cables(t + dt);

  // The step's start, to come back to.
  if (!fluid_saved_) fluid_saved_ = std::make_unique<sph::Fluid::Snapshot>();
  std::vector<double> plate_saved, cables_saved, coupling_saved;
  {
    ScopedTimer timer(timers_, "exchange_save");
    f.snapshot(*fluid_saved_);
    if (parts_.structure_rank) {
      plate_saved = parts_.plate->save_state();
      for (const auto& cable : parts_.cables) cable->save_state(cables_saved);
    }
    coupling_saved = c.save_state();
  }
  auto put_back = [&] {
    ScopedTimer timer(timers_, "exchange_save");
    f.rollback(*fluid_saved_);
    collective_outcome(comm_, 0, parts_.structure_rank, [&] {
      const Eigen::VectorXd attempt =
          parts_.plate->displacement();  // the next attempt's first Newton iterate
      parts_.plate->restore_state(plate_saved);
      parts_.plate->set_next_predictor(attempt);
      std::size_t used = 0;
      for (auto& cable : parts_.cables)
        used += cable->restore_state(cables_saved.data() + used, cables_saved.size() - used);
    });
    c.restore_state(coupling_saved);  // leaves the surface loads of the next iterate
  };

  coupling::ExchangeIterate verdict;
  for (int k = 0;; ++k) {
    if (k > 0) put_back();
    f.predict(sph::Fluid::PlateDensity::kDeferred);
    {
      ScopedTimer timer(timers_, "coupling");
      c.step(t, dt, interface_of(f), parts_.corrections);
    }
    const sph::PlateOutline moved = c.plate_outline();  // the faces' motion over this step
    f.update_density(moved);
    const auto& cr = parts_.corrections;
    f.apply_corrections(cr.touched, cr.dx.data(), cr.dy.data(), cr.dvx.data(), cr.dvy.data(), cr.drho.data());
    f.finish();
    f.set_plate_outline(moved);
    f.compute_forces();  // at t_n+1 with the plate there: F_out, and the next step's rates
    {
      ScopedTimer timer(timers_, "coupling");
      verdict = c.converge_exchange(f.plate_wall_loads());
    }
    if (verdict.accepted) break;
  }
  const int evaluations = verdict.iteration + 1;
  ++exchange_.steps;
  exchange_.evaluations += evaluations;
  exchange_.most = std::max(exchange_.most, evaluations);
  if (!verdict.converged) {
    if (exchange_.unconverged == 0) {  // said once; the rest are counted
      std::ostringstream line;
      line.precision(9);
      line << "warning: the plate-water exchange did not converge in the step to t = " << t + dt
           << " s: residual " << verdict.residual << " after " << evaluations
           << " evaluations (coupling.implicit; kept, counted in summary.json: exchange)";
      log_->line(line.str());
    }
    ++exchange_.unconverged;
    const double r = verdict.residual;
    ++exchange_.decades[r < 1e-3 ? 0 : r < 1e-2 ? 1 : r < 0.1 ? 2 : 3];
    exchange_.worst_residual = std::max(exchange_.worst_residual, verdict.residual);
  }
  if (options_.trace_coupling) trace_coupled_step();
  return dt;
}

}  // namespace halfeti::app
