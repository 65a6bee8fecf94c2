// User clip planes (GL 1.5 2.12): planes are transformed by the inverse of the modelview current
// at glClipPlane time and clip in eye space.
#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

void clip_plane(GLenum plane, double a, double b, double c, double d) {
  const double equation[4] = {a, b, c, d};
  glClipPlane(plane, equation);
}

// A lit sphere (two-sided: the inside shows through the cut in the back material).
void begin_clip_view() {
  clear(0.1f, 0.1f, 0.25f);
  lit_perspective_light0(35.0, 1.0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.7f, 0.3f);
  material4(GL_BACK, GL_DIFFUSE, 0.3f, 0.7f, 0.9f);
}

// One oblique plane (specified in eye space: identity modelview) cuts the near cap off a
// sphere: the inside of the far half shows, lit with the back material.
GLPT_SCENE(clip_plane_single, 64, 64) {
  begin_clip_view();
  clip_plane(GL_CLIP_PLANE0, 0.3, 0.2, -1.0, -3.7);
  glEnable(GL_CLIP_PLANE0);
  glTranslatef(0, 0, -4);
  sphere(1.2f, 32, 16);
}

// Three planes at once carve a wedge out of the sphere; planes 1 and 4 (not only 0) are used.
GLPT_SCENE(clip_planes_several, 64, 64) {
  begin_clip_view();
  glTranslatef(0, 0, -4);
  clip_plane(GL_CLIP_PLANE1, 1, 0, 0, 0.5);
  clip_plane(GL_CLIP_PLANE4, 0, -1, 0, 0.7);
  clip_plane(GL_CLIP_PLANE5, -1, 1, 0, 0.8);
  glEnable(GL_CLIP_PLANE1);
  glEnable(GL_CLIP_PLANE4);
  glEnable(GL_CLIP_PLANE5);
  glRotatef(30, 0, 1, 0);
  sphere(1.2f, 32, 16);
}

// A plane given under a rotated modelview (y = 0 rotated by 45 degrees about z), then the
// sphere drawn under a different modelview: the cut stays where the plane was defined.
GLPT_SCENE(clip_plane_rotated_modelview, 64, 64) {
  begin_clip_view();
  glPushMatrix();
  glTranslatef(0, 0, -4);
  glRotatef(45, 0, 0, 1);
  glRotatef(30, 1, 0, 0);
  clip_plane(GL_CLIP_PLANE2, 0, 1, 0, 0);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE2);
  glTranslatef(0.2f, 0, -4);
  glRotatef(70, 0, 1, 0);
  sphere(1.2f, 32, 16);
}

// Lines and points are clipped too: a fan of lines and a grid of points against two planes.
GLPT_SCENE(clip_planes_lines_and_points, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  clip_plane(GL_CLIP_PLANE0, 1, 0.5, 0, -20);   // keeps x + y/2 >= 20
  clip_plane(GL_CLIP_PLANE3, -0.3, -1, 0, 58);  // keeps 0.3x + y <= 58
  glEnable(GL_CLIP_PLANE0);
  glEnable(GL_CLIP_PLANE3);
  glBegin(GL_LINES);
  for (int i = 0; i < 8; ++i) {
    glColor3f(1, 0.3f + 0.09f * i, 0.2f);
    glVertex2f(2.5f, 2.5f + 8 * i);
    glVertex2f(61.5f, 60.5f - 7 * i);
  }
  glEnd();
  glPointSize(3);
  glBegin(GL_POINTS);
  glColor3f(0.3f, 0.8f, 1);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) glVertex2f(4.5f + 8 * x, 4.5f + 8 * y);
  }
  glEnd();
}

}  // namespace
