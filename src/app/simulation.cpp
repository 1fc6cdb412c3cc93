#include "halfeti/app/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "halfeti/core/error.hpp"
#include "halfeti/core/version.hpp"
#include "halfeti/excitation/excitation_scene.hpp"
#include "halfeti/io/probe_writer.hpp"

namespace halfeti::app {

class ProbeWriterHolder {
 public:
  ProbeWriterHolder(const std::string& path, const std::vector<std::string>& names, bool writer)
      : writer(path, names, writer) {}
  io::ProbeWriter writer;
};

namespace {

std::string directory_of(const std::string& file) {
  const auto p = file.find_last_of('/');
  return p == std::string::npos ? std::string(".") : file.substr(0, p);
}

double wall_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Parts build_parts(const scene::Scene& scene, MPI_Comm comm) {
  (void)comm;
  const scene::Node root = scene.root();
  Parts parts;
  parts.scene_dir = directory_of(scene.file);
  parts.gravity = root.real("gravity");
  parts.motion = excitation::make_ground_motion(root.section("excitation"), parts.scene_dir);
  return parts;
}

Simulation::Simulation(MPI_Comm comm, scene::Scene scene, RunOptions options)
    : comm_(comm), scene_(std::move(scene)), options_(std::move(options)) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
  const scene::Node root = scene_.root();
  out_dir_ = options_.out_dir.empty() ? "out/" + root.section("scene").string("name") : options_.out_dir;
  // Directory creation on rank 0, outcome shared, so a bad --out is one error on every rank.
  int ok = 1;
  std::string why;
  if (rank_ == 0) {
    try {
      io::make_directories(out_dir_);
      io::make_directories(out_dir_ + "/fields");
      io::make_directories(out_dir_ + "/checkpoints");
    } catch (const UserError& e) {
      ok = 0;
      why = e.what();
    }
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, comm_);
  if (!ok) throw UserError(rank_ == 0 ? why : "cannot create the output folder '" + out_dir_ + "'");

  parts_ = build_parts(scene_, comm_);
  probes_ = make_probes(root, parts_);
  std::vector<std::string> names;
  for (const auto& p : probes_) names.push_back(p.name);
  probe_out_ = std::make_unique<ProbeWriterHolder>(out_dir_ + "/probes.csv", names, rank_ == 0);
  log_ = std::make_unique<io::RunLog>(out_dir_ + "/log.txt", rank_ == 0, options_.echo);
  if (rank_ == 0) {
    std::ofstream resolved(out_dir_ + "/scene.resolved.yaml");
    resolved << "# resolved by " << "halfeti " << kVersion << " from " << scene_.file << "\n"
             << scene_.resolved_text();
  }
}

Simulation::~Simulation() = default;

void Simulation::sample_probes(double t) {
  std::vector<double> row;
  row.reserve(probes_.size());
  for (auto& p : probes_) row.push_back(p.sample(t));
  probe_out_->writer.write(t, row);
}

std::string Simulation::progress_line(double t, double dt, double wall) const {
  const double end = scene_.root().section("scene").real("end_time");
  const double eta = t > 0 ? wall * (end - t) / t : 0.0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "t = %.4f s (%5.1f%%)  step %lld  dt = %.3e s  wall %.1f s  eta %.1f s", t,
                100.0 * t / end, steps_, dt, wall, eta);
  return buf;
}

void Simulation::run() {
  const scene::Node root = scene_.root();
  const double end = root.section("scene").real("end_time");
  const scene::Node out = root.section("output");
  const double probe_dt = out.real("probe_interval");
  const double progress_dt = out.real("progress_interval") > 0 ? out.real("progress_interval") : end / 50.0;
  const double start = wall_now();

  log_->line(std::string("halfeti ") + kVersion);
  log_->line("scene " + scene_.file + " on " + std::to_string(size_) + " rank(s); output in " + out_dir_);
  log_->line("excitation: " + parts_.motion->describe());

  std::string status = "ok";
  try {
    // With no part that sets its own step, the clock advances by the probe interval.
    const double dt = probe_dt;
    double next_probe = 0.0, next_progress = progress_dt;
    {
      ScopedTimer timer(timers_, "probes");
      sample_probes(t_);
    }
    next_probe += probe_dt;
    while (t_ < end - 1e-12 * end) {
      const double step = std::min(dt, end - t_);
      t_ += step;
      ++steps_;
      if (t_ >= next_probe - 1e-9 * probe_dt) {
        ScopedTimer timer(timers_, "probes");
        sample_probes(t_);
        next_probe += probe_dt;
      }
      if (t_ >= next_progress) {
        log_->line(progress_line(t_, step, wall_now() - start));
        next_progress += progress_dt;
      }
    }
  } catch (const NumericalError&) {
    status = "numerical_failure";
    write_summary(status, wall_now() - start);
    throw;
  }
  log_->line(progress_line(t_, 0.0, wall_now() - start));
  write_summary(status, wall_now() - start);
  log_->line("done: " + std::to_string(steps_) + " steps in " + std::to_string(wall_now() - start) + " s");
}

void Simulation::write_summary(const std::string& status, double wall) {
  if (rank_ != 0) return;
  const scene::Node root = scene_.root();
  io::Json j = io::Json::object();
  j.set("halfeti", kVersion);
  j.set("scene", root.section("scene").string("name"));
  j.set("scene_file", scene_.file);
  j.set("ranks", size_);
  j.set("particles", 0);
  j.set("structure_dofs", 0);
  j.set("steps", steps_);
  j.set("simulated_time", t_);
  j.set("wall_time", wall);
  j.set("ns_per_particle_step", io::Json());
  io::Json timers = io::Json::object();
  for (const auto& [phase, seconds] : timers_.all()) timers.set(phase, seconds);
  j.set("timers", timers);
  j.set("max_density_variation", io::Json());
  j.set("mass_error", io::Json());
  io::Json events = io::Json::array();
  for (const auto& e : health_) {
    io::Json ev = io::Json::object();
    ev.set("time", e.time).set("step", e.step).set("kind", e.kind).set("fatal", e.fatal).set("message", e.message);
    events.push(ev);
  }
  j.set("health_events", events);
  j.set("exit_status", status);
  std::ofstream f(out_dir_ + "/summary.json");
  f << j.dump() << "\n";
}

}  // namespace halfeti::app
