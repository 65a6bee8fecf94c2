// Extremes (issue 22): scenes at the edges of what GL 1.x programs send: scales of 1e-6 and 1e6,
// a scene 1e5 from the origin, near/far planes of 1e-4/1e7, triangles from sub-pixel to far
// larger than the view, degenerate and duplicate triangles, NaN and Inf in vertices, normals,
// colours, matrices and light parameters, singular and projective matrices, grazing light,
// 1000 lights, a frame of 1e6 triangles, emission of 1e6 and 1e-6, and parameters GL rejects
// (their errors drawn as pixels). Mesa's answer is the specification, as everywhere in this
// suite; the scenes are named extremes_* and carry the ctest label `extremes`
// (discover_scenes.cmake). tests/extremes/README.md lists them with the path-traced checks.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "scene_util.hpp"

// After the GL declarations (scene_util.hpp's <GL/gl.h>) it calls.
#include "../../common/gl_shapes.hpp"

namespace {

using namespace glpt::conformance::util;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A deterministic generator (the same sequence in both runners).
struct Lcg {
  uint32_t state;
  float next() {  // [0, 1)
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  }
};

using glpt::test_shapes::sphere_around;

// The scene of the scale scenes, in units of 1: a lit sphere, a lit cube and a floor under a
// positional light, seen through a 53-degree frustum from 1 to 20. `s` scales everything (the
// frustum, the light's position and, through glScalef, the geometry); GL_NORMALIZE undoes what
// the scale does to the normals. GL's lighting is scale-invariant with constant attenuation and
// an infinite viewer, so every scale should give the image of scale 1.
void scaled_scene(double s) {
  clear(0.1f, 0.1f, 0.25f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5 * s, 0.5 * s, -0.5 * s, 0.5 * s, 1.0 * s, 20.0 * s);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  const float fs = static_cast<float>(s);
  light4(GL_LIGHT0, GL_POSITION, 2.0f * fs, 3.0f * fs, -1.0f * fs, 1.0f);
  light4(GL_LIGHT0, GL_SPECULAR, 1, 1, 1, 1);
  glEnable(GL_LIGHT0);
  material4(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  glScaled(s, s, s);
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.5f, 0.2f);
  sphere_around(-0.6, 0.1, -5.0, 1.0, 24, 12);
  glPushMatrix();
  glTranslatef(1.2f, -0.4f, -6.0f);
  glRotatef(30, 1, 1, 0);
  material4(GL_FRONT, GL_DIFFUSE, 0.3f, 0.8f, 0.4f);
  cube(0.7f);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0, -1.5f, -6.0f);
  glRotatef(-90, 1, 0, 0);
  material4(GL_FRONT, GL_DIFFUSE, 0.7f, 0.7f, 0.8f);
  grid(-4, -4, 4, 4, 8);
  glPopMatrix();
}

}  // namespace

// The scale scenes at 1e-6 and 1e6: the same image as at scale 1 (the frustum's matrix, the
// normal matrix and the lighting vectors stay well inside float range at both scales).
GLPT_SCENE(extremes_scale_unit, 64, 64) { scaled_scene(1.0); }
GLPT_SCENE(extremes_scale_1e_minus6, 64, 64) { scaled_scene(1e-6); }
GLPT_SCENE(extremes_scale_1e6, 64, 64) { scaled_scene(1e6); }

