// A stand-in for glpt's libGL.so.1 that lets the end-to-end harness be tested with real Mesa.
//
// Preloaded (LD_PRELOAD) in front of the system libGL, it wraps glXSwapBuffers: before each swap
// it reads the back buffer and, like glpt, writes $GLPT_OUTPUT/frame_NNNNNN.png and, with
// GLPT_STATS=1, prints a "glpt: frame=..." stats line to stderr in glpt's format. Then it calls
// the real glXSwapBuffers. It renders nothing itself: it only proves that the scripts that drive
// glpt (tests/e2e, bench) work.
#include <GL/gl.h>
#include <GL/glx.h>
#include <dlfcn.h>
#include <time.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "image_io.hpp"

namespace {

using SwapFn = void (*)(Display*, GLXDrawable);

// The real monotonic clock in ms. Benchmarks preload detclock.so (a virtual clock) before
// libGL, and it interposes clock_gettime for the whole process; RTLD_NEXT from here, after it in
// LD_PRELOAD, finds libc's clock_gettime, so these timings stay real.
double now_ms() {
  using ClockFn = int (*)(clockid_t, timespec*);
  static const ClockFn real_clock = reinterpret_cast<ClockFn>(dlsym(RTLD_NEXT, "clock_gettime"));
  timespec ts{};
  (real_clock ? real_clock : clock_gettime)(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

std::atomic<unsigned> g_frame{0};

}  // namespace

extern "C" __attribute__((visibility("default"))) void glXSwapBuffers(Display* dpy,
                                                                      GLXDrawable drawable) {
  static const SwapFn real = reinterpret_cast<SwapFn>(dlsym(RTLD_NEXT, "glXSwapBuffers"));
  const char* out = std::getenv("GLPT_OUTPUT");
  const char* stats = std::getenv("GLPT_STATS");
  const unsigned frame = g_frame++;
  if ((out && *out) || (stats && std::string(stats) == "1")) {
    const double t0 = now_ms();
    GLint vp[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    const int w = vp[2], h = vp[3];
    std::vector<uint8_t> pixels(static_cast<size_t>(w > 0 ? w : 0) * (h > 0 ? h : 0) * 4);
    if (!pixels.empty()) {
      glReadBuffer(GL_BACK);
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    }
    const double capture_ms = now_ms() - t0;
    const double t1 = now_ms();
    if (out && *out && !pixels.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%06u.png", frame);
      std::string error;
      if (!glpt::write_png_rgba8(std::string(out) + name, static_cast<uint32_t>(w),
                                 static_cast<uint32_t>(h), pixels.data(), true, &error)) {
        std::fprintf(stderr, "fake_shim: %s\n", error.c_str());
      }
    }
    const double present_ms = now_ms() - t1;
    const double total_ms = now_ms() - t0;
    if (stats && std::string(stats) == "1") {
      const double rays = static_cast<double>(w) * h;
      std::fprintf(stderr,
                   "glpt: frame=%u size=%dx%d capture_ms=%.2f blas_ms=0.00 tlas_ms=0.00 "
                   "trace_ms=0.00 present_ms=%.2f total_ms=%.2f triangles=0 rays=%.0f "
                   "mrays_per_s=%.2f blas_builds=0 blas_reused=0 spp=1\n",
                   frame, w, h, capture_ms, present_ms, total_ms, rays,
                   total_ms > 0 ? rays / (total_ms * 1000.0) : 0.0);
    }
  }
  if (real) real(dpy, drawable);
}
