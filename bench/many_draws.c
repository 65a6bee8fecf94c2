/* many_draws: a frame of many separate draws, for bench_classify.sh.
 *
 * usage: many_draws [--draws N] [--frames F] [--shapes S] [--moving M] [--still-camera]
 *
 * Draws N lit cubes per frame into a 256x256 GLX window, each its own glBegin/glEnd block under
 * its own modelview (glPushMatrix, glTranslatef, glRotatef), as a program drawing every object
 * separately does; the cubes come in S shapes (sizes). A HUD quad in glOrtho ends each frame.
 * The camera turns a little every frame (folded into the modelview), so every modelview changes
 * while the world stands still: what identity matching and classification work hardest on.
 * --moving M: the first M cubes bob up and down (moving objects); --still-camera: the camera
 * stays (then only the moving cubes change).
 * Deterministic (no clock, no rand()).
 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glx_window.h"

static void cube(float s) {
  static const float n[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    const int a = f / 2, u = (a + 1) % 3, v = (a + 2) % 3;
    const float side = (f % 2) ? -s : s;
    glNormal3fv(n[f]);
    for (int k = 0; k < 4; ++k) {
      float p[3];
      p[a] = side;
      p[u] = (k == 1 || k == 2) ? s : -s;
      p[v] = (k >= 2) ? s : -s;
      glVertex3fv(p);
    }
  }
  glEnd();
}

int main(int argc, char** argv) {
  int draws = 5000, frames = 20, shapes = 4, moving = 0, still_camera = 0;
  for (int i = 1; i < argc; i += 2) {
    if (!strcmp(argv[i], "--still-camera")) {
      still_camera = 1;
      --i;
      continue;
    }
    if (i + 1 >= argc) {
      fprintf(stderr, "many_draws: %s needs a value\n", argv[i]);
      return 2;
    }
    if (!strcmp(argv[i], "--draws"))
      draws = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--moving"))
      moving = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--frames"))
      frames = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--shapes"))
      shapes = atoi(argv[i + 1]);
    else {
      fprintf(stderr, "many_draws: bad argument %s\n", argv[i]);
      return 2;
    }
  }
  if (draws < 1 || frames < 1 || shapes < 1) {
    fprintf(stderr, "many_draws: counts must be >= 1\n");
    return 2;
  }
  GlxWindow w;
  if (glx_window_open(&w, "many_draws", 256, 256) != 0) return 1;
  Display* dpy = w.dpy;
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_DEPTH_TEST);
  int grid = 1;
  while (grid * grid < draws) ++grid;
  for (int frame = 0; frame < frames; ++frame) {
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.1, 0.1, -0.1, 0.1, 0.2, 400.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(30.0f, 1, 0, 0);
    glRotatef(still_camera ? 0.0f : 0.5f * (float)frame, 0, 1, 0);
    glTranslatef(0.0f, -20.0f, -20.0f);
    const float light[4] = {0.3f, 1.0f, 0.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    for (int d = 0; d < draws; ++d) {
      glPushMatrix();
      const float bob = d < moving ? 0.5f * (float)((frame + d) % 4) : 0.0f;
      glTranslatef((float)(d % grid) * 1.5f - grid * 0.75f, bob, -(float)(d / grid) * 1.5f);
      glRotatef((float)(d * 37 % 360), 0, 1, 0);
      glColor3f((float)(d % 7) / 7.0f, (float)(d % 5) / 5.0f, 0.8f);
      cube(0.3f + 0.1f * (float)(d % shapes));
      glPopMatrix();
    }
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 256, 0, 256, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_LIGHTING);
    glColor3f(1, 1, 1);
    glRecti(8, 8, 120, 20);
    glEnable(GL_LIGHTING);
    glXSwapBuffers(dpy, w.window);
  }
  glFinish();
  glx_window_close(&w);
  return 0;
}