// A lit sphere and a quad whose vertices are 1e5 from the origin on every axis, seen by a
// modelview that translates them back: float vertices there are 1/128 apart, so the sphere's
// silhouette is slightly quantized, the same in both (the vertex transform is float in both).
GLPT_SCENE(extremes_far_from_origin, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  perspective(40.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  constexpr double kFar = 1e5;
  glTranslated(-kFar, -kFar, -kFar);
  // The light's position goes through the same modelview: eye-space (2, 2, -1).
  light4(GL_LIGHT0, GL_POSITION, static_cast<float>(kFar + 2), static_cast<float>(kFar + 2),
         static_cast<float>(kFar - 1), 1.0f);
  material4(GL_FRONT, GL_DIFFUSE, 0.9f, 0.6f, 0.3f);
  sphere_around(kFar - 0.4, kFar + 0.2, kFar - 5.0, 1.2, 24, 12);
  material4(GL_FRONT, GL_DIFFUSE, 0.4f, 0.7f, 0.9f);
  glBegin(GL_QUADS);
  glNormal3f(0, 1, 0);
  glVertex3d(kFar - 3, kFar - 1.5, kFar - 2);
  glVertex3d(kFar + 3, kFar - 1.5, kFar - 2);
  glVertex3d(kFar + 3, kFar - 1.5, kFar - 12);
  glVertex3d(kFar - 3, kFar - 1.5, kFar - 12);
  glEnd();
}

// Near plane 1e-4, far plane 1e7: a quad 1e-3 in front of the eye in the lower left corner, a
// sphere at 2, a sphere of radius 3e5 at 1e6 and a floor from 1e-2 to 5e6, smooth-coloured. At
// these planes window z of everything beyond ~1e3 rounds to the far plane's, so the far sphere
// and the floor's far end are drawn by GL_LEQUAL in draw order (the floor first). Objects nearer
// than ~1e2 still resolve in 24 bits (the near sphere and the floor in front of it).
GLPT_SCENE(extremes_near_far_planes, 64, 64) {
  clear(0.05f, 0.05f, 0.1f);
  perspective(60.0, 1.0, 1e-4, 1e7);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glShadeModel(GL_SMOOTH);
  // The floor at y = -1, from z = -1e-2 to z = -5e6, colour by distance.
  glBegin(GL_QUAD_STRIP);
  const double zs[] = {-1e-2, -1e-1, -1, -10, -1e2, -1e3, -1e4, -1e5, -1e6, -5e6};
  for (int i = 0; i < 10; ++i) {
    glColor3f(0.2f + 0.08f * i, 0.6f, 0.9f - 0.08f * i);
    glVertex3d(-1e7, -1, zs[i]);
    glVertex3d(1e7, -1, zs[i]);
  }
  glEnd();
  glColor3f(0.9f, 0.9f, 0.3f);
  sphere_around(0.0, 2e5, -1e6, 3e5, 20, 10);
  glColor3f(0.9f, 0.3f, 0.3f);
  sphere_around(0.3, 0.0, -2.0, 0.5, 20, 10);
  glColor3f(0.3f, 0.9f, 0.3f);
  glBegin(GL_QUADS);
  glVertex3f(-4e-4f, -4e-4f, -1e-3f);
  glVertex3f(-2e-4f, -4e-4f, -1e-3f);
  glVertex3f(-2e-4f, -2e-4f, -1e-3f);
  glVertex3f(-4e-4f, -2e-4f, -1e-3f);
  glEnd();
}

// Sub-pixel triangles: in each of the 64 x 64 pixels a triangle 0.05 to 0.8 pixels across at an
// offset that varies with the pixel, so that some contain their pixel's centre (drawn) and some
// do not (nothing), plus 20000 specks of 1/1000 pixel (GL 1.5 3.5.1: a fragment only where a
// pixel centre is inside; none of them is). Both rasterize with llvmpipe's fixed-point rules.
GLPT_SCENE(extremes_subpixel_triangles, 64, 64) {
  clear(0.0f, 0.0f, 0.0f);
  ortho_pixels(64, 64);
  Lcg rng{22u};
  glBegin(GL_TRIANGLES);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const float size = 0.05f + 0.75f * rng.next();
      const float ox = x + rng.next() * (1 - size), oy = y + rng.next() * (1 - size);
      glColor3f(0.2f + 0.8f * x / 64, 0.2f + 0.8f * y / 64, size);
      glVertex2f(ox, oy);
      glVertex2f(ox + size, oy);
      glVertex2f(ox, oy + size);
    }
  }
  glColor3f(1, 1, 1);
  for (int i = 0; i < 20000; ++i) {
    const float x = 64 * rng.next(), y = 64 * rng.next();
    glVertex2f(x, y);
    glVertex2f(x + 1e-3f, y);
    glVertex2f(x, y + 1e-3f);
  }
  glEnd();
}

// Triangles far larger than the view: one smooth-coloured with corners at +-1e6 pixels (its
// colour across the window is an interpolation between far-away vertices), one with a corner
// at 1e30 (clipped, flat colour), one crossing the eye plane in a perspective view (near-plane
// clipping of a triangle reaching 1e6 behind the eye).
GLPT_SCENE(extremes_huge_triangles, 64, 64) {
  clear(0.0f, 0.0f, 0.0f);
  ortho_pixels(64, 64);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(-1e6f, -1e6f);
  glColor3f(0, 1, 0);
  glVertex2f(1e6f, -1e6f);
  glColor3f(0, 0, 1);
  glVertex2f(0.0f, 1e6f);
  glEnd();
  glShadeModel(GL_FLAT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 1, 0);
  glVertex2f(40, 40);
  glVertex2f(1e30f, 40);
  glVertex2f(40, 60);
  glEnd();
  glShadeModel(GL_SMOOTH);
  perspective(60.0, 1.0, 0.5, 100.0);
  glBegin(GL_TRIANGLES);
  glColor3f(0, 1, 1);
  glVertex3f(-2, -1, -3);
  glColor3f(1, 0, 1);
  glVertex3f(0, -1, 1e6f);
  glColor3f(1, 1, 1);
  glVertex3f(-0.5f, 0.5f, -3);
  glEnd();
}

