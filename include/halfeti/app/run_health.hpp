// The run's health beyond the fluid's own monitors (DESIGN.md "Health monitors"): the cables going slack and
// snapping taut again, a failure raised by a part that keeps no log (the plate's Newton, the contact), and every
// warning announced on stderr and in log.txt as it starts.
#pragma once

#include <mpi.h>

#include <map>
#include <string>
#include <vector>

#include "halfeti/app/parts.hpp"
#include "halfeti/core/health.hpp"
#include "halfeti/io/run_log.hpp"

namespace halfeti::app {

class RunHealth {
 public:
  // The first kPrinted episodes of a kind are printed; later ones are only counted (summary.json).
  static constexpr int kPrinted = 3;

  // Collective over comm: each cable's state after the step (from rank 0, a structure rank). A cable going slack
  // opens a "cable_slack" episode (worst: how far the chord fell short of the unstretched length [m]); taut again,
  // it closes and a "cable_snap" episode opens (worst: the largest stress of one cable [Pa] until it next goes
  // slack: the snap load).
  void check_cables(MPI_Comm comm, const Parts& parts, double t, long long step);

  // A fatal error of a part: recorded unless the fluid's log already holds this step's fatal event.
  void record_failure(double t, long long step, const std::string& message, const HealthLog& fluid);

  // Prints the events of `fluid` and of this log that are new since the last call (rank 0's log writes).
  void announce(io::RunLog& log, const HealthLog& fluid);

  // This log and the fluid's, in time order (the fluid's first within a step).
  HealthLog merged(const HealthLog& fluid) const;

  // Restart: this log and the cables' states as text, and back (the announcements restart after what was saved).
  std::string save_state() const;
  void restore_state(const std::string& text, const HealthLog& fluid);

 private:
  enum class Cable { kUnknown = 0, kTaut = 1, kSlack = 2, kSnapped = 3 };  // kSnapped: taut after being slack
  HealthLog events_;
  std::vector<Cable> cables_;
  std::vector<long> open_;  // per cable: index of its open episode in events_ (-1: none)
  std::size_t announced_fluid_ = 0, announced_own_ = 0;
  std::map<std::string, int> printed_;
};

}  // namespace halfeti::app
