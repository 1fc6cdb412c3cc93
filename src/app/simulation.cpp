#include "halfeti/app/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "halfeti/app/restart.hpp"
#include "halfeti/app/run_control.hpp"
#include "halfeti/app/run_size.hpp"
#include "halfeti/core/collective.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/io/checkpoint.hpp"

namespace halfeti::app {

namespace {

std::string format(const char* fmt, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

// The structure solves on its own ranks (world rank 0 among them); its failure must stop every rank together (no
// rank may be left waiting in a collective call).
template <class Work>
void on_structure_rank(MPI_Comm comm, bool structure_rank, Work&& work) {
  collective_outcome(comm, 0, structure_rank, work);
}

}  // namespace

Simulation::Simulation(MPI_Comm comm, scene::Scene scene, RunOptions options)
    : comm_(comm), scene_(std::move(scene)), options_(std::move(options)) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
  const scene::Node root = scene_.root();
  out_dir_ = options_.out_dir.empty() ? "out/" + root.section("scene").string("name") : options_.out_dir;

  // A restart reads its checkpoint on every rank and refuses a scene that changes the physics.
  std::unique_ptr<io::Checkpoint> checkpoint;
  if (!options_.restart.empty()) checkpoint = read_restart(options_.restart, scene_, restart_path_);
  continuing_ = prepare_run_folder(comm_, out_dir_, checkpoint.get(), restart_path_, options_.overwrite);

