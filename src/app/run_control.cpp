#include "halfeti/app/run_control.hpp"

#include <cmath>
#include <csignal>
#include <ctime>

namespace halfeti::app {

double next_in_schedule(double next, double interval, double t, double tol) {
  if (!(interval > 0.0)) return next;
  if (const double behind = (t + tol - next) / interval; behind > 1000.0)
    next += std::floor(behind) * interval;
  while (next <= t + tol) {
    const double after = next + interval;
    next = after > next ? after : std::nextafter(t + tol, HUGE_VAL);
  }
  return next;
}

namespace {
// The signal a run was asked to stop by (0: none), set by the handler, read at each step's end.
volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void request_stop(int signal) {
  g_stop_signal = signal;
}
}  // namespace

void install_stop_handlers() {
  g_stop_signal = 0;
  for (int sig : {SIGTERM, SIGINT, SIGUSR1}) std::signal(sig, request_stop);
}

int requested_stop_signal() {
  return static_cast<int>(g_stop_signal);
}

const char* signal_name(int s) {
  switch (s) {
    case SIGTERM:
      return "SIGTERM";
    case SIGINT:
      return "SIGINT";
    case SIGUSR1:
      return "SIGUSR1";
    default:
      return "a signal";
  }
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buf;
}

}  // namespace halfeti::app
