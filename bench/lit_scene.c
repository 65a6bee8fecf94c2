/* lit_scene: a textured, lit GL 1.x scene for bench_light_transport.sh.
 *
 * usage: lit_scene [--lights N] [--triangles T] [--frames F] [--size WxH] [--pan DEG]
 *
 * A textured floor and a grid of 16 textured spheres (display lists, at least T triangles in all,
 * default 50 000) in a GLX window, drawn F times (default 12) with nothing changing, then exits;
 * --pan DEG turns the camera by DEG degrees per frame about its vertical axis (a moving camera
 * over a still world; default 0).
 * --lights N (default 1): N positional GL lights above the scene. GL allows 8 per state, so
 * with more than 8 each sphere is drawn with 8 of them (sphere i: lights i*7, i*7+1, ... mod N)
 * and the floor with the first 8: every light lights something, as in a scene of many lamps.
 * Prints nothing; run it with GLPT_STATS=1 to see what each frame cost.
 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glx_window.h"

enum { kSpheres = 16 };

static void light_positions(int n, float (*positions)[4]) {
  for (int i = 0; i < n; ++i) {
    const float angle = 2.39996323f * (float)i; /* golden angle: spread over the disc */
    const float radius = 3.5f * sqrtf(((float)i + 0.5f) / (float)n);
    positions[i][0] = radius * cosf(angle);
    positions[i][1] = 2.5f + 0.5f * (float)(i % 3);
    positions[i][2] = -8.0f + radius * sinf(angle);
    positions[i][3] = 1.0f;
  }
}

static void sphere(float radius, int rings, int segments) {
  for (int i = 0; i < rings; ++i) {
    const float t0 = (float)M_PI * (float)i / (float)rings;
    const float t1 = (float)M_PI * (float)(i + 1) / (float)rings;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= segments; ++j) {
      const float phi = 2.0f * (float)M_PI * (float)j / (float)segments;
      for (int k = 0; k < 2; ++k) {
        const float t = k == 0 ? t1 : t0;
        const float n[3] = {sinf(t) * cosf(phi), cosf(t), sinf(t) * sinf(phi)};
        glNormal3fv(n);
        glTexCoord2f(4.0f * (float)j / (float)segments, 2.0f * t / (float)M_PI);
        glVertex3f(radius * n[0], radius * n[1], radius * n[2]);
      }
    }
    glEnd();
  }
}

int main(int argc, char** argv) {
  int lights = 1, triangles = 50000, frames = 12, width = 320, height = 240;
  float pan = 0.0f; /* degrees the camera turns about its vertical axis per frame */
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--lights") && i + 1 < argc)
      lights = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--triangles") && i + 1 < argc)
      triangles = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--frames") && i + 1 < argc)
      frames = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--pan") && i + 1 < argc)
      pan = (float)atof(argv[++i]);
    else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
      if (sscanf(argv[++i], "%dx%d", &width, &height) != 2) return 2;
    } else {
      fprintf(
          stderr,
          "usage: lit_scene [--lights N] [--triangles T] [--frames F] [--size WxH] [--pan DEG]\n");
      return 2;
    }
  }
  if (lights < 1 || lights > 4096 || triangles < 100 || frames < 1) return 2;
  GlxWindow w;
  if (glx_window_open(&w, "lit_scene", width, height) != 0) return 1;
  Display* dpy = w.dpy;

  /* A checker texture, modulating the lit colour. */
  enum { kTex = 64 };
  static unsigned char texels[kTex][kTex][3];
  for (int y = 0; y < kTex; ++y)
    for (int x = 0; x < kTex; ++x) {
      const int on = ((x / 8) + (y / 8)) & 1;
      texels[y][x][0] = on ? 230 : 60;
      texels[y][x][1] = on ? 200 : 90;
      texels[y][x][2] = on ? 150 : 120;
    }
  GLuint texture;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, kTex, kTex, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  /* Spheres of 2 * rings * segments triangles each. */
  const int per_sphere = triangles / kSpheres;
  /* Rounded up: the scene has at least T triangles. */
  int rings = (int)ceilf(sqrtf((float)per_sphere / 4.0f));
  if (rings < 4) rings = 4;
  const int segments = 2 * rings;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  sphere(0.6f, rings, segments);
  glEndList();

  float(*positions)[4] = malloc(sizeof(float[4]) * (size_t)lights);
  if (!positions) return 1;
  light_positions(lights, positions);
  const float strength = 6.0f / (float)(lights < 8 ? lights : 8);

  for (int frame = 0; frame < frames; ++frame) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6 * width / height, 0.6 * width / height, -0.6, 0.6, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(20.0f, 1, 0, 0);
    glRotatef(pan * (float)frame, 0, 1, 0);
    glTranslatef(0, -2.0f, 0);
    glClearColor(0.1f, 0.1f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_TEXTURE_2D);
    const float white[] = {1, 1, 1, 1}, spec[] = {0.4f, 0.4f, 0.4f, 1};
    glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    for (int draw = 0; draw <= kSpheres; ++draw) {
      /* Draw `draw`'s 8 lights (the floor, draw kSpheres, takes the first 8). */
      for (int k = 0; k < 8; ++k) {
        const GLenum light = GL_LIGHT0 + (GLenum)k;
        if (k >= lights) {
          glDisable(light);
          continue;
        }
        const int index = draw == kSpheres ? k : (draw * 7 + k) % lights;
        const float color[] = {strength, strength, strength, 1};
        glLightfv(light, GL_POSITION, positions[index]);
        glLightfv(light, GL_DIFFUSE, color);
        glLightfv(light, GL_SPECULAR, color);
        glLightf(light, GL_CONSTANT_ATTENUATION, 0.0f);
        glLightf(light, GL_QUADRATIC_ATTENUATION, 0.15f);
        glEnable(light);
      }
      if (draw == kSpheres) {
        glBegin(GL_QUADS);
        glNormal3f(0, 1, 0);
        glTexCoord2f(0, 0);
        glVertex3f(-6, 0, -2);
        glTexCoord2f(8, 0);
        glVertex3f(6, 0, -2);
        glTexCoord2f(8, 8);
        glVertex3f(6, 0, -14);
        glTexCoord2f(0, 8);
        glVertex3f(-6, 0, -14);
        glEnd();
      } else {
        glPushMatrix();
        glTranslatef(-2.4f + 1.6f * (float)(draw % 4), 0.6f, -4.5f - 2.0f * (float)(draw / 4));
        glCallList(list);
        glPopMatrix();
      }
    }
    glXSwapBuffers(dpy, w.window);
  }
  glFinish();
  free(positions);
  glx_window_close(&w);
  return 0;
}
