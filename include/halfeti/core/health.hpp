// Health events: what a monitor saw (DESIGN.md, "Health monitors"). A warning is printed when it starts (stderr and
// log.txt), tallied by kind in summary.json with its worst value and where that was, and the run's status says it
// ended with warnings; a fatal event stops the run (after a checkpoint) with its message as the one line on stderr.
//
// Contract: a monitor decides collectively (a reduction over its communicator), so every rank holds the same log,
// a fatal event is raised on every rank together and the run can end cleanly without MPI_Abort.
#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace halfeti {

// One episode of a condition: from the step it started (time, step, message) while it held, the worst value
// measured and where (updated each step by the monitor; a fatal event is its own episode).
struct HealthEvent {
  double time = 0.0;
  long long step = 0;
  std::string kind;     // "density_variation", "spacing_collapse", "spilled", "cable_slack", "nan", ...
  std::string message;  // time, step, place, value, cause and a hint, in one line
  bool fatal = false;
  // The episode's worst value (kind's unit, e.g. a fraction for density_variation) and its time, step and place;
  // NaN when the monitor measures no value or no place.
  double worst = std::numeric_limits<double>::quiet_NaN();
  double worst_time = std::numeric_limits<double>::quiet_NaN();
  long long worst_step = 0;
  double worst_x = std::numeric_limits<double>::quiet_NaN();
  double worst_y = std::numeric_limits<double>::quiet_NaN();
};

using HealthLog = std::vector<HealthEvent>;

// An event as a monitor raises it (its worst value not yet measured).
HealthEvent health_event(double time, long long step, const std::string& kind, const std::string& message,
                         bool fatal = false);

// Whether a is worse than b for this kind: larger is worse, except for the kinds that measure a margin
// (spacing_collapse: the closest pair in dx).
bool health_worse(const std::string& kind, double a, double b);

// The worst value of an event updated by a measurement at (time, step, x, y), if that is worse (or the first).
void health_observe(HealthEvent& e, double value, double time, long long step, double x, double y);

// The log by kind, for summary.json and the run's last line: episodes, the first, the worst over all of them.
struct HealthTally {
  struct Kind {
    int episodes = 0;
    bool fatal = false;
    const HealthEvent* first = nullptr;
    const HealthEvent* worst = nullptr;  // the episode holding the worst value (the first when none has one)
  };
  std::map<std::string, Kind> kinds;
  int warnings = 0;  // non-fatal episodes
};
HealthTally tally(const HealthLog& log);  // points into log: keep it alive

// "3 warnings (density_variation 2, spacing_collapse 1)", or "no warnings".
std::string warnings_line(const HealthTally& t);

// The log as text (one tab-separated line per event; doubles in hexadecimal so they read back bit for bit), for
// the checkpoint, and back. decode raises UserError on a malformed line.
std::string encode_health_log(const HealthLog& log);
HealthLog decode_health_log(const std::string& text);

}  // namespace halfeti
