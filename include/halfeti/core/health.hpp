// Health events: what a monitor saw (DESIGN.md, "Health monitors"). Warnings are recorded in summary.json; a
// fatal event stops the run (after a checkpoint) with its message as the one line on stderr.
//
// Contract: a monitor decides collectively (a reduction over its communicator), so a fatal event is raised on every
// rank together and the run can end cleanly without MPI_Abort.
#pragma once

#include <string>
#include <vector>

namespace halfeti {

struct HealthEvent {
  double time = 0.0;
  long long step = 0;
  std::string kind;     // "density_variation", "particle_outside", "nan", "inverted_element", ...
  std::string message;  // time, step, place, cause and a hint, in one line
  bool fatal = false;
};

using HealthLog = std::vector<HealthEvent>;

}  // namespace halfeti
