// A run: builds the parts a scene names, advances them to the end time, and writes the outputs of DESIGN.md's
// contract (probes.csv, summary.json, log.txt, scene.resolved.yaml, fields/, checkpoints/).
#pragma once

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "halfeti/app/parts.hpp"
#include "halfeti/app/probes.hpp"
#include "halfeti/app/run_health.hpp"
#include "halfeti/core/health.hpp"
#include "halfeti/core/scene.hpp"
#include "halfeti/core/timers.hpp"
#include "halfeti/io/checkpoint.hpp"
#include "halfeti/io/fields.hpp"
#include "halfeti/io/probe_writer.hpp"
#include "halfeti/io/run_log.hpp"

namespace halfeti::app {

struct RunOptions {
  std::string out_dir;                  // empty: out/<scene.name>
  std::vector<std::string> petsc_args;  // passed to PETSc when the scene has a structure
  bool echo = true;                     // progress lines to stdout as well as log.txt
  std::string restart;                  // --restart: a checkpoint, or a run folder (its latest checkpoint)
  bool overwrite = false;               // --overwrite: clear another run's outputs from the folder first
  double max_wall = 0.0;                // --max-wall: stop (resumable) before this many wall seconds; 0: none
  double max_memory =
      0.0;  // --max-memory: refuse a scene estimated above this per rank [B]; 0: the machine's
  bool trace_coupling = false;  // --trace coupling: diagnostic lines per coupled step on stderr
  std::string command_line;     // for summary.json's provenance
};

// Reads what a resolved scene names without building the heavy parts (what `halfeti check` does beyond the
// schema): ground motion (its record file), part parameters with their cross-checks, and the probes, bound to
// `parts` (which must outlive them). Errors name the scene file and the key.
std::vector<ProbeColumn> build_parameters(const scene::Scene& scene, Parts& parts);

class Simulation {
 public:
  Simulation(MPI_Comm comm, scene::Scene scene, RunOptions options);
  ~Simulation();

  // Runs to the end time and returns 0, or stops at a step boundary on SIGTERM, SIGINT, SIGUSR1 or --max-wall
  // with a checkpoint and summary.json (status "stopped") and returns kExitStoppedResumable. On a numerical
  // failure it writes a checkpoint and summary.json ("numerical_failure") and rethrows; on a failed write,
  // summary.json ("io_failure") if it can; the caller turns the error into one line and an exit status.
  int run();

  const std::string& out_dir() const { return out_dir_; }

 private:
  void announce();
  double advance(double remaining);  // one step of every part; returns the step taken
  double advance_coupled();          // water and plate through contact
  double
  advance_coupled_implicit();  // the same, the plate-water exchange converged (simulation_exchange.cpp)
  static coupling::InterfaceParticles interface_of(
      const sph::Fluid& f);  // the owned particles, for the coupling
  void sample(double t);
  void prepare_structure();
  void show_plate_to_fluid();  // the coupling's current plate surface as the water's plate wall or barriers
  void step_structure(double t, double dt);
  void load_cables(double t);
  void open_field_series();          // the field series of the run's parts (simulation_outputs.cpp)
  void open_outputs(bool restored);  // probes.csv, probes.json, log.txt, scene.resolved.yaml
  void write_fields(double t);       // every series of the run's parts (simulation_fields.cpp)
  void write_fluid_fields(double t);
  void write_plate_fields(double t);
  void write_cable_fields(double t);
  void write_tank_outline();
  void trace_coupled_step()
      const;  // --trace coupling: the step's contact and plate-wall forces, the fastest particle
  // between_steps: false for the checkpoint at a failure inside a step (for inspection; a restart refuses it).
  void write_checkpoint(const std::string& label, bool between_steps = true);
  void restore(io::Checkpoint checkpoint);
  std::string run_steps(double end,
                        double start);  // the step loop; returns why it stopped early ("" at the end)
  std::string stop_reason(double wall, double step_wall);
  std::string output_failure() const;
  void check_outputs();
  void write_summary(const std::string& status, double wall, double loop_wall);
  std::string progress_line(double dt, double wall) const;
  HealthLog health_events() const;  // every part's, in step order
  void check_health();              // after a step: the run's own monitors, then every new warning printed
  void record_failure(const std::string& message);

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  scene::Scene scene_;
  RunOptions options_;
  std::string out_dir_;
  Parts parts_;
  std::vector<ProbeColumn> probes_;
  std::unique_ptr<io::ProbeWriter> probe_out_;
  std::unique_ptr<io::RunLog> log_;
  std::unique_ptr<io::FieldSeries> fluid_fields_, plate_fields_, cable_fields_, tank_fields_;
  PhaseTimers timers_;
  RunHealth health_;
  double t_ = 0.0;
  double step_end_ = 0.0;  // the time the step under way advances to (a failure's time)
  bool in_step_ =
      false;  // between a step's start and its end (a failure outside a step is the static start's)
  long long steps_ = 0, steps_at_start_ = 0, last_checkpoint_step_ = -1, initial_particles_ = 0;
  double initial_mass_ = 0.0, max_density_variation_ = 0.0;
  std::string restart_path_;  // the checkpoint continued from ("" for a fresh run)
  bool continuing_ = false;   // the restart writes into the folder of the run it continues
  std::string started_utc_;
  double run_start_ = 0.0, earlier_wall_ = 0.0, last_checkpoint_wall_ = 0.0, last_dt_ = 0.0;
  // CPU seconds of all ranks of the runs this one continues (NaN: continued from a checkpoint that did not record
  // them)
  double earlier_cpu_ = 0.0;
  // The converged exchange (coupling.plate_wall_exchange: implicit): the step's saved start and this run's counts.
  struct ExchangeCounts {
    long long steps = 0, evaluations = 0, unconverged = 0;
    int most = 0;                 // evaluations of the step that needed most
    double worst_residual = 0.0;  // of the steps kept unconverged
    long long decades[4] = {
        0, 0, 0, 0};  // steps kept with residual in [1e-4, 1e-3), [1e-3, 1e-2), [1e-2, 0.1), >= 0.1
  } exchange_;
  std::unique_ptr<sph::Fluid::Snapshot> fluid_saved_;
};

}  // namespace halfeti::app