// Degenerate and duplicate triangles: zero-area triangles (a repeated vertex, collinear
// vertices: nothing drawn), two strips stitched by repeated vertices (the degenerate triangles
// between them draw nothing), incomplete primitives (2 vertices of GL_TRIANGLES, 3 of GL_QUADS,
// 2 of GL_POLYGON: nothing), and the same triangle drawn twice: with GL_LESS the first colour
// stays, with GL_LEQUAL the second wins, with additive blending both add.
GLPT_SCENE(extremes_degenerate_duplicate, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLES);
  glVertex2f(5, 5);  // a repeated vertex
  glVertex2f(30, 5);
  glVertex2f(5, 5);
  glVertex2f(5, 10);  // collinear
  glVertex2f(20, 25);
  glVertex2f(35, 40);
  glVertex2f(10, 50);  // all three the same
  glVertex2f(10, 50);
  glVertex2f(10, 50);
  glEnd();
  // Two strips of two quads each, joined by two repeated vertices.
  glColor3f(0.9f, 0.5f, 0.2f);
  glBegin(GL_TRIANGLE_STRIP);
  glVertex2f(2, 12);
  glVertex2f(2, 20);
  glVertex2f(14, 12);
  glVertex2f(14, 20);
  glVertex2f(14, 20);  // stitch
  glVertex2f(18, 12);  // stitch
  glVertex2f(18, 12);
  glVertex2f(18, 20);
  glVertex2f(30, 12);
  glVertex2f(30, 20);
  glEnd();
  glBegin(GL_TRIANGLES);  // incomplete: nothing
  glVertex2f(40, 5);
  glVertex2f(60, 5);
  glEnd();
  glBegin(GL_QUADS);
  glVertex2f(40, 10);
  glVertex2f(60, 10);
  glVertex2f(60, 30);
  glEnd();
  glBegin(GL_POLYGON);
  glVertex2f(40, 40);
  glVertex2f(60, 60);
  glEnd();
  // The same triangle twice, depth-tested.
  glEnable(GL_DEPTH_TEST);
  const float tri[3][2] = {{4, 30}, {30, 30}, {4, 60}};
  for (const GLenum func : {GLenum{GL_LESS}, GLenum{GL_LEQUAL}}) {
    glDepthFunc(func);
    glPushMatrix();
    if (func == GL_LEQUAL) glTranslatef(12, 0, 0);
    for (int copy = 0; copy < 2; ++copy) {
      glColor3f(copy == 0 ? 0.9f : 0.2f, copy == 0 ? 0.2f : 0.9f, 0.3f);
      glBegin(GL_TRIANGLES);
      for (const auto& v : tri) glVertex3f(v[0], v[1], 0.25f);
      glEnd();
    }
    glPopMatrix();
  }
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor3f(0.3f, 0.2f, 0.4f);
  for (int copy = 0; copy < 2; ++copy) {
    glBegin(GL_TRIANGLES);
    glVertex2f(36, 36);
    glVertex2f(62, 36);
    glVertex2f(62, 62);
    glEnd();
  }
  glDisable(GL_BLEND);
}

// NaN and +-Inf in vertex positions (GL accepts them; what such a primitive draws is undefined):
// separate triangles with one bad coordinate each, and a strip with a NaN vertex in its middle,
// among good triangles that must draw as usual. Mesa's clipper drops every primitive with a
// non-finite clip coordinate, and so does glpt.
GLPT_SCENE(extremes_nan_inf_vertices, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  const float bad[] = {kNaN, kInf, -kInf};
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; ++i) {
    for (int coord = 0; coord < 4; ++coord) {  // x, y, z, w
      const float x0 = 4.0f + 15 * i, y0 = 4.0f + 10 * coord;
      glColor3f(0.3f + 0.3f * i, 0.9f - 0.2f * coord, 0.4f);
      glVertex2f(x0, y0);  // a good vertex, a good one, and one with a bad coordinate
      glVertex2f(x0 + 12, y0);
      float v[4] = {x0, y0 + 8, 0, 1};
      v[coord] = bad[i];
      glVertex4fv(v);
      glColor3f(0.9f, 0.9f, 0.9f);  // a good triangle next to it
      glVertex2f(x0 + 12, y0 + 1);
      glVertex2f(x0 + 12, y0 + 8);
      glVertex2f(x0 + 2, y0 + 8);
    }
  }
  glEnd();
  // A strip of 6 vertices whose fourth is NaN: the three triangles using it are dropped, the
  // first is drawn.
  glColor3f(0.9f, 0.6f, 0.1f);
  glBegin(GL_TRIANGLE_STRIP);
  glVertex2f(50, 4);
  glVertex2f(50, 20);
  glVertex2f(62, 4);
  glVertex2f(kNaN, 20);
  glVertex2f(62, 40);
  glVertex2f(50, 40);
  glEnd();
  // The same through a vertex array with glDrawElements.
  const float positions[] = {48, 44, 62, 44, 62, 60, kInf, 60, 48, 60};
  const GLubyte indices[] = {0, 1, 2, 0, 2, 4, 0, 2, 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glColor3f(0.2f, 0.8f, 0.9f);
  glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_BYTE, indices);
  glDisableClientState(GL_VERTEX_ARRAY);
}

