/* gears_cpu: glxgears' scene (three gears in display lists, flat and smooth shading, one light)
 * drawn as fast as the implementation allows for a fixed time, reporting what each frame cost.
 *
 * usage: gears_cpu [--seconds S] [--size N]
 *
 * After half a second of warm-up (not counted), draws for S seconds.
 *
 * Prints one line: frames=F fps=R thread_us=T process_us=P, where thread_us is the CPU time of
 * the program's own thread per frame (its GL calls and whatever the implementation does on that
 * thread) and process_us the CPU time of every thread of the process per frame (an
 * implementation's worker threads included; not the X server's). CPU time per frame is steadier
 * than the frame rate on a machine shared with other work: bench_frame_cpu.sh reports both.
 * The gears turn by frame count, not by clock, so every run draws the same frames.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "glx_window.h"
#include "glxgears_gear.h" /* tests/programs */

static double seconds_of(clockid_t clock) {
  struct timespec t;
  clock_gettime(clock, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* One frame of glxgears' scene, the gears turned by `frame`. */
static void draw_frame(const GlxWindow* w, GLuint gears, long frame) {
  const float angle = 0.5f * (float)(frame % 720);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPushMatrix();
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
  glPushMatrix();
  glTranslatef(-3.0f, -2.0f, 0.0f);
  glRotatef(angle, 0.0f, 0.0f, 1.0f);
  glCallList(gears);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(3.1f, -2.0f, 0.0f);
  glRotatef(-2.0f * angle - 9.0f, 0.0f, 0.0f, 1.0f);
  glCallList(gears + 1);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(-3.1f, 4.2f, 0.0f);
  glRotatef(-2.0f * angle - 25.0f, 0.0f, 0.0f, 1.0f);
  glCallList(gears + 2);
  glPopMatrix();
  glPopMatrix();
  glXSwapBuffers(w->dpy, w->window);
}

int main(int argc, char** argv) {
  double seconds = 5.0;
  int size = 300;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--seconds"))
      seconds = atof(argv[i + 1]);
    else if (!strcmp(argv[i], "--size"))
      size = atoi(argv[i + 1]);
    else {
      fprintf(stderr, "gears_cpu: bad argument %s\n", argv[i]);
      return 2;
    }
  }
  if (seconds <= 0.0 || size < 16 || size > 4096) {
    fprintf(stderr, "gears_cpu: --seconds > 0, --size 16..4096\n");
    return 2;
  }
  GlxWindow w;
  if (glx_window_open(&w, "gears_cpu", size, size) != 0) return 1;
  static const GLfloat position[4] = {5.0f, 5.0f, 10.0f, 0.0f};
  static const GLfloat red[4] = {0.8f, 0.1f, 0.0f, 1.0f}, green[4] = {0.0f, 0.8f, 0.2f, 1.0f},
                       blue[4] = {0.2f, 0.2f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  const GLuint gears = glGenLists(3);
  glNewList(gears, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glxgears_gear(1.0f, 4.0f, 1.0f, 20, 0.7f, 0);
  glEndList();
  glNewList(gears + 1, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
  glxgears_gear(0.5f, 2.0f, 2.0f, 10, 0.7f, 0);
  glEndList();
  glNewList(gears + 2, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
  glxgears_gear(1.3f, 2.0f, 0.5f, 10, 0.7f, 0);
  glEndList();
  glEnable(GL_NORMALIZE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -1.0, 1.0, 5.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -40.0f);
  /* Warm-up (pipelines compiled, buffers allocated) before anything is counted. */
  long frames = 0;
  for (const double warm_up = seconds_of(CLOCK_MONOTONIC);
       seconds_of(CLOCK_MONOTONIC) - warm_up < 0.5;)
    draw_frame(&w, gears, frames++);
  const double start = seconds_of(CLOCK_MONOTONIC);
  const double thread_start = seconds_of(CLOCK_THREAD_CPUTIME_ID);
  const double process_start = seconds_of(CLOCK_PROCESS_CPUTIME_ID);
  const long first = frames;
  double elapsed = 0.0;
  do {
    draw_frame(&w, gears, frames++);
    elapsed = seconds_of(CLOCK_MONOTONIC) - start;
  } while (elapsed < seconds);
  frames -= first;
  const double thread_us = (seconds_of(CLOCK_THREAD_CPUTIME_ID) - thread_start) * 1e6 / frames;
  const double process_us = (seconds_of(CLOCK_PROCESS_CPUTIME_ID) - process_start) * 1e6 / frames;
  printf("frames=%ld fps=%.1f thread_us=%.1f process_us=%.1f\n", frames, frames / elapsed,
         thread_us, process_us);
  glx_window_close(&w);
  return 0;
}
