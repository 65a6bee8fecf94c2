/* gl_throughput: geometry submission speed of a GL 1.x implementation, for bench_front_end.sh.
 *
 * usage: gl_throughput --mode immediate|arrays|elements|vbo [--triangles N] [--frames F]
 *
 * Draws N small lit, coloured triangles per frame into a 256x256 GLX window, F frames after two
 * warm-up frames, and prints one line:
 *   mode=M triangles=N frames=F submit_ms=S frame_ms=T
 * submit_ms: mean wall time of the frame's GL calls alone (what the front end costs the program:
 * vertex capture for immediate mode, array reads for the rest); frame_ms: mean wall time of the
 * whole frame including glFinish and the swap (the implementation's total cost).
 *   immediate  glBegin(GL_TRIANGLES), per vertex glColor4ub, glNormal3f, glVertex3f
 *   arrays     glDrawArrays from client arrays (interleaved colour, normal, position)
 *   elements   glDrawElements (GL_UNSIGNED_INT) from client arrays
 *   vbo        glDrawElements with the vertices and indices in buffer objects (GL 1.5)
 * Triangles are about 2 pixels wide so rasterization is not what is measured.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "glx_window.h"

typedef struct {
  GLubyte color[4];
  GLfloat normal[3];
  GLfloat position[3];
} Vertex;

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static void build(Vertex* v, GLuint* indices, int triangles) {
  unsigned seed = 12345u;
  for (int t = 0; t < triangles; ++t) {
    seed = seed * 1664525u + 1013904223u;
    float x = (float)((seed >> 8) % 1000) / 500.0f - 1.0f;
    seed = seed * 1664525u + 1013904223u;
    float y = (float)((seed >> 8) % 1000) / 500.0f - 1.0f;
    for (int k = 0; k < 3; ++k) {
      Vertex* p = &v[3 * t + k];
      p->color[0] = (GLubyte)(t * 7);
      p->color[1] = (GLubyte)(t * 13);
      p->color[2] = (GLubyte)(k * 90);
      p->color[3] = 255;
      p->normal[0] = 0.0f;
      p->normal[1] = 0.3f * (float)k;
      p->normal[2] = 1.0f;
      p->position[0] = x + (k == 1 ? 0.016f : 0.0f);
      p->position[1] = y + (k == 2 ? 0.016f : 0.0f);
      p->position[2] = 0.0f;
      indices[3 * t + k] = (GLuint)(3 * t + k);
    }
  }
}

int main(int argc, char** argv) {
  const char* mode = "immediate";
  int triangles = 100000, frames = 20;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--mode") == 0 && i + 1 < argc) {
      mode = argv[++i];
    } else if (strcmp(argv[i], "--triangles") == 0 && i + 1 < argc) {
      triangles = atoi(argv[++i]);
    } else if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = atoi(argv[++i]);
    } else {
      fprintf(stderr,
              "usage: gl_throughput --mode immediate|arrays|elements|vbo [--triangles N] [--frames "
              "F]\n");
      return 2;
    }
  }
  int kind = strcmp(mode, "immediate") == 0  ? 0
             : strcmp(mode, "arrays") == 0   ? 1
             : strcmp(mode, "elements") == 0 ? 2
             : strcmp(mode, "vbo") == 0      ? 3
                                             : -1;
  if (kind < 0 || triangles <= 0 || frames <= 0) {
    fprintf(stderr, "gl_throughput: bad arguments\n");
    return 2;
  }
  GlxWindow w;
  if (glx_window_open(&w, "gl_throughput", 256, 256) != 0) return 1;
  Display* dpy = w.dpy;
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_DEPTH_TEST);

  Vertex* vertices = malloc(sizeof(Vertex) * 3 * (size_t)triangles);
  GLuint* indices = malloc(sizeof(GLuint) * 3 * (size_t)triangles);
  if (!vertices || !indices) return 1;
  build(vertices, indices, triangles);
  const GLsizei stride = sizeof(Vertex);
  const char* base = (const char*)vertices;
  const void* index_base = indices;
  if (kind == 3) {
    GLuint buffers[2];
    glGenBuffers(2, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(Vertex) * 3 * (size_t)triangles), vertices,
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(sizeof(GLuint) * 3 * (size_t)triangles),
                 indices, GL_STATIC_DRAW);
    base = NULL;
    index_base = NULL;
  }
  if (kind != 0) {
    glColorPointer(4, GL_UNSIGNED_BYTE, stride, base + offsetof(Vertex, color));
    glNormalPointer(GL_FLOAT, stride, base + offsetof(Vertex, normal));
    glVertexPointer(3, GL_FLOAT, stride, base + offsetof(Vertex, position));
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_VERTEX_ARRAY);
  }

  double submit = 0.0, total = 0.0;
  for (int frame = -2; frame < frames; ++frame) {
    double start = now_ms();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    switch (kind) {
      case 0:
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 3 * triangles; ++i) {
          glColor4ubv(vertices[i].color);
          glNormal3fv(vertices[i].normal);
          glVertex3fv(vertices[i].position);
        }
        glEnd();
        break;
      case 1:
        glDrawArrays(GL_TRIANGLES, 0, 3 * triangles);
        break;
      default:
        glDrawElements(GL_TRIANGLES, 3 * triangles, GL_UNSIGNED_INT, index_base);
        break;
    }
    double submitted = now_ms();
    glFinish();
    glXSwapBuffers(dpy, w.window);
    double end = now_ms();
    if (frame >= 0) {
      submit += submitted - start;
      total += end - start;
    }
  }
  printf("mode=%s triangles=%d frames=%d submit_ms=%.3f frame_ms=%.3f\n", mode, triangles, frames,
         submit / frames, total / frames);
  glx_window_close(&w);
  free(vertices);
  free(indices);
  return 0;
}