  probes_ = build_parameters(scene_, parts_);
  estimate_size(scene_, parts_, size_, options_.max_memory);  // before anything large is allocated
  {
    ScopedTimer timer(timers_, "setup");
    build_parts(parts_, comm_, options_.trace_coupling);
  }
  if (parts_.fluid) initial_particles_ = parts_.fluid->global_count();  // the lattice's (before a restore)
  open_field_series();
  if (checkpoint) {
    ScopedTimer timer(timers_, "restart");
    restore(*checkpoint);
  }
  open_outputs(checkpoint != nullptr);
}

Simulation::~Simulation() = default;

void Simulation::prepare_structure() {
  if (!parts_.structure_setup) return;
  on_structure_rank(comm_, parts_.structure_rank, [&] {
    if (parts_.structure_setup->start_static) {
      // The equilibrium of the tank at rest: every ground motion is zero before t = 0, so solve at t = -1 s.
      const auto report = parts_.plate->solve_static(-1.0, 10);
      log_->line("structure: static equilibrium in " + std::to_string(report.newton_iterations) +
                 " Newton iterations");
    }
    parts_.plate->initialise_acceleration(0.0);
  });
  // The water and the coupling were given the plate's surface as built; the static start moved it (the cables'
  // pull and the plate's weight). Without this the first step took the built surface for the plate's place and
  // velocity: the interface added mass's spring pulled the surface back toward it and the water saw the faces move
  // by the static displacement in one step (docs/coupling.md section 22).
  if (parts_.coupling) {
    parts_.coupling->refresh_surface();
    show_plate_to_fluid();
  }
}

void Simulation::show_plate_to_fluid() {
  // The barrier: the plate's mid-line with the plate-wall ghosts (they stand for what the plate hides), its
  // outline in the paper's contact-only form.
  if (parts_.coupling->parameters().plate_wall)
    parts_.fluid->set_plate_outline(parts_.coupling->plate_outline());  // with its mid-line as the barrier
  else
    parts_.fluid->set_barriers(parts_.coupling->outline());
}

void Simulation::load_cables(double t) {
  // The tank frame's inertial load on the cables (their weight stays in the element), at the end of the step.
  const double ag = parts_.motion->acceleration(t);
  for (size_t i = 0; i < parts_.cables.size(); ++i)
    parts_.cables[i]->set_horizontal_load(cable::tank_frame_load(parts_.cable_setups[i].set, ag));
}

void Simulation::step_structure(double t, double dt) {
  if (!parts_.structure_setup) return;
  ScopedTimer timer(timers_, "structure");
  on_structure_rank(comm_, parts_.structure_rank, [&] {
    load_cables(t + dt);
    parts_.plate->step(t, dt);
  });
}

coupling::InterfaceParticles Simulation::interface_of(const sph::Fluid& f) {
  const auto& grad = f.renormalised_density_gradient();
  return {f.owned_count(), f.gid().data(), f.x().data(),    f.y().data(),
          f.vx().data(),   f.vy().data(),  f.mass().data(), grad.empty() ? nullptr : grad.data()};
}

// One coupled step (DESIGN.md "One time step"): fluid forces and prediction, the interface gathered to the plate's
// rank, the plate and the invaders solved together (eq. 21), the corrections handed back (eqs. 4, 22-24), then
// the fluid finishes its step (health, migration) and the plate's new outline bars pairs across it.
double Simulation::advance_coupled() {
  if (parts_.coupling->parameters().implicit_exchange()) return advance_coupled_implicit();
  sph::Fluid& f = *parts_.fluid;
  f.compute_forces();
  const double t = f.time(), dt = f.dt();
  const bool plate_wall = parts_.coupling->parameters().plate_wall;
  if (plate_wall)
    parts_.coupling->set_fluid_loads(f.plate_wall_loads(), dt);  // the water's wall force on the plate
  f.predict();
  if (parts_.plate) load_cables(t + dt);
  {
    ScopedTimer timer(timers_, "coupling");
    parts_.coupling->step(t, dt, interface_of(f), parts_.corrections);
  }
  const auto& c = parts_.corrections;
  f.apply_corrections(c.touched, c.dx.data(), c.dy.data(), c.dvx.data(), c.dvy.data(), c.drho.data());
  f.finish();
  show_plate_to_fluid();
  if (options_.trace_coupling) trace_coupled_step();
  return dt;
}

double Simulation::advance(double remaining) {
  if (parts_.coupling) return advance_coupled();
  if (parts_.fluid) {
    parts_.fluid->step();
    return parts_.fluid->dt();
  }
  if (parts_.structure_setup) {
    const double dt = std::min(parts_.structure_setup->time_step, remaining);
    step_end_ = t_ + dt;
    step_structure(t_, dt);
    return dt;
  }
  // No parts: the clock advances by the probe interval (at most a million steps over the run).
  const double end = scene_.root().section("scene").real("end_time");
  return std::min(std::max(scene_.root().section("output").real("probe_interval"), 1e-6 * end), remaining);
}

void Simulation::sample(double t) {
  ScopedTimer timer(timers_, "probes");
  std::vector<double> row;
  row.reserve(probes_.size());
  for (auto& p : probes_) row.push_back(p.sample(t));
  probe_out_->write(t, row);
  if (parts_.fluid)
    max_density_variation_ = std::max(max_density_variation_, parts_.fluid->max_density_variation());
}

// Whether every rank should stop at this step's end: a signal reached one of them, or (rank 0's clock) the next
// step and a checkpoint would not fit in --max-wall. One reduction per step; the reason on every rank.
std::string Simulation::stop_reason(double wall, double step_wall) {
  int why[3] = {requested_stop_signal(), 0, 0};
  if (rank_ == 0 && options_.max_wall > 0.0 &&
      wall + 2.0 * step_wall + 2.0 * last_checkpoint_wall_ >= options_.max_wall)
    why[1] = 1;
  if (rank_ == 0 && !output_failure().empty()) why[2] = 1;
  MPI_Allreduce(MPI_IN_PLACE, why, 3, MPI_INT, MPI_MAX, comm_);
  if (why[2] != 0) check_outputs();
  if (why[0] != 0) return signal_name(why[0]);
  if (why[1] != 0) return "the wall-time limit (--max-wall " + format("%g", options_.max_wall) + " s)";
  return "";
}

// rank 0's first failed write of the log or the probes ("" when none).
std::string Simulation::output_failure() const {
  if (probe_out_ && !probe_out_->failure().empty()) return probe_out_->failure();
  if (log_ && !log_->failure().empty()) return log_->failure();
  return "";
}

// Collective: raises the failed write of rank 0's log or probes as an IoError on every rank.
void Simulation::check_outputs() {
  collective_outcome(comm_, 0, rank_ == 0, [&] {
    if (const std::string f = output_failure(); !f.empty()) throw IoError(f);
  });
}

// The steps from t_ to `end` with the outputs on their schedules; returns why the run stopped before the end (a
// signal, the wall-time limit), "" when it got there.
std::string Simulation::run_steps(double end, double start) {
  const scene::Node out = scene_.root().section("output");
  const double probe_dt = out.real("probe_interval");
  const double field_dt = out.real("field_interval");
  const double checkpoint_dt = out.real("checkpoint_interval");
  const double progress_dt = out.real("progress_interval") > 0 ? out.real("progress_interval") : end / 50.0;
  // A step ends within round-off of a scheduled time counts as reaching it. The schedules are the sequences
  // dt, dt + dt, ... (each the sum of the one before and dt), resumed after t on a restart.
  const double tol = 1e-9 * end;
  const auto first_after = [&](double interval) { return next_in_schedule(interval, interval, t_, tol); };
  double next_probe = first_after(probe_dt), next_field = first_after(field_dt),
         next_checkpoint = first_after(checkpoint_dt), next_progress = first_after(progress_dt);
  if (restart_path_.empty()) {
    prepare_structure();
    sample(t_);
    if (field_dt > 0) write_fields(t_);
  }
  double dt = 0.0, step_wall = 0.0;
  while (t_ < end - tol) {
    const double step_start = wall_seconds();
    in_step_ = true;
    dt = advance(end - t_);
    t_ = parts_.fluid ? parts_.fluid->time() : t_ + dt;
    ++steps_;
    check_health();
    in_step_ = false;
    if (t_ >= next_probe - tol) {
      sample(t_);
      next_probe = next_in_schedule(next_probe, probe_dt, t_, tol);
    }
    if (field_dt > 0 && t_ >= next_field - tol) {
      write_fields(t_);
      next_field = next_in_schedule(next_field, field_dt, t_, tol);
    }
    if (checkpoint_dt > 0 && t_ >= next_checkpoint - tol) {
      write_checkpoint("scheduled");
      next_checkpoint = next_in_schedule(next_checkpoint, checkpoint_dt, t_, tol);
    }
    if (t_ >= next_progress - tol) {
      log_->line(progress_line(dt, wall_seconds() - start));
      next_progress = next_in_schedule(next_progress, progress_dt, t_, tol);
    }
    step_wall = std::max(step_wall, wall_seconds() - step_start);
    if (t_ < end - tol)  // the same on every rank: the check is collective
      if (std::string why = stop_reason(wall_seconds() - start, step_wall); !why.empty()) return why;
  }
  last_dt_ = dt;
  return "";
}

int Simulation::run() {
  const double end = scene_.root().section("scene").real("end_time");
  const double start = wall_seconds();
  run_start_ = start;
  started_utc_ = utc_now();
  announce();
  if (!restart_path_.empty())
    log_->line("restart: from " + restart_path_ + " at t = " + format("%.9g", t_) + " s, step " +
               std::to_string(steps_));
  else if (parts_.fluid)
    initial_mass_ = parts_.fluid->total_mass();
  write_summary("running", 0.0, 0.0);
  install_stop_handlers();

  const double loop_start = wall_seconds();
  std::string stopped;
  try {
    stopped = run_steps(end, start);
  } catch (const NumericalError& e) {
    // Errors are raised on every rank together (the monitors reduce first), so the checkpoint is collective.
    record_failure(e.what());
    log_->line(std::string("stopped: ") + e.what());
    try {
      write_checkpoint("at the failure", false);
    } catch (const IoError& io) {
      log_->line(std::string("no checkpoint at the failure: ") + io.what());
    }
    write_summary("numerical_failure", wall_seconds() - start, wall_seconds() - loop_start);
    throw;
  } catch (const IoError& e) {
    // An output that cannot be written (a full disk): said once, and in summary.json if that can still be written.
    try {
      log_->line(std::string("stopped: ") + e.what());
      write_summary("io_failure", wall_seconds() - start, wall_seconds() - loop_start);
    } catch (const IoError&) {
    }
    throw;
  }
  check_outputs();
  const double loop_wall = wall_seconds() - loop_start;
  if (!stopped.empty()) {
    write_checkpoint("at the stop");
    log_->line("stopped: " + stopped + " at t = " + format("%.9g", t_) + " s, step " +
               std::to_string(steps_) + "; continue with: halfeti run " + scene_.file + " --restart " +
               out_dir_ + " --out " + out_dir_);
    write_summary("stopped", wall_seconds() - start, loop_wall);
    return kExitStoppedResumable;
  }
  if (last_checkpoint_step_ != steps_)
    write_checkpoint("final");  // unless the schedule just wrote this step's
  log_->line(progress_line(last_dt_, wall_seconds() - start));
  const HealthLog events = health_events();
  const HealthTally health = tally(events);
  write_summary(health.warnings > 0 ? "ok_with_warnings" : "ok", wall_seconds() - start, loop_wall);
  log_->line("done: " + std::to_string(steps_) + " steps, " + format("%.2f", wall_seconds() - start) +
             " s wall, " + warnings_line(health) + (health.warnings > 0 ? " (summary.json: health)" : ""));
  check_outputs();
  return 0;
}

HealthLog Simulation::health_events() const {
  return health_.merged(parts_.fluid ? parts_.fluid->health_events() : HealthLog{});
}

void Simulation::check_health() {
  if (!parts_.cable_setups.empty()) health_.check_cables(comm_, parts_, t_, steps_);
  health_.announce(*log_, parts_.fluid ? parts_.fluid->health_events() : HealthLog{});
}

void Simulation::record_failure(const std::string& message) {
  // The failure's time and step are those of the step that failed (the fluid's clock has advanced to its end; the
  // plate alone was going to step_end_); a failure before the first step is the static start's, at t = 0.
  if (in_step_) {
    t_ = parts_.fluid ? parts_.fluid->time() : step_end_;
    ++steps_;
    in_step_ = false;
  }
  health_.record_failure(t_, steps_, message, parts_.fluid ? parts_.fluid->health_events() : HealthLog{});
}

}  // namespace halfeti::app
