// Wall-clock timing for glpt's statistics, immune to the program's notion of time.
//
// Programs may run under an LD_PRELOAD clock (shared/tools/detclock.c makes clock_gettime
// virtual so animations are deterministic). glpt's own stage timings must stay real, so they
// read CLOCK_MONOTONIC through libc's own clock_gettime, looked up in libc itself: a handle's
// lookup searches that library, not the global scope a preloaded library comes first in. libc's
// reads the vDSO; the raw system call it replaced cost a kernel entry per reading (a few
// microseconds each under a hypervisor, nine per glxgears frame). The raw call remains the
// fallback where libc cannot be looked up.
#pragma once

#include <dlfcn.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

namespace glpt {

namespace detail {
using ClockGettime = int (*)(clockid_t, timespec*);
inline ClockGettime libc_clock_gettime() {
  static const ClockGettime function = []() -> ClockGettime {
    void* libc = dlopen("libc.so.6", RTLD_NOW | RTLD_NOLOAD);
    if (libc == nullptr) return nullptr;
    auto* found = reinterpret_cast<ClockGettime>(dlsym(libc, "clock_gettime"));
    dlclose(libc);  // a RTLD_NOLOAD handle only counted a reference: libc stays
    return found;
  }();
  return function;
}
}  // namespace detail

inline double monotonic_ms() {
  timespec ts{};
  if (const detail::ClockGettime clock = detail::libc_clock_gettime())
    clock(CLOCK_MONOTONIC, &ts);
  else
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
