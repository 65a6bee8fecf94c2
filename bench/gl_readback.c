/* gl_readback: what a draw followed by glReadPixels costs (the loop of conformance tests such as
 * piglit's gl-1.0-blend-func: set state, draw a small quad, read it back, compare).
 *
 * usage: gl_readback [--iterations N] [--size S] [--read W] [--mode draw_read|read|draw_finish]
 *
 * Opens an SxS GLX window (default 160, piglit's), then times N iterations (default 2000, after
 * 50 warm-up iterations) of:
 *   draw_read    glBlendFunc (one of four factor pairs, in turn), a WxW quad (glBegin/glEnd),
 *                glReadPixels of that quad (GL_RGBA, GL_FLOAT, as piglit's probes)
 *   read         glReadPixels alone (nothing drawn since the last read)
 *   draw_finish  the state change and the quad, then glFinish
 * and prints one line:  mode=M size=S read=W iterations=N us_per_iteration=T
 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "glx_window.h"

static double now_us(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e6 + t.tv_nsec / 1e3;
}

int main(int argc, char** argv) {
  int iterations = 2000, size = 160, read = 10;
  const char* mode = "draw_read";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--iterations"))
      iterations = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--size"))
      size = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--read"))
      read = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--mode"))
      mode = argv[i + 1];
    else {
      fprintf(stderr, "gl_readback: unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  const int draw = strcmp(mode, "read") != 0, finish_only = !strcmp(mode, "draw_finish");
  if (iterations < 1 || size < 1 || read < 1 || read > size ||
      (strcmp(mode, "draw_read") && strcmp(mode, "read") && strcmp(mode, "draw_finish"))) {
    fprintf(stderr, "gl_readback: bad arguments\n");
    return 2;
  }
  GlxWindow w;
  if (glx_window_open(&w, "gl_readback", size, size) != 0) return 1;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, size, 0, size, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_BLEND);
  glClearColor(0.2f, 0.3f, 0.4f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  static const GLenum factors[4][2] = {{GL_ONE, GL_ZERO},
                                       {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
                                       {GL_DST_COLOR, GL_ZERO},
                                       {GL_ONE, GL_ONE}};
  float* pixels = malloc(sizeof(float) * 4 * (size_t)read * (size_t)read);
  double sum = 0;
  double start = 0;
  for (int i = 0; i < iterations + 50; ++i) {
    if (i == 50) start = now_us();
    if (draw) {
      glBlendFunc(factors[i % 4][0], factors[i % 4][1]);
      glColor4f(0.1f * (float)(i % 10), 0.5f, 0.25f, 0.75f);
      glBegin(GL_QUADS);
      glVertex2i(0, 0);
      glVertex2i(read, 0);
      glVertex2i(read, read);
      glVertex2i(0, read);
      glEnd();
    }
    if (finish_only) {
      glFinish();
    } else {
      glReadPixels(0, 0, read, read, GL_RGBA, GL_FLOAT, pixels);
      sum += pixels[0];
    }
  }
  const double us = (now_us() - start) / iterations;
  printf("mode=%s size=%d read=%d iterations=%d us_per_iteration=%.1f (checksum %.3f)\n", mode,
         size, read, iterations, us, sum);
  free(pixels);
  glx_window_close(&w);
  return 0;
}
