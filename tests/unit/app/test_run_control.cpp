// The output schedule of the run loop (app/run_control.hpp): the sequence dt, dt + dt, ... reached within round-off,
// resumed after a restart's time, never stuck (an interval below the time's round-off once hung the run: issue
// #18's `output.field_interval: 1e-300`).
#include <gtest/gtest.h>

#include <cmath>

#include "halfeti/app/run_control.hpp"

using halfeti::app::next_in_schedule;

TEST(OutputSchedule, FollowsTheSumsOfTheInterval) {
  // The sequence is built by repeated addition, as the run builds it: 0.1, 0.1 + 0.1, ... (not k * 0.1).
  const double dt = 0.1, tol = 1e-12;
  double next = dt, expected = dt;
  for (int k = 0; k < 50; ++k) {
    const double t = expected;  // a step that ends exactly on the scheduled time
    next = next_in_schedule(next, dt, t, tol);
    expected += dt;
    EXPECT_EQ(next, expected) << "after output " << k;
  }
}

TEST(OutputSchedule, AStepEndingWithinTheToleranceCountsAsReachingIt) {
  EXPECT_DOUBLE_EQ(next_in_schedule(0.5, 0.5, 0.5 - 1e-13, 1e-12), 1.0);
  // ... and one ending short of it by more than the tolerance does not.
  EXPECT_DOUBLE_EQ(next_in_schedule(0.5, 0.5, 0.5 - 1e-9, 1e-12), 0.5);
}

TEST(OutputSchedule, ResumesPastTheTimeOfARestart) {
  // A restart at t = 0.73 with a 0.1 s interval: the first output after it is 0.8 (to round-off).
  const double next = next_in_schedule(0.1, 0.1, 0.73, 1e-12);
  EXPECT_NEAR(next, 0.8, 1e-12);
  EXPECT_GT(next, 0.73);
}

TEST(OutputSchedule, AnIntervalFarBelowTheStepIsNeverStuck) {
  // 1e-300 is below the round-off of t = 1: adding it changes nothing. The schedule must still move past t.
  for (double interval : {1e-300, 1e-20, 1e-9}) {
    const double t = 1.0, tol = 1e-9;
    const double next = next_in_schedule(interval, interval, t, tol);
    EXPECT_GT(next, t + tol) << "interval " << interval;
    EXPECT_TRUE(std::isfinite(next));
  }
}

TEST(OutputSchedule, AnOutputThatIsOffStaysOff) {
  EXPECT_EQ(next_in_schedule(0.0, 0.0, 5.0, 1e-9), 0.0);
  EXPECT_EQ(next_in_schedule(-1.0, -1.0, 5.0, 1e-9), -1.0);
}
