/* swap_rate.so: preloaded ahead of a libGL, counts an unmodified program's glXSwapBuffers calls
 * over a short window and exits, so a benchmark can alternate two libGLs many times a minute.
 *
 *   LD_PRELOAD="swap_rate.so [glpt's libGL.so.1]" GLPT_SWAP_RATE_SECONDS=1.5 glxgears
 *
 * The first GLPT_SWAP_RATE_WARMUP seconds after the first swap are not counted (default 1:
 * start-up, pipeline compilation, the first frames); then it counts swaps for
 * GLPT_SWAP_RATE_SECONDS (default 1.5), prints "swap_rate: frames=N seconds=S fps=F" on stderr
 * and exits with status 0. Each swap is passed on to the next glXSwapBuffers in the lookup order
 * (glpt's when it is preloaded after this library, else the system libGL's).
 *
 * Why: on a shared 2-core machine the CPU's speed drifts by tens of per cent within seconds
 * (the same frame's CPU time varies that much), so long runs of one library and then the other
 * compare different machines; many short windows, alternating, and the median of the per-window
 * ratios do not (bench_raster_vs_mesa.sh).
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef void (*SwapBuffersFn)(void* display, unsigned long drawable);

static double seconds_now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static double seconds_from_env(const char* name, double fallback) {
  const char* text = getenv(name);
  if (text == NULL || *text == '\0') return fallback;
  char* end = NULL;
  const double value = strtod(text, &end);
  return (end != text && value > 0.0 && value < 3600.0) ? value : fallback;
}

/* The program's one rendering thread calls it; no locking. */
void glXSwapBuffers(void* display, unsigned long drawable) {
  static SwapBuffersFn next_swap = NULL;
  static double first_swap = -1.0, window_start = -1.0, warmup = 1.0, window = 1.5;
  static long frames = 0;
  if (next_swap == NULL) {
    next_swap = (SwapBuffersFn)dlsym(RTLD_NEXT, "glXSwapBuffers");
    if (next_swap == NULL) {
      fprintf(stderr, "swap_rate: no glXSwapBuffers after this library\n");
      exit(2);
    }
    warmup = seconds_from_env("GLPT_SWAP_RATE_WARMUP", 1.0);
    window = seconds_from_env("GLPT_SWAP_RATE_SECONDS", 1.5);
  }
  next_swap(display, drawable);
  const double now = seconds_now();
  if (first_swap < 0.0) first_swap = now;
  if (window_start < 0.0) {
    if (now - first_swap >= warmup) window_start = now;
    return;
  }
  ++frames;
  if (now - window_start >= window) {
    fprintf(stderr, "swap_rate: frames=%ld seconds=%.3f fps=%.1f\n", frames, now - window_start,
            (double)frames / (now - window_start));
    fflush(stderr);
    exit(0);
  }
}