// Non-finite colours and extreme normals on finite triangles, where GL's arithmetic defines the
// pixels: colours of +-Inf clamp to 1 and 0 (GL 1.5 2.14.9); lit quads with the normals
// (0, 0, 1), (0, 0, 1e30) (N.L huge: the diffuse term saturates), (0, 0, -1e30) (no diffuse)
// and (0, 0, 1e-15) (N.L tiny: black), below without and above with GL_NORMALIZE (which makes
// all but the back-facing one the unit normal again). Infinite and NaN normals have no defined
// colour: with (0, 0, +Inf) Mesa skips the identity normal transform and gets N.L = +Inf
// (white), glpt multiplies by the matrix, 0 * Inf = NaN (black); tests/extremes checks that such
// normals stay finite in the image and leave their neighbours alone. A checkered quad textured
// as usual sits among them (texel edges on pixel edges: no ties).
GLPT_SCENE(extremes_nan_inf_attributes, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  glColor3f(kInf, -kInf, 0.5f);
  quad(2, 2, 20, 20);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1.0f, 0.0f);
  material4(GL_FRONT, GL_DIFFUSE, 0.8f, 0.6f, 0.4f);
  const float normals[][3] = {{0, 0, 1}, {0, 0, 1e30f}, {0, 0, -1e30f}, {0, 0, 1e-15f}};
  for (const bool normalize : {false, true}) {
    if (normalize) glEnable(GL_NORMALIZE);
    const float y0 = normalize ? 34.0f : 2.0f;
    for (int i = 0; i < 4; ++i) {
      glBegin(GL_QUADS);
      glNormal3fv(normals[i]);
      glVertex2f(24.0f + 10 * i, y0);
      glVertex2f(32.0f + 10 * i, y0);
      glVertex2f(32.0f + 10 * i, y0 + 28);
      glVertex2f(24.0f + 10 * i, y0 + 28);
      glEnd();
    }
  }
  glDisable(GL_LIGHTING);
  texture_2d(GL_RGBA, 8, 8, checker(8, 8, 2, {255, 255, 255, 255}, {40, 80, 200, 255}));
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  quad(2, 24, 18, 40);
  glDisable(GL_TEXTURE_2D);
  // Mesa's glGetIntegerv(GL_CURRENT_NORMAL) of a huge normal overflows (INT_MIN), glpt saturates:
  // the state comparison is not about that.
  glNormal3f(0, 0, 1);
}

// Non-finite matrices: a modelview loaded with a NaN, one scaled by Inf, a rotation by a NaN
// angle, a projection with an Inf: every vertex transformed by them is non-finite and the draw
// is dropped; the good draws between them are drawn as usual. GL raises no error for any of it.
GLPT_SCENE(extremes_nan_inf_matrices, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  auto square = [](float x, float y, float r, float g, float b) {
    glColor3f(r, g, b);
    quad(x, y, x + 12, y + 12);
  };
  square(2, 2, 0.9f, 0.9f, 0.9f);
  float nan_matrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  nan_matrix[12] = kNaN;
  glPushMatrix();
  glLoadMatrixf(nan_matrix);
  square(18, 2, 1, 0, 0);
  glPopMatrix();
  square(34, 2, 0.2f, 0.9f, 0.2f);
  glPushMatrix();
  glScalef(kInf, 1, 1);
  square(50, 2, 1, 0, 0);
  glPopMatrix();
  glPushMatrix();
  glRotatef(kNaN, 0, 0, 1);
  square(2, 20, 1, 0, 0);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0, kInf, 0);
  square(18, 20, 1, 0, 0);
  glPopMatrix();
  square(34, 20, 0.2f, 0.2f, 0.9f);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glMultMatrixf(nan_matrix);
  glMatrixMode(GL_MODELVIEW);
  square(50, 20, 1, 0, 0);
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  square(2, 40, 0.9f, 0.6f, 0.2f);
  // GL_LIGHT1 positioned under the NaN modelview (its eye-space position is NaN) stays
  // disabled: the quad lit by GL_LIGHT2 next to it must not see it.
  glEnable(GL_LIGHTING);
  glPushMatrix();
  glLoadMatrixf(nan_matrix);
  light4(GL_LIGHT1, GL_POSITION, 0, 0, 1, 1);
  glPopMatrix();
  light4(GL_LIGHT2, GL_POSITION, 0, 0, 1, 0);
  light4(GL_LIGHT2, GL_DIFFUSE, 0.6f, 0.8f, 0.3f, 1);
  glEnable(GL_LIGHT2);
  glNormal3f(0, 0, 1);
  square(18, 40, 0, 0, 0);
  glDisable(GL_LIGHTING);
}

