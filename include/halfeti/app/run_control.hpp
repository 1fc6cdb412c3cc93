// What the run loop asks of its surroundings, apart from the physics: when the next output is due, whether a
// signal asked the run to stop, and the wall clock's date for summary.json.
#pragma once

#include <string>

namespace halfeti::app {

// The next time of an output schedule once the run has reached t: the sequence interval, interval + interval, ...
// (each the sum of the one before and the interval), within `tol` of a scheduled time counting as reaching it.
// Skips whole intervals at once when a step spans very many (an interval far below the time step) and is never
// stuck where the interval is below the time's round-off: the result is always past t + tol. An interval that is
// not positive (the output is off) returns `next` unchanged.
double next_in_schedule(double next, double interval, double t, double tol);

// SIGTERM, SIGINT and SIGUSR1 (a scheduler's warning) set a flag the run reads at each step's end, so that it
// stops with a checkpoint instead of dying. install_stop_handlers clears the flag.
void install_stop_handlers();
int requested_stop_signal();  // 0: none
const char* signal_name(int signal);

// The current time in UTC, ISO 8601 to the second ("2026-01-31T12:00:00Z").
std::string utc_now();

}  // namespace halfeti::app
