/* glxgears_gear.h: glxgears' gear() (Brian Paul, public domain / MIT in Mesa demos), for the
 * programs that draw glxgears' scene: tests/programs/gearsdet.c (renderers compared) and
 * bench/gears_cpu.c (what a frame costs). */
#ifndef GLPT_GLXGEARS_GEAR_H
#define GLPT_GLXGEARS_GEAR_H

#include <GL/gl.h>
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* glxgears' gear(): a gear wheel of `teeth` teeth, flat faces, smooth inner cylinder unless
 * `all_flat` (facing mode). */
static inline void glxgears_gear(GLfloat inner_radius, GLfloat outer_radius, GLfloat width,
                                 GLint teeth, GLfloat tooth_depth, int all_flat) {
  GLint i;
  GLfloat r0, r1, r2;
  GLfloat angle, da;
  GLfloat u, v, len;

  r0 = inner_radius;
  r1 = outer_radius - tooth_depth / 2.0f;
  r2 = outer_radius + tooth_depth / 2.0f;

  da = 2.0f * (GLfloat)M_PI / teeth / 4.0f;

  glShadeModel(GL_FLAT);

  glNormal3f(0.0f, 0.0f, 1.0f);

  /* front face */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; i++) {
    angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
    if (i < teeth) {
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
    }
  }
  glEnd();

  /* front sides of teeth */
  glBegin(GL_QUADS);
  for (i = 0; i < teeth; i++) {
    angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), width * 0.5f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), width * 0.5f);
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
  }
  glEnd();

  glNormal3f(0.0f, 0.0f, -1.0f);

  /* back face */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; i++) {
    angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
    if (i < teeth) {
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
    }
  }
  glEnd();

  /* back sides of teeth */
  glBegin(GL_QUADS);
  for (i = 0; i < teeth; i++) {
    angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), -width * 0.5f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), -width * 0.5f);
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
  }
  glEnd();

  /* outward faces of teeth */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i < teeth; i++) {
    angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
    glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
    u = r2 * cosf(angle + da) - r1 * cosf(angle);
    v = r2 * sinf(angle + da) - r1 * sinf(angle);
    len = sqrtf(u * u + v * v);
    u /= len;
    v /= len;
    glNormal3f(v, -u, 0.0f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), width * 0.5f);
    glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), -width * 0.5f);
    glNormal3f(cosf(angle), sinf(angle), 0.0f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), width * 0.5f);
    glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), -width * 0.5f);
    u = r1 * cosf(angle + 3 * da) - r2 * cosf(angle + 2 * da);
    v = r1 * sinf(angle + 3 * da) - r2 * sinf(angle + 2 * da);
    glNormal3f(v, -u, 0.0f);
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
    glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
    glNormal3f(cosf(angle), sinf(angle), 0.0f);
  }
  glVertex3f(r1 * cosf(0), r1 * sinf(0), width * 0.5f);
  glVertex3f(r1 * cosf(0), r1 * sinf(0), -width * 0.5f);
  glEnd();

  glShadeModel(all_flat ? GL_FLAT : GL_SMOOTH);

  /* inside radius cylinder */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; i++) {
    angle = i * 2.0f * (GLfloat)M_PI / teeth;
    glNormal3f(-cosf(angle), -sinf(angle), 0.0f);
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
    glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
  }
  glEnd();
}

#endif