// Light parameters at and beyond float's range, where GL's arithmetic still defines the pixels:
// each of six spheres is lit by GL_LIGHT0 re-specified with one extreme value: diffuse 1e30
// (saturates where N.L > 0, black where N.L <= 0), a positional light at 1e15 (its squared
// distance 3e30 still a float: lit from (1, 1, 1) as a directional light), a spot direction of NaN
// (the cone test fails: outside the cone), linear attenuation +Inf (the light adds nothing),
// specular 1e30 (saturated highlights), light-model ambient +Inf (clamps to 1). GL accepts them all
// (its range checks are on spot exponent, cutoff, attenuation signs). NaN ambient and NaN positions
// have no defined colour, and neither has a position of 1e30, whose squared distance overflows
// to Inf (Mesa keeps the light's ambient, glpt loses the whole light to 0 * Inf = NaN):
// tests/extremes checks those for finite output.
GLPT_SCENE(extremes_nan_inf_lights, 96, 64) {
  clear(0.1f, 0.1f, 0.25f);
  perspective(40.0, 1.5, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  material4(GL_FRONT, GL_DIFFUSE, 0.8f, 0.6f, 0.4f);
  material4(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  for (int i = 0; i < 6; ++i) {
    // Good defaults for the light, then the one extreme value.
    light4(GL_LIGHT0, GL_POSITION, 2, 2, 2, 0);
    light4(GL_LIGHT0, GL_DIFFUSE, 1, 1, 1, 1);
    light4(GL_LIGHT0, GL_SPECULAR, 0, 0, 0, 1);
    light4(GL_LIGHT0, GL_AMBIENT, 0.1f, 0.1f, 0.1f, 1);
    light4(GL_LIGHT0, GL_SPOT_DIRECTION, 0, 0, -1, 0);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
    light_model4(GL_LIGHT_MODEL_AMBIENT, 0.2f, 0.2f, 0.2f);
    switch (i) {
      case 0:
        light4(GL_LIGHT0, GL_DIFFUSE, 1e30f, 1, 1, 1);
        break;
      case 1:
        light4(GL_LIGHT0, GL_POSITION, 1e15f, 1e15f, 1e15f, 1);
        break;
      case 2:
        light4(GL_LIGHT0, GL_POSITION, 0, 0, 2, 1);
        light4(GL_LIGHT0, GL_SPOT_DIRECTION, kNaN, 0, -1, 0);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30);
        break;
      case 3:
        light4(GL_LIGHT0, GL_POSITION, 0, 0, 2, 1);
        glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, kInf);
        break;
      case 4:
        light4(GL_LIGHT0, GL_SPECULAR, 1e30f, 1e30f, 1e30f, 1);
        break;
      default:
        light_model4(GL_LIGHT_MODEL_AMBIENT, kInf, 0.2f, 0.2f);
        break;
    }
    sphere_around(-2.4 + 2.4 * (i % 3), i < 3 ? 1.1 : -1.1, -7.0, 0.9, 16, 8);
  }
  // Mesa's integer queries of these overflow (x86's INT_MIN) where glpt saturates; the state
  // comparison is not about that: good values back.
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0.2f, 0.2f, 0.2f);
  light4(GL_LIGHT0, GL_SPECULAR, 1, 1, 1, 1);
}

