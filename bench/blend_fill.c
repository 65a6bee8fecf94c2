/* blend_fill: blended fill rate, for bench_blend_fill.sh (what blending in the fragment shader
 * costs against the pipeline's blending, docs/performance.md).
 *
 * usage: blend_fill [--size WxH] [--layers N] [--frames F]
 *
 * Each frame clears, then draws N window-sized quads, each blended over the last with one of four
 * blend states in turn (translucent, additive, modulating, premultiplied), and ends with
 * glFinish and a swap; prints the median frame time in ms and the blended pixels per second.
 * Deterministic.
 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "glx_window.h"

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int compare_doubles(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

int main(int argc, char** argv) {
  int width = 640, height = 480, layers = 16, frames = 30;
  for (int i = 1; i < argc; i += 2) {
    if (i + 1 >= argc) {
      fprintf(stderr, "blend_fill: %s needs a value\n", argv[i]);
      return 2;
    }
    if (!strcmp(argv[i], "--size") && sscanf(argv[i + 1], "%dx%d", &width, &height) == 2) continue;
    if (!strcmp(argv[i], "--layers")) {
      layers = atoi(argv[i + 1]);
      continue;
    }
    if (!strcmp(argv[i], "--frames")) {
      frames = atoi(argv[i + 1]);
      continue;
    }
    fprintf(stderr, "blend_fill: bad argument %s\n", argv[i]);
    return 2;
  }
  if (width < 1 || height < 1 || width > 4096 || height > 4096 || layers < 1 || frames < 3) {
    fprintf(stderr, "blend_fill: --size 1..4096 x 1..4096, --layers >= 1, --frames >= 3\n");
    return 2;
  }
  GlxWindow w;
  if (glx_window_open(&w, "blend_fill", width, height) != 0) return 1;
  double* times = malloc(sizeof(double) * (size_t)frames);
  if (!times) return 1;
  glEnable(GL_BLEND);
  for (int frame = 0; frame < frames; ++frame) {
    const double start = now_ms();
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    for (int layer = 0; layer < layers; ++layer) {
      switch (layer % 4) {
        case 0:
          glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
          break;
        case 1:
          glBlendFunc(GL_ONE, GL_ONE);
          break;
        case 2:
          glBlendFunc(GL_DST_COLOR, GL_ZERO);
          break;
        default:
          glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
          break;
      }
      const float t = (float)layer / (float)layers;
      glBegin(GL_QUADS);
      glColor4f(0.9f * t, 0.5f, 1.0f - t, 0.3f);
      glVertex2f(-1, -1);
      glColor4f(0.2f, 0.8f * t, 0.4f, 0.6f);
      glVertex2f(1, -1);
      glColor4f(0.1f, 0.3f, 0.9f * t, 0.5f);
      glVertex2f(1, 1);
      glColor4f(0.7f, 0.2f, 0.3f * t, 0.4f);
      glVertex2f(-1, 1);
      glEnd();
    }
    glFinish();
    glXSwapBuffers(w.dpy, w.window);
    times[frame] = now_ms() - start;
  }
  qsort(times + 2, (size_t)frames - 2, sizeof(double), compare_doubles);  // the first two warm up
  const double median = times[2 + (frames - 2) / 2];
  printf("frame_ms=%.3f mpixels_per_s=%.1f\n", median,
         (double)width * height * layers / (median * 1e3));
  free(times);
  glx_window_close(&w);
  return 0;
}
