// The run's whole state in a checkpoint and back (issue #16): each part saves and restores its own; this file
// puts them in the checkpoint's blocks and texts, and the run's own clock and accumulators beside them.
#include <cerrno>
#include <cstring>
#include <limits>

#include "halfeti/app/restart.hpp"
#include "halfeti/app/simulation.hpp"
#include "halfeti/core/collective.hpp"
#include "halfeti/core/error.hpp"

namespace halfeti::app {

void Simulation::write_checkpoint(const std::string& label, bool between_steps) {
  ScopedTimer timer(timers_, "checkpoint");
  const double started = wall_seconds();
  // The CPU seconds of all ranks so far, these processes' and the runs' they continue (collective: every rank
  // writes the checkpoint).
  double cpu = process_cpu_seconds();
  MPI_Allreduce(MPI_IN_PLACE, &cpu, 1, MPI_DOUBLE, MPI_SUM, comm_);
  io::Checkpoint c;
  c.time = t_;
  c.steps = steps_;
  c.ranks = size_;
  c.blocks["run"] = {t_,
                     static_cast<double>(steps_),
                     initial_mass_,
                     max_density_variation_,
                     earlier_wall_ + (run_start_ > 0.0 ? started - run_start_ : 0.0),
                     earlier_cpu_ + cpu};
  c.texts["scene"] = scene_.resolved_text();
  // A failure inside a step leaves a state for inspection, not one a step can start from.
  c.texts["written"] = between_steps ? "between steps" : "at a failure inside a step";
  if (parts_.fluid) {
    sph::Fluid::State st = parts_.fluid->state();
    c.particles = std::move(st.particles);
    c.blocks["fluid"] = {st.time, static_cast<double>(st.step), st.spilled_mass, parts_.fluid->sound_speed()};
    c.texts["health_log"] = encode_health_log(st.events);
    c.texts["active_warnings"] = encode_lines(st.active_warnings);
  }
  if (parts_.structure_setup) {
    std::vector<double> plate, cables;
    if (parts_.structure_rank) {  // collective over the structure's ranks; rank 0 (one of them) writes
      plate = parts_.plate->save_state();
      for (const auto& cable : parts_.cables) cable->save_state(cables);
    }
    c.blocks["plate"] = std::move(plate);
    c.blocks["cables"] = std::move(cables);
  }
  if (parts_.coupling) c.blocks["coupling"] = parts_.coupling->save_state();
  c.texts["run_health"] = health_.save_state();
  const std::string dir = out_dir_ + "/checkpoints", path = dir + "/" + io::checkpoint_file_name(steps_);
  io::write_checkpoint(comm_, path, c);
  // The newest output.checkpoint_keep checkpoints stay (0: all).
  const int keep = static_cast<int>(scene_.root().section("output").integer("checkpoint_keep"));
  collective_outcome(comm_, 0, rank_ == 0, [&] {
    const auto all = io::list_checkpoints(dir);
    for (std::size_t k = 0; keep > 0 && k + static_cast<std::size_t>(keep) < all.size(); ++k)
      if (std::remove(all[k].c_str()) != 0)
        HALFETI_IO_ERROR("cannot remove the old checkpoint '" << all[k] << "': " << std::strerror(errno));
  });
  last_checkpoint_wall_ = wall_seconds() - started;
  last_checkpoint_step_ = steps_;
  log_->line("checkpoint (" + label + "): " + path);
}

// The parts' state from a checkpoint (the parts are built; each part checks that the state fits it).
void Simulation::restore(io::Checkpoint c) {
  const auto block = [&](const char* name) -> const std::vector<double>& {
    const auto it = c.blocks.find(name);
    if (it == c.blocks.end())
      HALFETI_USER_ERROR("restart: '" << restart_path_ << "' holds no " << name << " state");
    return it->second;
  };
  const auto text = [&](const char* name) {
    const auto it = c.texts.find(name);
    return it == c.texts.end() ? std::string() : it->second;
  };
  if (text("written") != "between steps")
    HALFETI_USER_ERROR("restart: '" << restart_path_ << "' was written " << text("written")
                                    << " (for inspection); continue from an earlier checkpoint");
  const auto& run = block("run");
  // Five entries: a checkpoint written before the CPU seconds were recorded (they stay unknown).
  if (run.size() != 5 && run.size() != 6)
    HALFETI_USER_ERROR("restart: the run state of '" << restart_path_ << "' is malformed");
  t_ = run[0];
  steps_ = static_cast<long long>(run[1]);
  initial_mass_ = run[2];
  max_density_variation_ = run[3];
  earlier_wall_ = run[4];
  earlier_cpu_ = run.size() == 6 ? run[5] : std::numeric_limits<double>::quiet_NaN();
  steps_at_start_ = steps_;
  if (parts_.fluid) {
    const auto& f = block("fluid");
    if (f.size() != 4)
      HALFETI_USER_ERROR("restart: the fluid state of '" << restart_path_ << "' is malformed");
    // The sound speed may be sized from the peak ground acceleration up to end_time (eq. 10): a longer run must
    // not change it.
    if (f[3] != parts_.fluid->sound_speed())
      HALFETI_USER_ERROR("restart: the sound speed is " << parts_.fluid->sound_speed()
                                                        << " m/s, the checkpoint's " << f[3]
                                                        << " m/s (sized from the excitation up to end_time: "
                                                           "set fluid.sound_speed to continue)");
    sph::Fluid::State st;
    st.particles = std::move(c.particles);
    st.time = f[0];
    st.step = static_cast<long>(f[1]);
    st.spilled_mass = f[2];
    st.events = decode_health_log(text("health_log"));
    st.active_warnings = decode_lines(text("active_warnings"));
    parts_.fluid->restore(std::move(st));
  }
  const std::string run_health = text("run_health");
  if (run_health.empty()) HALFETI_USER_ERROR("restart: '" << restart_path_ << "' holds no run health state");
  health_.restore_state(run_health, parts_.fluid ? parts_.fluid->health_events() : HealthLog{});
  if (parts_.structure_setup) {
    collective_outcome(comm_, 0, parts_.structure_rank, [&] {
      parts_.plate->restore_state(block("plate"));  // before the cables: its pattern pass evaluates them
      const auto& cables = block("cables");
      std::size_t used = 0;
      for (auto& cable : parts_.cables)
        used += cable->restore_state(cables.data() + used, cables.size() - used);
      if (used != cables.size())
        HALFETI_USER_ERROR("restart: '" << restart_path_
                                        << "' holds the state of more cables than the scene has");
    });
  }
  if (parts_.coupling) {
    parts_.coupling->restore_state(block("coupling"));
    show_plate_to_fluid();
  }
}

}  // namespace halfeti::app
