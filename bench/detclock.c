/* Copied from shared/tools/detclock.c for the bench scripts (bench_tradeoffs.sh). */
/* Deterministic clock for LD_PRELOAD: every gettimeofday/clock_gettime/time call
   advances a virtual clock by DETCLOCK_STEP_US (default 1000 us) from a fixed epoch. */
#define _GNU_SOURCE
#include <stdlib.h>
#include <sys/time.h>
#include <time.h>
static unsigned long long now_us = 1700000000ULL * 1000000ULL;
static unsigned long long step(void) {
  static long s = -1;
  if (s < 0) {
    const char* e = getenv("DETCLOCK_STEP_US");
    s = e ? atol(e) : 1000;
  }
  return __atomic_add_fetch(&now_us, s, __ATOMIC_RELAXED);
}
int gettimeofday(struct timeval* tv, void* tz) {
  unsigned long long t = step();
  if (tv) {
    tv->tv_sec = t / 1000000;
    tv->tv_usec = t % 1000000;
  }
  (void)tz;
  return 0;
}
int clock_gettime(clockid_t c, struct timespec* ts) {
  unsigned long long t = step();
  (void)c;
  ts->tv_sec = t / 1000000;
  ts->tv_nsec = (t % 1000000) * 1000;
  return 0;
}
time_t time(time_t* p) {
  unsigned long long t = step();
  if (p) *p = t / 1000000;
  return t / 1000000;
}
