// What a run tells: its start-up lines (log.txt), the progress line, the coupling trace (--trace coupling), and
// summary.json, the run's status, provenance, size, cost, timers, mass balance and health, written by rank 0
// (DESIGN.md's output contract; README "Outputs").
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "halfeti/app/simulation.hpp"
#include "halfeti/core/collective.hpp"
#include "halfeti/core/version.hpp"
#include "halfeti/io/json.hpp"

namespace halfeti::app {

void Simulation::announce() {
  log_->line(std::string("halfeti ") + kVersion + ": scene " + scene_.file + " on " + std::to_string(size_) +
             " rank(s); output in " + out_dir_);
  log_->line("excitation: " + parts_.motion->describe());
  if (const auto* f = parts_.fluid.get()) {
    std::ostringstream os;
    os << "fluid: " << f->global_count() << " particles, dx = " << f->params().spacing
       << " m, h = " << f->smoothing_length() << " m, c0 = " << f->sound_speed() << " m/s, scheme "
       << (f->params().scheme == sph::Scheme::kDeltaSph ? "delta-SPH" : "standard SPH");
    log_->line(os.str());
    if (f->params().cfl > 1.0) {
      std::ostringstream w;
      w << "fluid.cfl = " << f->params().cfl
        << " is past the explicit step's usual stability limit (1): expect the run to fail";
      log_->warning(w.str());
    }
  }
  if (parts_.plate) log_->line(parts_.plate->summary());
  for (const auto& c : parts_.cable_setups) {
    log_->line(cable::describe_per_depth(c.set, c.name));
    std::ostringstream os;
    os << "cable " << c.name << ": anchor [" << c.anchor.x() << ", " << c.anchor.y() << "] to " << c.node
       << ", unstretched length " << c.unstretched_length << " m";
    if (c.initial_stress > 0) os << " (from the initial stress " << c.initial_stress << " Pa)";
    log_->line(os.str());
  }
  if (!parts_.fluid && !parts_.structure_setup)
    log_->line("no parts: the clock advances by the probe interval");
}

std::string Simulation::progress_line(double dt, double wall) const {
  const double end = scene_.root().section("scene").real("end_time");
  const double eta = t_ > 0 ? wall * std::max(0.0, end - t_) / t_ : 0.0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "t = %.4f s (%5.1f%%)  step %lld  dt = %.3e s  wall %.1f s  eta %.1f s", t_,
                std::min(100.0, 100.0 * t_ / end), steps_, dt, wall, eta);
  return buf;
}

// One line per coupled step on stderr (rank 0: the contact and plate-wall forces on the plate's side; every rank:
// its fastest particle), for the noise figures of docs/coupling.md.
void Simulation::trace_coupled_step() const {
  const sph::Fluid& f = *parts_.fluid;
  const auto& r = parts_.coupling->last_step();
  double best = 0, bx = 0, by = 0;
  for (std::size_t i = 0; i < f.owned_count(); ++i) {
    const double u = std::hypot(f.vx()[i], f.vy()[i]);
    if (u > best) {
      best = u;
      bx = f.x()[i];
      by = f.y()[i];
    }
  }
  std::fprintf(stderr, "coupling_trace_fastest t=%.6f u=%.3g at (%.5f, %.5f)\n", f.time(), best, bx, by);
  if (rank_ == 0)
    std::fprintf(
        stderr,
        "coupling_trace t=%.6f inv=%d rel=%d L=%.3g umax=%.3g Fc=(%.4g,%.4g) maxF=%.3g Fw=(%.4g,%.4g)\n",
        f.time(), r.invaders, r.released, r.layer, r.u_max, r.force_x, r.force_y, r.max_force,
        parts_.coupling->fluid_load_x(), parts_.coupling->fluid_load_y());
}

