// Evaluators (GL 1.5 5.1): Bezier curves and patches through glMap1/glMap2, drawn with
// glEvalMesh in each mode, glEvalCoord and glEvalPoint, with evaluated colours, texture
// coordinates and normals (GL_AUTO_NORMAL), rational maps, and maps compiled into display lists.
//
// Every scene ends by setting the current colour, normal and texture coordinates: Mesa leaves
// stale values there after evaluating an attribute its vertex did not hold yet (its vbo module
// restores a slot it never initialized), where GL 1.5 5.1 and glpt keep the current values; the
// state dumps then compare what both define.
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A 4 x 4 bicubic patch over [-1.5, 1.5]^2 with a bump in the middle and a raised corner, u along
// x (the first index, 12 floats apart) and v along y (3 apart).
struct Patch {
  GLfloat p[4][4][3];
};
Patch bump_patch(float bump) {
  Patch patch{};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      patch.p[i][j][0] = -1.5f + static_cast<float>(i);
      patch.p[i][j][1] = -1.5f + static_cast<float>(j);
      const bool inner = (i == 1 || i == 2) && (j == 1 || j == 2);
      patch.p[i][j][2] = inner ? bump : (i == 3 && j == 3 ? 1.0f : -0.5f);
    }
  }
  return patch;
}

// Colours at the corners of a bilinear 2 x 2 colour map.
const GLfloat kCornerColours[2][2][4] = {{{1, 0.2f, 0.2f, 1}, {0.2f, 1, 0.2f, 1}},
                                         {{0.2f, 0.3f, 1, 1}, {1, 1, 0.2f, 1}}};

// Loads bump_patch(bump) as the enabled GL_MAP2_VERTEX_3 and, with `colours`, kCornerColours as
// the enabled GL_MAP2_COLOR_4.
void load_bump_patch(float bump, bool colours) {
  const Patch patch = bump_patch(bump);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch.p[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  if (colours) {
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 8, 2, 0, 1, 4, 2, &kCornerColours[0][0][0]);
    glEnable(GL_MAP2_COLOR_4);
  }
}

void settle_current_values() {
  glColor4f(1, 1, 1, 1);
  glNormal3f(0, 0, 1);
  glTexCoord4f(0, 0, 0, 1);
}

// A lit bicubic patch, normals from GL_AUTO_NORMAL, as triangle strips (glEvalMesh2 GL_FILL) on
// a 10 x 10 grid, tilted towards the viewer. The image: a shaded bump on a blue background.
GLPT_SCENE(evaluators_patch_lit, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  lit_perspective_light0(40.0, 1.0);
  load_bump_patch(1.6f, false);
  glEnable(GL_AUTO_NORMAL);
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f, 0.7f, 0.4f);
  material4(GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
  glTranslatef(0, 0, -6);
  glRotatef(-40, 1, 0, 0);
  glRotatef(15, 0, 0, 1);
  glMapGrid2f(10, 0, 1, 10, 0, 1);
  glEvalMesh2(GL_FILL, 0, 10, 0, 10);
  settle_current_values();
}

