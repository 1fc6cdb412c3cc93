// A run: builds the parts a scene names, advances them to the end time, and writes the outputs of DESIGN.md's
// contract (probes.csv, summary.json, log.txt, scene.resolved.yaml, fields/, checkpoints/).
#pragma once

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "halfeti/app/parts.hpp"
#include "halfeti/app/probes.hpp"
#include "halfeti/core/health.hpp"
#include "halfeti/core/scene.hpp"
#include "halfeti/core/timers.hpp"
#include "halfeti/io/json.hpp"
#include "halfeti/io/run_log.hpp"

namespace halfeti::app {

struct RunOptions {
  std::string out_dir;                  // empty: out/<scene.name>
  std::string restart;                  // checkpoint to start from (empty: from the scene's initial state)
  std::vector<std::string> petsc_args;  // passed to PETSc when the scene has a structure
  bool echo = true;                     // progress lines to stdout as well as log.txt
};

// Builds the parts and probes of a resolved scene without running it (what `halfeti check` does beyond the
// schema): reads the files the scene names and cross-checks keys that depend on each other.
Parts build_parts(const scene::Scene& scene, MPI_Comm comm);

class Simulation {
 public:
  Simulation(MPI_Comm comm, scene::Scene scene, RunOptions options);
  ~Simulation();

  // Runs to the end time. On a numerical failure it writes summary.json (status "numerical_failure") and
  // rethrows; the caller turns the error into one line and an exit status.
  void run();

  const std::string& out_dir() const { return out_dir_; }

 private:
  void sample_probes(double t);
  void write_summary(const std::string& status, double wall);
  std::string progress_line(double t, double dt, double wall) const;

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  scene::Scene scene_;
  RunOptions options_;
  std::string out_dir_;
  Parts parts_;
  std::vector<ProbeColumn> probes_;
  std::unique_ptr<class ProbeWriterHolder> probe_out_;
  std::unique_ptr<io::RunLog> log_;
  PhaseTimers timers_;
  HealthLog health_;
  double t_ = 0.0;
  long long steps_ = 0;
};

}  // namespace halfeti::app