void Simulation::write_summary(const std::string& status, double wall, double loop_wall) {
  // Every rank takes part in the collective reads below; rank 0 writes.
  const long long particles = parts_.fluid ? parts_.fluid->global_count() : 0;
  const double mass = parts_.fluid ? parts_.fluid->total_mass() : 0.0;
  PhaseTimers timers = timers_;
  if (parts_.fluid) timers.merge(parts_.fluid->timers());
  if (parts_.coupling) {
    PhaseTimers contact;
    const PhaseTimers coupling_timers = parts_.coupling->timers();  // returned by value: keep it alive
    for (const auto& [phase, seconds] : coupling_timers.all()) contact.add("contact_" + phase, seconds);
    timers.merge(contact);
  }
  if (parts_.plate) {
    PhaseTimers plate;
    for (const auto& [phase, seconds] : parts_.plate->timers().all()) plate.add(phase, seconds);
    timers.merge(plate);
  }
  const long long dofs = parts_.plate ? parts_.plate->dof_count() : 0;  // written by rank 0, a structure rank
  // Cost: CPU seconds (user + system) summed over the ranks, and the peak resident memory of the busiest rank and
  // of all ranks together (getrusage: this process since it started).
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  const double cpu_here = cpu_seconds(usage);
  const double rss_here = 1024.0 * static_cast<double>(usage.ru_maxrss);  // Linux reports kB
  double sums[2] = {cpu_here, rss_here}, rss_max = rss_here;
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm_);
  MPI_Allreduce(MPI_IN_PLACE, &rss_max, 1, MPI_DOUBLE, MPI_MAX, comm_);
  // Per rank: the water's messages and bytes sent (halo and migration), seconds waiting for them, its own work
  // (the fluid's phases that no other rank waits in: pairs, forces, density gradient, integration) and its peak
  // memory, gathered on rank 0.
  constexpr int kPerRank = 5;
  double mine[kPerRank] = {0, 0, 0, 0, rss_here};
  if (parts_.fluid) {
    const auto& tr = parts_.fluid->traffic();
    const auto& ft = parts_.fluid->timers();
    mine[0] = static_cast<double>(tr.messages);
    mine[1] = static_cast<double>(tr.bytes);
    mine[2] = tr.wait_seconds;
    mine[3] = ft.seconds("neighbours") + ft.seconds("forces") + ft.seconds("density_gradient") +
              ft.seconds("integrate");
  }
  std::vector<double> per_rank(rank_ == 0 ? kPerRank * size_ : 0);
  MPI_Gather(mine, kPerRank, MPI_DOUBLE, per_rank.data(), kPerRank, MPI_DOUBLE, 0, comm_);
  collective_outcome(comm_, 0, rank_ == 0, [&] {  // rank 0 writes; a failed write stops every rank
    const scene::Node root = scene_.root();
    io::Json j = io::Json::object();
    j.set("halfeti", kVersion);
    j.set("exit_status", status);
    j.set("scene", root.section("scene").string("name"));
    j.set("scene_file", scene_.file);
    if (root.section("scene").has("description"))
      j.set("description", root.section("scene").string("description"));
    // Provenance: what ran, where, when and from what.
    io::Json prov = io::Json::object();
    prov.set("version", kVersion).set("commit", kGitCommit).set("command_line", options_.command_line);
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    prov.set("host", host).set("started", started_utc_);
    const char* job = std::getenv("SLURM_JOB_ID");
    prov.set("slurm_job_id", job ? io::Json(std::string(job)) : io::Json());
    prov.set("restarted_from", restart_path_.empty() ? io::Json() : io::Json(restart_path_));
    j.set("provenance", prov);
    j.set("ranks", size_);
    j.set("particles", particles);  // now (water over the open top leaves the run)
    j.set("initial_particles", initial_particles_);
    j.set("structure_dofs", dofs);
    j.set("cables", static_cast<int>(parts_.cable_setups.size()));
    j.set("steps", steps_);
    const long long steps_here = steps_ - steps_at_start_;
    j.set("steps_this_run", steps_here);  // a restarted run's since its restart, as its timers and cost
    j.set("simulated_time", t_);
    j.set("wall_time", wall);  // this run's (a restarted run's: since its restart)
    j.set("loop_wall_time", loop_wall);
    j.set("earlier_wall_time", earlier_wall_);  // of the runs it continues
    j.set("ns_per_particle_step",
          particles > 0 && steps_here > 0
              ? io::Json(1e9 * loop_wall / (static_cast<double>(particles) * steps_here))
              : io::Json());
    io::Json cost = io::Json::object();
    cost.set("cpu_seconds", sums[0]).set("cpu_seconds_per_rank", sums[0] / size_);
    cost.set("peak_memory_bytes_busiest_rank", rss_max).set("peak_memory_bytes_all_ranks", sums[1]);
    // The runs a restarted run continues: their CPU seconds (null when its checkpoint did not record them).
    cost.set("earlier_cpu_seconds", std::isnan(earlier_cpu_) ? io::Json() : io::Json(earlier_cpu_));
    j.set("cost", cost);  // this run's (a restarted run's: since its restart)
    io::Json tj = io::Json::object();
    for (const auto& [phase, seconds] : timers.all()) tj.set(phase, seconds);
    j.set("timers", tj);
    if (parts_.fluid) {  // this run's (a restarted run's: since its restart)
      io::Json comm = io::Json::object();
      const double steps_d = std::max(1.0, static_cast<double>(steps_here));
      io::Json msgs = io::Json::array(), bytes = io::Json::array(), wait = io::Json::array(),
               work = io::Json::array(), memory = io::Json::array();
      double work_max = 0.0, work_sum = 0.0;
      for (int r = 0; r < size_; ++r) {
        const double* v = &per_rank[static_cast<std::size_t>(kPerRank * r)];
        msgs.push(v[0] / steps_d);
        bytes.push(v[1] / steps_d);
        wait.push(v[2]);
        work.push(v[3]);
        memory.push(v[4]);
        work_max = std::max(work_max, v[3]);
        work_sum += v[3];
      }
      comm.set("messages_sent_per_step", msgs)
          .set("bytes_sent_per_step", bytes)
          .set("mpi_wait_seconds", wait);
      comm.set("compute_seconds", work).set("peak_memory_bytes", memory);
      comm.set("load_imbalance", work_sum > 0.0 ? io::Json(work_max * size_ / work_sum) : io::Json());
      j.set("ranks_detail", comm);
    }
    if (parts_.coupling &&
        parts_.coupling->parameters().implicit_exchange()) {  // this run's (since a restart)
      io::Json ex = io::Json::object();
      const auto& e = exchange_;
      ex.set("steps", e.steps).set("evaluations", e.evaluations);
      ex.set("evaluations_per_step",
             e.steps > 0 ? io::Json(double(e.evaluations) / double(e.steps)) : io::Json());
      ex.set("most_in_a_step", e.most).set("unconverged_steps", e.unconverged);
      ex.set("worst_unconverged_residual", e.unconverged > 0 ? io::Json(e.worst_residual) : io::Json());
      // The steps kept unconverged by their residual: below 1e-3, 1e-3 to 1e-2, 1e-2 to 0.1, 0.1 and above (a
      // tolerance below 1e-4 counts its near misses in the first).
      io::Json decades = io::Json::array();
      for (long long n : e.decades) decades.push(n);
      ex.set("unconverged_by_residual", decades);
      j.set("exchange", ex);
    }
    j.set("max_density_variation", parts_.fluid ? io::Json(max_density_variation_) : io::Json());
    // Water thrown over the tank's open top leaves the run (a "spilled" health event); the error counts it in.
    const double spilled = parts_.fluid ? parts_.fluid->spilled_mass() : 0.0;
    j.set("mass_error", parts_.fluid && initial_mass_ > 0
                            ? io::Json((mass + spilled - initial_mass_) / initial_mass_)
                            : io::Json());
    j.set("spilled_mass", parts_.fluid ? io::Json(spilled) : io::Json());
    // Health: each kind's episodes, the first (its message) and the worst value with where and when; the list.
    const HealthLog log = health_events();
    const HealthTally health = tally(log);
    const auto number = [](double v) { return std::isfinite(v) ? io::Json(v) : io::Json(); };
    io::Json kinds = io::Json::object();
    for (const auto& [kind, k] : health.kinds) {
      io::Json kj = io::Json::object();
      kj.set("episodes", k.episodes).set("fatal", k.fatal);
      kj.set("first_time", k.first->time)
          .set("first_step", k.first->step)
          .set("first_message", k.first->message);
      kj.set("worst", number(k.worst->worst))
          .set("worst_episode", k.worst->message)
          .set("worst_time", number(k.worst->worst_time));
      kj.set("worst_step", std::isfinite(k.worst->worst_time) ? io::Json(k.worst->worst_step) : io::Json());
      io::Json place = io::Json::array();
      place.push(number(k.worst->worst_x)).push(number(k.worst->worst_y));
      kj.set("worst_at", std::isfinite(k.worst->worst_x) ? place : io::Json());
      kinds.set(kind, kj);
    }
    io::Json hj = io::Json::object();
    hj.set("warnings", health.warnings).set("summary", warnings_line(health)).set("by_kind", kinds);
    j.set("health", hj);
    io::Json events = io::Json::array();
    for (const auto& e : log) {
      io::Json ev = io::Json::object();
      ev.set("time", e.time)
          .set("step", e.step)
          .set("kind", e.kind)
          .set("fatal", e.fatal)
          .set("message", e.message);
      ev.set("worst", number(e.worst));
      events.push(ev);
    }
    j.set("health_events", events);
    io::write_file_atomically(out_dir_ + "/summary.json", j.dump() + "\n");
  });
}

}  // namespace halfeti::app