// Parameters GL rejects, each with the error GL 1.5 names (and Mesa raises), drawn as a row of
// swatches (green: no error, red: GL_INVALID_VALUE, blue: GL_INVALID_ENUM, yellow:
// GL_INVALID_OPERATION, white: anything else) so that the image compares them: glFrustum with a
// near plane of 0 or -1, near = far, left = right; glOrtho with left = right; glViewport of
// negative width; spot exponent 129 and +Inf; spot cutoff 91; negative attenuation; shininess
// 129; line width 0; point size -1; fog density -1; glDepthRange(NaN, Inf) (clamped, no error).
// Below the swatches, a lit sphere under the light as those calls left it (the rejected ones
// left it unchanged). NaN for these parameters is where glpt deliberately differs: GL 1.5 2.1.1
// leaves it unspecified, Mesa's range checks let NaN through into the state, glpt raises
// GL_INVALID_VALUE and keeps the state (tests/extremes checks that).
GLPT_SCENE(extremes_rejected_parameters, 64, 64) {
  std::vector<GLenum> errors;
  auto record = [&errors] { errors.push_back(glGetError()); };
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 0, 10);
  record();
  glFrustum(-1, 1, -1, 1, -1, 10);
  record();
  glFrustum(-1, 1, -1, 1, 2, 2);
  record();
  glFrustum(1, 1, -1, 1, 1, 10);
  record();
  glOrtho(0, 0, -1, 1, -1, 1);
  record();
  glMatrixMode(GL_MODELVIEW);
  glViewport(0, 0, -1, 64);
  record();
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129);
  record();
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, kInf);
  record();
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 91);
  record();
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, -1);
  record();
  glMaterialf(GL_FRONT, GL_SHININESS, 129);
  record();
  glLineWidth(0);
  record();
  glPointSize(-1);
  record();
  glFogf(GL_FOG_DENSITY, -1);
  record();
  glDepthRange(kNaN, kInf);
  record();
  glDepthRange(0, 1);

  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  for (size_t i = 0; i < errors.size(); ++i) {
    switch (errors[i]) {
      case GL_NO_ERROR:
        glColor3f(0, 1, 0);
        break;
      case GL_INVALID_VALUE:
        glColor3f(1, 0, 0);
        break;
      case GL_INVALID_ENUM:
        glColor3f(0, 0, 1);
        break;
      case GL_INVALID_OPERATION:
        glColor3f(1, 1, 0);
        break;
      default:
        glColor3f(1, 1, 1);
        break;
    }
    const float x = 2.0f + 5 * static_cast<float>(i % 12),
                y = 56.0f - 6 * static_cast<float>(i / 12);
    quad(x, y, x + 4, y + 4);
  }
  // The light as the accepted calls left it, on a sphere.
  perspective(40.0, 1.0, 1.0, 20.0);
  glViewport(0, 0, 64, 44);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 0, 0, 1, 1);
  light4(GL_LIGHT0, GL_SPOT_DIRECTION, 0, 0, -1, 0);
  material4(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f);
  glMaterialf(GL_FRONT, GL_SHININESS, 30);  // accepted, after the rejected 129
  sphere_around(0.0, 0.0, -5.0, 1.3, 24, 12);
}

