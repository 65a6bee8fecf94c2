// Wall-clock timing for glpt's statistics, immune to the program's notion of time.
//
// Programs may run under an LD_PRELOAD clock (shared/tools/detclock.c makes clock_gettime
// virtual so animations are deterministic). glpt's own stage timings must stay real, so they
// read CLOCK_MONOTONIC through the raw system call, which no preloaded library can interpose.
#pragma once

#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

namespace glpt {

inline double monotonic_ms() {
  timespec ts{};
  syscall(SYS_clock_gettime, CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

class Stopwatch {
 public:
  double elapsed_ms() const { return monotonic_ms() - start_; }
  void restart() { start_ = monotonic_ms(); }

 private:
  double start_ = monotonic_ms();
};

}  // namespace glpt
