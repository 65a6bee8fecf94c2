// Flat and smooth shading for every primitive type (GL 1.5 2.14.7): with GL_FLAT each
// primitive takes the colour of its provoking vertex (table 2.12): independent lines 2i,
// strips and loops i+1, triangles 3i, triangle strips and fans i+2, quads 4i, quad strips 2i+2,
// polygons the first vertex.
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// Eight distinct colours, cycled per vertex, so that every vertex of a primitive differs.
void vertex_colour(int i) {
  static const float kPalette[8][3] = {{1, 0.1f, 0.1f}, {0.1f, 1, 0.1f},   {0.2f, 0.3f, 1},
                                       {1, 1, 0.1f},    {1, 0.2f, 1},      {0.1f, 1, 1},
                                       {1, 0.6f, 0.1f}, {0.7f, 0.7f, 0.7f}};
  glColor3fv(kPalette[i % 8]);
}

void begin_shading(int width, int height, GLenum model) {
  clear(0.08f, 0.08f, 0.08f);
  ortho_pixels(width, height);
  glShadeModel(model);
}

void triangles(GLenum model) {
  begin_shading(64, 64, model);
  const float v[9][2] = {{4, 4},   {30, 8}, {12, 30}, {34, 6}, {60, 12},
                         {40, 34}, {8, 36}, {56, 40}, {28, 60}};
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 9; ++i) {
    vertex_colour(i);
    glVertex2fv(v[i]);
  }
  glEnd();
}

void triangle_strip() {
  begin_shading(64, 64, GL_FLAT);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 10; ++i) {
    vertex_colour(i);
    glVertex2f(4.0f + 13.5f * static_cast<float>(i / 2), i % 2 == 0 ? 10.0f : 50.0f);
  }
  glEnd();
}

void triangle_fan() {
  begin_shading(64, 64, GL_FLAT);
  glBegin(GL_TRIANGLE_FAN);
  vertex_colour(0);
  glVertex2f(32, 30);
  for (int i = 0; i <= 7; ++i) {
    const double a = 2 * kPi * i / 8 + 0.2;
    vertex_colour(i + 1);
    glVertex2f(static_cast<float>(32 + 28 * std::cos(a)),
               static_cast<float>(30 + 26 * std::sin(a)));
  }
  glEnd();
}

void quads(GLenum model) {
  begin_shading(64, 64, model);
  const float v[8][2] = {{4, 4},   {30, 6},  {28, 30}, {6, 26},
                         {34, 20}, {60, 30}, {54, 60}, {30, 52}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 8; ++i) {
    vertex_colour(i);
    glVertex2fv(v[i]);
  }
  glEnd();
}

void quad_strip() {
  begin_shading(64, 64, GL_FLAT);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < 10; ++i) {
    vertex_colour(i);
    const float x = 4.0f + 14.0f * static_cast<float>(i / 2);
    glVertex2f(x, i % 2 == 0 ? 8.0f + 3 * static_cast<float>(i / 2) : 56.0f);
  }
  glEnd();
}

void polygon(GLenum model) {
  begin_shading(64, 64, model);
  glBegin(GL_POLYGON);
  for (int i = 0; i < 7; ++i) {
    const double a = 2 * kPi * i / 7 + 0.3;
    vertex_colour(i + 2);  // the first vertex is not colour 0: a mistake shows
    glVertex2f(static_cast<float>(32 + 28 * std::cos(a)),
               static_cast<float>(32 + 28 * std::sin(a)));
  }
  glEnd();
}

// A zig-zag of vertices; each primitive type connects them differently.
void lines(GLenum mode, GLenum model) {
  begin_shading(64, 64, model);
  glBegin(mode);
  for (int i = 0; i < 12; ++i) {
    const double a = 2 * kPi * i / 12;
    const double r = i % 2 == 0 ? 28 : 14;
    vertex_colour(i);
    glVertex2f(static_cast<float>(32.3 + r * std::cos(a)),
               static_cast<float>(31.7 + r * std::sin(a)));
  }
  glEnd();
}

GLPT_SCENE(shading_flat_triangles, 64, 64) { triangles(GL_FLAT); }
GLPT_SCENE(shading_flat_triangle_strip, 64, 64) { triangle_strip(); }
GLPT_SCENE(shading_flat_triangle_fan, 64, 64) { triangle_fan(); }
GLPT_SCENE(shading_flat_quads, 64, 64) { quads(GL_FLAT); }
GLPT_SCENE(shading_flat_quad_strip, 64, 64) { quad_strip(); }
GLPT_SCENE(shading_flat_polygon, 64, 64) { polygon(GL_FLAT); }
GLPT_SCENE(shading_flat_lines, 64, 64) { lines(GL_LINES, GL_FLAT); }
GLPT_SCENE(shading_flat_line_strip, 64, 64) { lines(GL_LINE_STRIP, GL_FLAT); }
GLPT_SCENE(shading_flat_line_loop, 64, 64) { lines(GL_LINE_LOOP, GL_FLAT); }
GLPT_SCENE(shading_smooth_triangles, 64, 64) { triangles(GL_SMOOTH); }
GLPT_SCENE(shading_smooth_quads, 64, 64) { quads(GL_SMOOTH); }
GLPT_SCENE(shading_smooth_polygon, 64, 64) { polygon(GL_SMOOTH); }
GLPT_SCENE(shading_smooth_line_loop, 64, 64) { lines(GL_LINE_LOOP, GL_SMOOTH); }

// Flat shading of lit geometry: the provoking vertex's lit colour (its normal) colours the
// whole primitive; a faceted sphere.
GLPT_SCENE(shading_flat_lit_sphere, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  lit_perspective_light0(35.0, 1.0);
  glShadeModel(GL_FLAT);
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.6f, 0.3f);
  glTranslatef(0, 0, -4);
  glRotatef(20, 1, 0, 0);
  sphere(1.1f, 12, 8);
}

}  // namespace
