/* vertex_stream: the vertex-bound immediate-mode stream of issue 20, for bench_vertex_stream.sh.
 *
 * usage: vertex_stream [--vertices N] [--frames F]
 *
 * A 64x64 GLX window, GL_LIGHTING with GL_LIGHT0; each frame glClear, then N glNormal3f/glVertex3f
 * pairs (default 300,000) as one glBegin(GL_TRIANGLES)/glEnd, almost all triangles of zero area
 * (the three vertices of 99 in 100 triangles are one point, so rasterization costs nothing), then
 * glFinish and a swap: the cost per vertex before rasterization (capture, conversion, upload,
 * vertex shader, clipping and setup). F frames (default 20) after two warm-up frames; prints one
 * line: vertices=N frames=F ms_per_frame=T mverts_per_s=V
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
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

int main(int argc, char** argv) {
  int vertices = 300000, frames = 20;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--vertices")) {
      vertices = atoi(argv[i + 1]);
    } else if (!strcmp(argv[i], "--frames")) {
      frames = atoi(argv[i + 1]);
    } else {
      fprintf(stderr, "vertex_stream: unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  vertices -= vertices % 3;
  if (vertices < 3 || frames < 1) {
    fprintf(stderr, "vertex_stream: bad arguments\n");
    return 2;
  }
  GlxWindow w;
  if (glx_window_open(&w, "vertex_stream", 64, 64) != 0) return 1;
  Display* dpy = w.dpy;
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  // Positions and normals precomputed, so the program's own loop is only the GL calls.
  float* data = malloc(sizeof(float) * 6 * (size_t)vertices);
  unsigned seed = 12345u;
  for (int t = 0; t < vertices / 3; ++t) {
    seed = seed * 1664525u + 1013904223u;
    const float x = (float)((seed >> 8) % 1000) / 500.0f - 1.0f;
    seed = seed * 1664525u + 1013904223u;
    const float y = (float)((seed >> 8) % 1000) / 500.0f - 1.0f;
    for (int k = 0; k < 3; ++k) {
      float* v = &data[6 * (3 * t + k)];
      const float spread = (t % 100 == 0) ? 0.05f : 0.0f;  // 1 in 100 covers pixels
      v[0] = 0.0f;
      v[1] = 0.6f;
      v[2] = 0.8f;
      v[3] = x + (k == 1 ? spread : 0.0f);
      v[4] = y + (k == 2 ? spread : 0.0f);
      v[5] = 0.0f;
    }
  }
  double start = 0;
  for (int f = 0; f < frames + 2; ++f) {
    if (f == 2) start = now_ms();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < vertices; ++i) {
      const float* v = &data[6 * i];
      glNormal3f(v[0], v[1], v[2]);
      glVertex3f(v[3], v[4], v[5]);
    }
    glEnd();
    glFinish();
    glXSwapBuffers(dpy, w.window);  // a frame boundary for GLPT_STATS (64x64: presenting is cheap)
  }
  const double ms = (now_ms() - start) / frames;
  printf("vertices=%d frames=%d ms_per_frame=%.2f mverts_per_s=%.2f\n", vertices, frames, ms,
         vertices / ms / 1000.0);
  free(data);
  glx_window_close(&w);
  return 0;
}