// A patch with evaluated colours and texture coordinates (a checkerboard, modulated), unlit:
// glEvalMesh2 GL_FILL over part of a grid whose domain is larger than the maps'.
GLPT_SCENE(evaluators_patch_colour_texture, 64, 64) {
  clear(0.2f, 0.2f, 0.2f);
  perspective(40.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  texture_2d(GL_RGBA, 16, 16, checker(16, 16, 4, {255, 255, 255, 255}, {60, 60, 60, 255}));
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  load_bump_patch(-1.0f, true);
  const GLfloat st[2][2][2] = {{{0, 0}, {0, 3}}, {{3, 0}, {3, 3}}};
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 4, 2, 0, 1, 2, 2, &st[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glTranslatef(0, 0, -5.5f);
  glRotatef(-30, 1, 0, 0);
  glMapGrid2f(16, -0.25f, 1.25f, 12, -0.25f, 1.25f);
  glEvalMesh2(GL_FILL, 2, 14, 1, 11);
  settle_current_values();
}

// The same kind of patch as a wireframe: glEvalMesh2 GL_LINE (the rows, then the columns, as
// line strips) with evaluated colours, depth-tested.
GLPT_SCENE(evaluators_mesh_lines, 64, 64) {
  clear(0.05f, 0.05f, 0.1f);
  perspective(40.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  load_bump_patch(1.8f, true);
  glTranslatef(0, 0, -6);
  glRotatef(-50, 1, 0, 0);
  glRotatef(20, 0, 0, 1);
  glMapGrid2f(12, 0, 1, 8, 0, 1);
  glEvalMesh2(GL_LINE, 0, 12, 0, 8);
  settle_current_values();
}

// The patch's grid points (glEvalMesh2 GL_POINT), 3-pixel points with evaluated colours, and a
// few glEvalPoint2 points of another grid in white.
GLPT_SCENE(evaluators_mesh_points, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  perspective(40.0, 1.0, 1.0, 20.0);
  load_bump_patch(1.2f, true);
  glPointSize(3);
  glTranslatef(0, 0, -5.5f);
  glRotatef(-35, 1, 0, 0);
  glMapGrid2f(9, 0, 1, 9, 0, 1);
  glEvalMesh2(GL_POINT, 0, 9, 0, 9);
  glDisable(GL_MAP2_COLOR_4);
  glColor3f(1, 1, 1);
  glMapGrid2d(4, 0.1, 0.9, 4, 0.1, 0.9);
  glPointSize(2);
  glBegin(GL_POINTS);
  for (int i = 0; i <= 4; ++i) glEvalPoint2(i, 4 - i);
  glEnd();
  settle_current_values();
}

// Curves: a rational quadratic (GL_MAP1_VERTEX_4, a quarter circle) and a cubic with evaluated
// colours, through glEvalMesh1 GL_LINE and GL_POINT, glEvalCoord1 and glEvalPoint1, 2-pixel
// lines in a pixel-unit view.
GLPT_SCENE(evaluators_curves, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  const float w = static_cast<float>(std::sqrt(0.5));
  const GLfloat arc[3][4] = {{60, 4, 0, 1}, {60 * w, 60 * w, 0, w}, {4, 60, 0, 1}};
  glMap1f(GL_MAP1_VERTEX_4, 0, 1, 4, 3, &arc[0][0]);
  glEnable(GL_MAP1_VERTEX_4);
  glColor3f(1, 0.8f, 0.2f);
  glLineWidth(2);
  glMapGrid1f(20, 0, 1);
  glEvalMesh1(GL_LINE, 0, 20);
  glDisable(GL_MAP1_VERTEX_4);
  const GLfloat cubic[4][3] = {{4, 30, 0}, {20, 62, 0}, {40, -10, 0}, {60, 40, 0}};
  const GLfloat colours[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0.2f, 0.4f, 1, 1}};
  glMap1f(GL_MAP1_VERTEX_3, 2, 5, 3, 4, &cubic[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 2, 5, 4, 3, &colours[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 24; ++i) glEvalCoord1f(2.0f + 3.0f * static_cast<float>(i) / 24.0f);
  glEnd();
  glPointSize(4);
  glMapGrid1d(6, 2, 5);
  glEvalMesh1(GL_POINT, 0, 6);
  glBegin(GL_POINTS);
  glEvalPoint1(-1);
  glEnd();
  settle_current_values();
}

// A rational patch (GL_MAP2_VERTEX_4, weights above 1 in the middle pull the surface up) lit with
// GL_AUTO_NORMAL's homogeneous normals, specular highlight included.
GLPT_SCENE(evaluators_rational_patch_lit, 64, 64) {
  clear(0.15f, 0.1f, 0.1f);
  lit_perspective_light0(40.0, 1.0);
  GLfloat p[3][3][4];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const float weight = (i == 1 && j == 1) ? 3.0f : (i == 1 || j == 1 ? 1.5f : 1.0f);
      p[i][j][0] = (-1.5f + 1.5f * static_cast<float>(i)) * weight;
      p[i][j][1] = (-1.5f + 1.5f * static_cast<float>(j)) * weight;
      p[i][j][2] = (i == 1 && j == 1 ? 1.5f : 0.0f) * weight;
      p[i][j][3] = weight;
    }
  }
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 12, 3, 0, 1, 4, 3, &p[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_AUTO_NORMAL);
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.4f, 0.8f, 0.5f);
  material4(GL_FRONT_AND_BACK, GL_SPECULAR, 0.8f, 0.8f, 0.8f);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
  glTranslatef(0, 0, -6);
  glRotatef(-45, 1, 0, 0);
  glMapGrid2f(12, 0, 1, 12, 0, 1);
  glEvalMesh2(GL_FILL, 0, 12, 0, 12);
  settle_current_values();
}

// Evaluated colours driving lighting through GL_COLOR_MATERIAL, flat-shaded (the colour of each
// strip triangle's last vertex), next to the same patch smooth-shaded.
GLPT_SCENE(evaluators_colour_material, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  lit_perspective_light0(40.0, 1.0);
  load_bump_patch(1.4f, true);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glMapGrid2f(6, 0, 1, 6, 0, 1);
  for (int side = 0; side < 2; ++side) {
    glShadeModel(side == 0 ? GL_FLAT : GL_SMOOTH);
    glPushMatrix();
    glTranslatef(side == 0 ? -1.7f : 1.7f, 0, -8);
    glRotatef(-40, 1, 0, 0);
    glScalef(0.5f, 0.5f, 0.5f);
    glEvalMesh2(GL_FILL, 0, 6, 0, 6);
    glPopMatrix();
  }
  settle_current_values();
}

// Maps in a display list: glMap2f copies its points when compiled (the array is changed before
// the list runs), glMapGrid2f and glEvalMesh2 run with the list, and a glEvalCoord2 strip inside
// a compiled glBegin/glEnd; the list is called twice under different transforms.
GLPT_SCENE(evaluators_display_list, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  lit_perspective_light0(40.0, 1.0);
  Patch patch = bump_patch(1.6f);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch.p[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(8, 0, 1, 8, 0, 1);
  glEvalMesh2(GL_FILL, 0, 8, 0, 4);
  glDisable(GL_LIGHTING);
  glColor3f(1, 1, 0.3f);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 16; ++i) glEvalCoord2f(static_cast<float>(i) / 16.0f, 0.75f);
  glEnd();
  glEnable(GL_LIGHTING);
  glEndList();
  patch.p[1][1][2] = -3.0f;  // not seen by the list
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.5f, 0.7f, 1.0f);
  for (int k = 0; k < 2; ++k) {
    glPushMatrix();
    glTranslatef(k == 0 ? -1.6f : 1.6f, 0, -8);
    glRotatef(k == 0 ? -30.0f : -60.0f, 1, 0, 0);
    glScalef(0.6f, 0.6f, 0.6f);
    glCallList(list);
    glPopMatrix();
  }
  settle_current_values();
}

}  // namespace