// Singular modelviews: a sphere flattened by glScalef(1, 1, 0) (its normal matrix, the inverse
// transpose, does not exist: GL 1.5 2.11.3 leaves the normals undefined), one scaled by 0
// (a point: nothing or one pixel), and a modelview of rank 2 (two equal rows); a singular
// projection (a zero row: every w 0). Lighting with GL_NORMALIZE on.
GLPT_SCENE(extremes_singular_matrices, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  perspective(40.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  light4(GL_LIGHT0, GL_POSITION, 1, 1, 1, 0);
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.6f, 0.4f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glPushMatrix();
  glTranslatef(-1.0f, 0.8f, -6.0f);
  glScalef(1, 1, 0);
  sphere_around(0, 0, 0, 0.9, 16, 8);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(1.0f, 0.8f, -6.0f);
  glScalef(0, 0, 0);
  sphere_around(0, 0, 0, 0.9, 16, 8);
  glPopMatrix();
  glPushMatrix();
  // Rows x and y equal: every vertex lands on the line x = y.
  const float rank2[16] = {1, 1, 0, 0, 0.3f, 0.3f, 0, 0, 0, 0, 1, 0, -1.0f, -0.8f, -6.0f, 1};
  glLoadMatrixf(rank2);
  sphere_around(0, 0, 0, 0.9, 16, 8);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  float projection[16];
  glGetFloatv(GL_PROJECTION_MATRIX, projection);
  projection[3] = projection[7] = projection[11] = projection[15] = 0;  // w = 0 everywhere
  glLoadMatrixf(projection);
  glMatrixMode(GL_MODELVIEW);
  sphere_around(1.0, -0.8, -6.0, 0.9, 16, 8);
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  // A good sphere to compare against.
  sphere_around(0.0, -0.2, -8.0, 0.5, 16, 8);
}

// Projective matrices and homogeneous vertices: a modelview whose bottom row makes w vary with
// x (eye coordinates are projective; lighting uses them as GL 1.5 2.14.1 says), vertices with
// w = 0.5 and 2 (the same points as w = 1 scaled), a triangle whose vertices are all at
// negative w (GL clips it away entirely), and a triangle with one vertex of negative w (it
// spans the plane at infinity: GL clips to the part in front of the eye).
GLPT_SCENE(extremes_projective_matrices, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  perspective(50.0, 1.0, 1.0, 50.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 1, 1, 2, 0);
  glEnable(GL_COLOR_MATERIAL);
  glPushMatrix();
  glTranslatef(-0.8f, 0.6f, -5);
  const float projective[16] = {1, 0, 0, 0.25f, 0, 1, 0, 0, 0, 0, 1, 0.05f, 0, 0, 0, 1};
  glMultMatrixf(projective);
  glColor3f(0.9f, 0.6f, 0.3f);
  sphere_around(0, 0, 0, 0.9, 16, 8);
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  // Homogeneous vertices: (x, y, z) * w.
  glColor3f(0.3f, 0.9f, 0.4f);
  glVertex4f(0.2f * 0.5f, 0.2f * 0.5f, -5 * 0.5f, 0.5f);
  glVertex4f(2.0f * 2, 0.2f * 2, -5.0f * 2, 2);
  glVertex4f(1.0f, 2.0f, -5.0f, 1);
  // All at negative w.
  glColor3f(1, 0, 0);
  glVertex4f(0.2f, 0.2f, 5, -1);
  glVertex4f(2.0f, 0.2f, 5, -1);
  glVertex4f(1.0f, 2.0f, 5, -1);
  // One vertex at negative w.
  glColor3f(0.3f, 0.5f, 1.0f);
  glVertex4f(-2.0f, -2.0f, -6, 1);
  glVertex4f(0.0f, -0.5f, -6, 1);
  glVertex4f(-0.5f, -1.5f, 6, -1);
  glEnd();
}

// Grazing light: a plane lit by a directional light 0.01 degrees above its horizon (N.L about
// 2e-4), one exactly on it (N.L = 0: no diffuse, no specular), spot lights whose cone edge
// grazes the plane, and specular highlights of shininess 128 at a grazing half vector, with a
// local viewer. Colours tiny but not zero: the rounding of both is compared.
GLPT_SCENE(extremes_grazing_light, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  perspective(50.0, 1.0, 1.0, 50.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0, 0, 0);
  const double grazing = 0.01 * kPi / 180;
  // Directional lights along the floor (normal +y): 0.01 degrees above it and exactly on it.
  light4(GL_LIGHT0, GL_POSITION, 0, static_cast<float>(std::sin(grazing)),
         static_cast<float>(-std::cos(grazing)), 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 1000, 1000, 1000, 1);  // 2e-4 * 1000: a visible 0.2
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT1, GL_POSITION, 1, 0, 0, 0);
  light4(GL_LIGHT1, GL_SPECULAR, 1, 1, 1, 1);
  glEnable(GL_LIGHT1);
  // A spot light just above the floor pointing along it, cone edge grazing.
  light4(GL_LIGHT2, GL_POSITION, 0, -0.99f, -4, 1);
  light4(GL_LIGHT2, GL_SPOT_DIRECTION, 0, -0.2f, -1, 0);
  light4(GL_LIGHT2, GL_DIFFUSE, 0.2f, 0.9f, 0.3f, 1);
  light4(GL_LIGHT2, GL_SPECULAR, 1, 1, 1, 1);
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 12);
  glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 2);
  glEnable(GL_LIGHT2);
  material4(GL_FRONT, GL_DIFFUSE, 0.8f, 0.6f, 0.4f);
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 128);
  glPushMatrix();
  glTranslatef(0, -1, -8);
  glRotatef(-90, 1, 0, 0);
  grid(-6, -7, 6, 7, 24);
  glPopMatrix();
  // A sphere whose terminator the near-horizontal light draws.
  sphere_around(1.2, 0.3, -7.0, 0.8, 24, 12);
  // Mesa's glGetLightiv of a colour of 1000 overflows (x86's INT_MIN), glpt saturates; the
  // state comparison is not about that.
  light4(GL_LIGHT0, GL_DIFFUSE, 1, 1, 1, 1);
}

