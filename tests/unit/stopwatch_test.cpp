// glpt's stage timings stay real when the program's clock_gettime is not (a preloaded
// deterministic clock, shared/tools/detclock.c): this executable defines clock_gettime itself,
// which, like a preloaded library's, comes first in the global lookup scope, and stops time.
#include "common/stopwatch.hpp"

#include <gtest/gtest.h>
#include <time.h>

#include <chrono>
#include <thread>

extern "C" int clock_gettime(clockid_t, timespec* ts) {
  ts->tv_sec = 1000;  // a program's frozen clock
  ts->tv_nsec = 0;
  return 0;
}

TEST(Stopwatch, MeasuresRealTimeWhileTheProgramsClockStandsStill) {
  timespec frozen{};
  clock_gettime(CLOCK_MONOTONIC, &frozen);  // the program's view
  ASSERT_EQ(frozen.tv_sec, 1000);
  const glpt::Stopwatch watch;
  std::this_thread::sleep_for(std::chrono::milliseconds(30));  // nanosleep: no clock read
  const double elapsed = watch.elapsed_ms();
  EXPECT_GE(elapsed, 25.0);
  EXPECT_LT(elapsed, 10000.0);
  EXPECT_GT(glpt::monotonic_ms(), 0.0);
}
