// Wall-clock timers by phase (named as in DESIGN.md's "one time step"), summed over a run and written to
// summary.json. A ScopedTimer adds the time spent in its scope to one phase.
#pragma once

#include <sys/resource.h>

#include <chrono>
#include <map>
#include <string>

namespace halfeti {

// Seconds on a steady clock (differences only).
inline double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU seconds (user + system) in a getrusage record.
inline double cpu_seconds(const struct rusage& usage) {
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// CPU seconds (user + system) of this process since it started.
inline double process_cpu_seconds() {
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  return cpu_seconds(usage);
}

class PhaseTimers {
 public:
  void add(const std::string& phase, double seconds) { seconds_[phase] += seconds; }
  double seconds(const std::string& phase) const {
    auto it = seconds_.find(phase);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  const std::map<std::string, double>& all() const { return seconds_; }
  void merge(const PhaseTimers& other) {
    for (const auto& [k, v] : other.seconds_) seconds_[k] += v;
  }

 private:
  std::map<std::string, double> seconds_;
};

class ScopedTimer {
 public:
  ScopedTimer(PhaseTimers& timers, std::string phase)
      : timers_(timers), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() {
    timers_.add(phase_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  PhaseTimers& timers_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace halfeti