// 1000 lights: 125 draws (a 5 x 25 grid of quads), each lit by its own 8 lights at positions and
// colours that vary with the draw (GL has 8 lights per draw; the lights of all draws together
// are 1000). Positional lights with attenuation, diffuse and specular: every quad shows its own
// lights only.
GLPT_SCENE(extremes_thousand_lights, 64, 64) {
  clear(0.0f, 0.0f, 0.0f);
  ortho_pixels(64, 64);
  glEnable(GL_LIGHTING);
  light_model4(GL_LIGHT_MODEL_AMBIENT, 0, 0, 0);
  material4(GL_FRONT, GL_DIFFUSE, 1, 1, 1);
  material4(GL_FRONT, GL_SPECULAR, 0.3f, 0.3f, 0.3f);
  glMaterialf(GL_FRONT, GL_SHININESS, 16);
  for (int l = 0; l < 8; ++l) glEnable(static_cast<GLenum>(GL_LIGHT0 + l));
  for (int d = 0; d < 125; ++d) {
    const int column = d % 25, row = d / 25;
    const float x0 = 0.5f + 2.5f * column, y0 = 0.5f + 12.6f * row;
    for (int l = 0; l < 8; ++l) {
      const GLenum light = static_cast<GLenum>(GL_LIGHT0 + l);
      const int k = d * 8 + l;
      const float h = static_cast<float>(k % 7) / 7.0f;
      light4(light, GL_POSITION, x0 + 2.5f * static_cast<float>(l % 2),
             y0 + 12.0f * static_cast<float>(l) / 8.0f, 3.0f + static_cast<float>(k % 5), 1);
      light4(light, GL_DIFFUSE, 0.05f + 0.2f * h, 0.05f + 0.2f * (1 - h),
             0.05f + 0.1f * static_cast<float>(k % 3), 1);
      light4(light, GL_SPECULAR, 0.1f, 0.1f, 0.1f, 1);
      glLightf(light, GL_LINEAR_ATTENUATION, 0.05f);
    }
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    // Tessellated in y so that per-vertex lighting follows the lights along the quad.
    for (int s = 0; s < 6; ++s) {
      const float ya = y0 + 2.0f * s, yb = ya + 2.0f;
      glVertex2f(x0, ya);
      glVertex2f(x0 + 2.5f, ya);
      glVertex2f(x0 + 2.5f, yb);
      glVertex2f(x0, yb);
    }
    glEnd();
  }
}

// A frame of 1e6 triangles: a 500 x 1000 grid of quads covering the window, each 0.128 x 0.064
// pixels, drawn with glDrawArrays and additive blending of a colour that varies across the
// window. The mesh is watertight, so GL's rasterization rules put exactly one fragment on every
// pixel (a crack would leave the clear colour, an overlap would add twice).
GLPT_SCENE(extremes_million_triangles, 64, 64) {
  clear(0.0f, 0.0f, 0.0f);
  ortho_pixels(64, 64);
  constexpr int kColumns = 500, kRows = 1000;
  std::vector<float> positions;
  std::vector<GLubyte> colours;
  positions.reserve(size_t{kColumns} * kRows * 12);
  colours.reserve(size_t{kColumns} * kRows * 24);
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kColumns; ++c) {
      const float x0 = 64.0f * c / kColumns, x1 = 64.0f * (c + 1) / kColumns;
      const float y0 = 64.0f * r / kRows, y1 = 64.0f * (r + 1) / kRows;
      const float quad_corners[6][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}};
      const GLubyte red = static_cast<GLubyte>(40 + 160 * c / kColumns);
      const GLubyte green = static_cast<GLubyte>(40 + 160 * r / kRows);
      for (const auto& p : quad_corners) {
        positions.push_back(p[0]);
        positions.push_back(p[1]);
        colours.insert(colours.end(), {red, green, 100, 255});
      }
    }
  }
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glShadeModel(GL_FLAT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions.data());
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colours.data());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(positions.size() / 2));
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisable(GL_BLEND);
}

// Emission of 1e6 (saturates to white), 1e-6 (rounds to black), -1e6 (clamps to black, GL 1.5
// 2.14.9) and +Inf on lit spheres, next to a sphere of ordinary emission 0.3.
GLPT_SCENE(extremes_emission, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  perspective(40.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, 1, 1, 1, 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 1);
  const float emissions[][3] = {
      {1e6f, 1e6f, 1e6f}, {1e-6f, 1e-6f, 1e-6f}, {-1e6f, 0, 0}, {kInf, 0.3f, 0}, {0.3f, 0.2f, 0}};
  for (int i = 0; i < 5; ++i) {
    material4(GL_FRONT, GL_EMISSION, emissions[i][0], emissions[i][1], emissions[i][2]);
    sphere_around(-1.6 + 1.6 * (i % 3), i < 3 ? 0.9 : -0.9, -7.0, 0.7, 16, 8);
  }
}
