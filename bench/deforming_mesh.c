/* deforming_mesh: a lit mesh whose vertices move every frame, for bench_refit.sh.
 *
 * usage: deforming_mesh [--grid G] [--frames F] [--amplitude A]
 *
 * A G x G grid (2 G^2 triangles, default G 96: 18,432) waving like a flag over a floor, in a
 * 256x256 GLX window under a still camera: one glDrawElements of the grid per frame with new
 * positions and normals (the same topology), so path-traced mode sees one deforming draw.
 * A: the wave's height relative to the grid's size (default 0.15). Deterministic.
 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glx_window.h"

int main(int argc, char** argv) {
  int grid = 96, frames = 40;
  float amplitude = 0.15f;
  for (int i = 1; i < argc; i += 2) {
    if (i + 1 >= argc) {
      fprintf(stderr, "deforming_mesh: %s needs a value\n", argv[i]);
      return 2;
    }
    if (!strcmp(argv[i], "--grid"))
      grid = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--frames"))
      frames = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--amplitude"))
      amplitude = (float)atof(argv[i + 1]);
    else {
      fprintf(stderr, "deforming_mesh: bad argument %s\n", argv[i]);
      return 2;
    }
  }
  if (grid < 2 || grid > 1024 || frames < 1) {
    fprintf(stderr, "deforming_mesh: --grid 2..1024, --frames >= 1\n");
    return 2;
  }
  const int n = grid + 1;
  float* positions = malloc(sizeof(float) * 3 * n * n);
  float* normals = malloc(sizeof(float) * 3 * n * n);
  unsigned* indices = malloc(sizeof(unsigned) * 6 * grid * grid);
  if (!positions || !normals || !indices) {
    fprintf(stderr, "deforming_mesh: out of memory\n");
    return 1;
  }
  for (int y = 0, k = 0; y < grid; ++y)
    for (int x = 0; x < grid; ++x) {
      const unsigned a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      indices[k++] = a, indices[k++] = b, indices[k++] = d;
      indices[k++] = a, indices[k++] = d, indices[k++] = c;
    }
  GlxWindow w;
  if (glx_window_open(&w, "deforming_mesh", 256, 256) != 0) return 1;
  Display* dpy = w.dpy;
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  for (int frame = 0; frame < frames; ++frame) {
    const float phase = 0.35f * (float)frame;
    for (int y = 0; y <= grid; ++y)
      for (int x = 0; x <= grid; ++x) {
        const float u = (float)x / grid, v = (float)y / grid;
        float* p = &positions[3 * (y * n + x)];
        const float wave = 6.2831853f * (1.5f * u + 0.5f * v) - phase;
        p[0] = 2.0f * u - 1.0f;
        p[1] = 2.0f * v - 1.0f;
        p[2] = amplitude * 2.0f * u * sinf(wave);  // fixed at the pole (u = 0)
        float* q = &normals[3 * (y * n + x)];
        const float dz_du = amplitude * 2.0f * (sinf(wave) + u * 6.2831853f * 1.5f * cosf(wave));
        const float dz_dv = amplitude * 2.0f * u * 6.2831853f * 0.5f * cosf(wave);
        q[0] = -dz_du * 0.5f, q[1] = -dz_dv * 0.5f, q[2] = 1.0f;
      }
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.1, 0.1, -0.1, 0.1, 0.2, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.5f);
    glRotatef(25.0f, 1, 0, 0);  // look down on the floor: the camera stays above it
    const float light[4] = {0.4f, 0.6f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glColor3f(0.7f, 0.7f, 0.7f);  // the floor
    glNormal3f(0.0f, 1.0f, 0.0f);
    glDisableClientState(GL_NORMAL_ARRAY);
    glBegin(GL_QUADS);
    glVertex3f(-3, -1.2f, 3);
    glVertex3f(3, -1.2f, 3);
    glVertex3f(3, -1.2f, -3);
    glVertex3f(-3, -1.2f, -3);
    glEnd();
    glEnableClientState(GL_NORMAL_ARRAY);
    glColor3f(0.9f, 0.3f, 0.2f);  // the flag
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glDrawElements(GL_TRIANGLES, 6 * grid * grid, GL_UNSIGNED_INT, indices);
    glXSwapBuffers(dpy, w.window);
  }
  glFinish();
  glx_window_close(&w);
  free(positions);
  free(normals);
  free(indices);
  return 0;
}
