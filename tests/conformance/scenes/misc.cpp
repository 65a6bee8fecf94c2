// Whole-frame behaviour: glRect, display lists, attribute stacks, vertex arrays and buffer
// objects, evaluators, several projections and viewports in one frame, projective modelviews,
// draw order without depth test, and scenes for defects glpt had.
#include <cmath>
#include <cstring>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// glRect in its four type variants; reversed corners give a clockwise rectangle, which back-face
// culling removes (GL 1.5 2.10: glRect is a polygon with vertices in the stated order).
GLPT_SCENE(misc_rect_variants, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  glColor3f(1, 0.4f, 0.2f);
  glRecti(2, 2, 20, 20);
  glColor3f(0.2f, 1, 0.4f);
  glRectf(22.5f, 2.5f, 40.5f, 20.5f);
  const GLdouble a[2] = {44, 2}, b[2] = {62, 20};
  glColor3f(0.3f, 0.5f, 1);
  glRectdv(a, b);
  const GLshort c[2] = {2, 24}, d[2] = {30, 40};
  glColor3f(1, 1, 0.3f);
  glRectsv(c, d);
  glEnable(GL_CULL_FACE);
  glColor3f(1, 0.3f, 1);
  glRectf(60, 44, 34, 62);  // clockwise: culled
  glRectf(2, 44, 30, 62);   // counter-clockwise: drawn
}

// Display lists holding state and geometry: colour, material, matrices, lighting changes, a
// nested list, and glCallLists with a list base. Lists are replayed under different transforms;
// the state they leave behind is visible in later drawing and in the state dump.
GLPT_SCENE(misc_display_lists_mixed_state, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  perspective(40.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  const GLuint base = glGenLists(4);
  glNewList(base, GL_COMPILE);  // a unit cube, its own colour
  glColor3f(0.9f, 0.5f, 0.2f);
  cube(0.5f);
  glEndList();
  glNewList(base + 1, GL_COMPILE);  // lighting state and a material
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  light4(GL_LIGHT0, GL_POSITION, -0.3f, 0.5f, 1, 0);
  material4(GL_FRONT, GL_DIFFUSE, 0.3f, 0.8f, 0.4f);
  glEndList();
  glNewList(base + 2, GL_COMPILE);  // transform + nested call
  glPushMatrix();
  glRotatef(30, 1, 1, 0);
  glCallList(base);
  glPopMatrix();
  glTranslatef(1.2f, 0, 0);
  glEndList();
  glNewList(base + 3, GL_COMPILE_AND_EXECUTE);  // executes now too: a sphere at the origin
  glPushMatrix();
  glTranslatef(0, -1.2f, -5);
  sphere(0.5f, 16, 8);
  glPopMatrix();
  glEndList();
  glTranslatef(-1.6f, 0.6f, -5);
  glCallList(base + 2);  // unlit cube, then moves right
  glCallList(base + 1);  // lighting on from here
  glCallList(base + 2);  // lit cube (the list's colour is ignored: no colour material)
  glListBase(base);
  const GLubyte offsets[2] = {2, 3};
  glCallLists(2, GL_UNSIGNED_BYTE, offsets);  // another lit cube, then the sphere list
}

// glPushAttrib/glPopAttrib restore what they saved: state changed inside a push (lighting,
// colour, line width, polygon mode, depth function, blend) is undone by the pop, and the
// drawing after the pop uses the restored state.
GLPT_SCENE(misc_push_pop_attrib, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  glColor3f(0.3f, 0.6f, 1);
  glLineWidth(1);
  glPushAttrib(GL_CURRENT_BIT | GL_LINE_BIT | GL_POLYGON_BIT | GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0.3f, 0.2f);
  glLineWidth(4);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glRectf(4, 4, 30, 30);
  glBegin(GL_LINES);
  glVertex2f(4, 40);
  glVertex2f(30, 60);
  glEnd();
  glPopAttrib();
  glRectf(34, 4, 60, 30);  // filled, unblended, the colour from before the push
  glBegin(GL_LINES);
  glVertex2f(34, 40);
  glVertex2f(60, 60);
  glEnd();
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPopClientAttrib();  // alignment back to 4: the state dump shows it
}

// Vertex arrays: glDrawArrays, glDrawElements and glDrawRangeElements from client arrays of
// positions, colours and texture coordinates, glMultiDrawArrays, and glArrayElement inside
// glBegin/glEnd.
GLPT_SCENE(misc_vertex_arrays, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  float positions[16][2];
  float colours[16][3];
  for (int i = 0; i < 16; ++i) {
    const double a = 2 * kPi * i / 16;
    positions[i][0] = static_cast<float>(16 + 13 * std::cos(a));
    positions[i][1] = static_cast<float>(16 + 13 * std::sin(a));
    colours[i][0] = 0.5f + 0.5f * static_cast<float>(std::cos(a));
    colours[i][1] = 0.5f + 0.5f * static_cast<float>(std::sin(a));
    colours[i][2] = i % 2 == 0 ? 1.0f : 0.2f;
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glColorPointer(3, GL_FLOAT, 0, colours);
  glDrawArrays(GL_POLYGON, 0, 16);
  glTranslatef(32, 0, 0);
  const GLushort star[12] = {0, 6, 12, 2, 8, 14, 4, 10, 0, 6, 12, 2};
  glDrawElements(GL_LINE_STRIP, 12, GL_UNSIGNED_SHORT, star);
  glTranslatef(-32, 32, 0);
  const GLuint fan[6] = {0, 3, 5, 8, 11, 13};
  glDrawRangeElements(GL_TRIANGLE_FAN, 0, 13, 6, GL_UNSIGNED_INT, fan);
  glTranslatef(32, 0, 0);
  const GLint firsts[2] = {0, 8};
  const GLsizei counts[2] = {5, 5};
  glMultiDrawArrays(GL_TRIANGLE_STRIP, firsts, counts, 2);
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1, 1, 1);
  glPointSize(3);
  glBegin(GL_POINTS);
  for (int i = 0; i < 16; i += 3) glArrayElement(i);
  glEnd();
}

// Interleaved arrays (glInterleavedArrays GL_T2F_C4UB_V3F) and a buffer object (GL 1.5 VBO)
// holding positions and normals for a lit, indexed mesh with the indices in an element buffer.
GLPT_SCENE(misc_interleaved_arrays_and_buffer_objects, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  struct Vertex {
    GLfloat s, t;
    GLubyte r, g, b, a;
    GLfloat x, y, z;
  };
  const Vertex quad_vertices[4] = {{0, 0, 255, 60, 60, 255, 4, 36, 0},
                                   {1, 0, 60, 255, 60, 255, 28, 36, 0},
                                   {1, 1, 60, 60, 255, 255, 28, 60, 0},
                                   {0, 1, 255, 255, 60, 255, 4, 60, 0}};
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_LUMINANCE, 4, 4, checker(4, 4, 1, Rgba8{255, 0, 0, 255}, Rgba8{120, 0, 0, 255}));
  glInterleavedArrays(GL_T2F_C4UB_V3F, 0, quad_vertices);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisable(GL_TEXTURE_2D);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);

  // A lit hemisphere-ish bump: a 6x6 grid of positions and normals in one buffer object.
  constexpr int kN = 6;
  std::vector<GLfloat> data;
  for (int y = 0; y < kN; ++y) {
    for (int x = 0; x < kN; ++x) {
      const float u = static_cast<float>(x) / (kN - 1) * 2 - 1,
                  v = static_cast<float>(y) / (kN - 1) * 2 - 1;
      const float nz = std::sqrt(std::max(0.1f, 2 - u * u - v * v));
      const float len = std::sqrt(u * u + v * v + nz * nz);
      data.insert(data.end(), {34 + 13 * (u + 1), 4 + 13 * (v + 1), 0, u / len, v / len, nz / len});
    }
  }
  std::vector<GLushort> indices;
  for (int y = 0; y + 1 < kN; ++y) {
    for (int x = 0; x + 1 < kN; ++x) {
      const GLushort i = static_cast<GLushort>(y * kN + x);
      indices.insert(indices.end(),
                     {i, static_cast<GLushort>(i + 1), static_cast<GLushort>(i + kN + 1),
                      static_cast<GLushort>(i + kN)});
    }
  }
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(GLfloat)), data.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLushort)),
               indices.data(), GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 6 * sizeof(GLfloat), nullptr);
  glNormalPointer(GL_FLOAT, 6 * sizeof(GLfloat),
                  reinterpret_cast<const void*>(3 * sizeof(GLfloat)));
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, -1, 1, 1, 0);
  glEnable(GL_LIGHT0);
  material4(GL_FRONT, GL_DIFFUSE, 1, 0.7f, 0.3f);
  glDrawElements(GL_QUADS, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_SHORT, nullptr);
  // A second draw reusing the buffer, offset, as points through a plain client colour.
  glDisable(GL_LIGHTING);
  glDisableClientState(GL_NORMAL_ARRAY);
  glTranslatef(-30, 30, 0);
  glColor3f(0.3f, 1, 1);
  glPointSize(2);
  glDrawArrays(GL_POINTS, 0, kN * kN);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

// Evaluators (GL 1.5 5.1): a bicubic Bezier patch with generated normals (GL_AUTO_NORMAL),
// lit, through glMapGrid2/glEvalMesh2, and a Bezier curve through glEvalCoord1.
GLPT_SCENE(misc_evaluators, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  lit_perspective_light0(40.0, 1.0);
  GLfloat patch[4][4][3];
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      patch[i][j][0] = -1.5f + i;
      patch[i][j][1] = -1.5f + j;
      patch[i][j][2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 1.5f : -0.5f;
    }
  }
  // u runs along the first index (stride 12 floats), v along the second (stride 3).
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  // One-sided: glEvalMesh2's quad strips run (u, v), (u, v+1), ... which is clockwise here, so
  // two-sided lighting would light the patch as a back face, with the normal reversed.
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.6f, 1);
  glPushMatrix();
  glTranslatef(0, 0, -6);
  glRotatef(-50, 1, 0, 0);
  glMapGrid2f(12, 0, 1, 12, 0, 1);
  glEvalMesh2(GL_FILL, 0, 12, 0, 12);
  glPopMatrix();
  glDisable(GL_LIGHTING);
  const GLfloat curve[4][3] = {{-2, -1.8f, -5}, {-1, 1.5f, -5}, {1, -2.5f, -5}, {2, 1.8f, -5}};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glColor3f(1, 1, 0.3f);
  glLineWidth(2);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 24; ++i) glEvalCoord1f(static_cast<float>(i) / 24);
  glEnd();
  // Mesa leaves a stale current normal after GL_AUTO_NORMAL evaluations (see evaluators.cpp);
  // a defined one keeps the state dumps comparable.
  glNormal3f(0, 0, 1);
}

// Defect: a HUD drawn with a second projection over a 3-D view in one frame: lit spheres in
// perspective, then a glOrtho overlay (a translucent panel, a frame and bitmap marks) without
// depth test. Both halves must use their own projection.
GLPT_SCENE(misc_hud_over_perspective, 64, 64) {
  clear(0.1f, 0.1f, 0.25f);
  lit_perspective_light0(45.0, 1.0);
  glEnable(GL_COLOR_MATERIAL);
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-1.5f + 1.5f * i, 0.3f, -4.0f - 2.0f * i);
    glColor3f(0.9f - 0.3f * i, 0.4f + 0.2f * i, 0.3f);
    sphere(0.8f, 24, 12);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0, 0, 0, 0.6f);
  glRectf(0, 0, 64, 14);
  glDisable(GL_BLEND);
  glColor3f(1, 1, 1);
  glBegin(GL_LINE_LOOP);
  glVertex2f(1.5f, 1.5f);
  glVertex2f(62.5f, 1.5f);
  glVertex2f(62.5f, 12.5f);
  glVertex2f(1.5f, 12.5f);
  glEnd();
  GLubyte mark[5] = {0x20, 0x70, 0xF8, 0x70, 0x20};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(1, 0.9f, 0.2f);
  glRasterPos2i(5, 4);
  for (int i = 0; i < 6; ++i) glBitmap(5, 5, 0, 0, 9, 0, mark);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
}

// Four viewports in one frame, each with its own projection and content (perspective lit
// sphere, orthographic triangle, a tilted textured quad, wireframe cube).
GLPT_SCENE(misc_several_viewports, 64, 64) {
  clear(0.15f, 0.15f, 0.15f);
  glEnable(GL_DEPTH_TEST);
  glViewport(0, 32, 32, 32);
  perspective(40.0, 1.0, 1.0, 10.0);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, -1, 1, 1, 0);
  glEnable(GL_LIGHT0);
  glTranslatef(0, 0, -4);
  sphere(1.3f, 24, 12);
  glDisable(GL_LIGHTING);
  glViewport(32, 32, 32, 32);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  rgb_triangle(-0.9f, -0.9f, 0.9f, -0.7f, 0, 0.9f);
  glViewport(0, 0, 32, 32);
  perspective(60.0, 1.0, 0.5, 10.0);
  glEnable(GL_TEXTURE_2D);
  texture_2d(GL_RGB, 4, 4, checker(4, 4, 1, Rgba8{255, 255, 255, 255}, Rgba8{200, 60, 60, 255}));
  glColor3f(1, 1, 1);
  glTranslatef(0, 0, -2);
  glRotatef(-50, 1, 0, 0);
  quad(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_2D);
  glViewport(40, 4, 20, 24);  // not square, not aligned to the others
  perspective(40.0, 20.0 / 24.0, 1.0, 10.0);
  glTranslatef(0, 0, -4);
  glRotatef(30, 1, 1, 0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(1, 1, 0.3f);
  cube(0.9f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

// Defect: a projective modelview: a planar-shadow matrix flattens a cube onto the ground plane
// along a directional light (w in the matrix's last row is not (0,0,0,1)). The shadow is drawn
// dark and blended once (stencil), with polygon offset against the ground.
GLPT_SCENE(misc_planar_shadow, 64, 64) {
  clear(0.3f, 0.4f, 0.6f);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  perspective(45.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glTranslatef(0, -1, -6);
  glRotatef(25, 1, 0, 0);
  glColor3f(0.4f, 0.7f, 0.3f);
  glBegin(GL_QUADS);
  glVertex3f(-3, 0, 3);
  glVertex3f(3, 0, 3);
  glVertex3f(3, 0, -3);
  glVertex3f(-3, 0, -3);
  glEnd();
  // Shadow matrix for the plane y = 0 and the light direction l = (1, 2, 0.5, 0):
  // M = (p.l) I - l p^T with p = (0, 1, 0, 0).
  const float l[4] = {1, 2, 0.5f, 0}, p[4] = {0, 1, 0, 0};
  const float dot = p[0] * l[0] + p[1] * l[1] + p[2] * l[2] + p[3] * l[3];
  float shadow[16];
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) {
      shadow[col * 4 + row] = (row == col ? dot : 0.0f) - l[row] * p[col];
    }
  }
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1, -1);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0, 0, 0, 0.5f);
  glPushMatrix();
  glMultMatrixf(shadow);
  glTranslatef(0, 1, 0);
  glRotatef(30, 0, 1, 0);
  cube(0.6f);
  glPopMatrix();
  glDisable(GL_BLEND);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, 1, 2, 0.5f, 0);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(0.9f, 0.5f, 0.2f);
  glTranslatef(0, 1, 0);
  glRotatef(30, 0, 1, 0);
  cube(0.6f);
}

// Defect: with the depth test off, later primitives cover earlier ones whatever their depth:
// the nearest quad is drawn first and ends up underneath.
GLPT_SCENE(misc_depth_test_off_draw_order, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  perspective(45.0, 1.0, 1.0, 20.0);
  const float colours[4][3] = {{1, 0.3f, 0.2f}, {0.3f, 1, 0.3f}, {0.3f, 0.5f, 1}, {1, 1, 0.3f}};
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-0.9f + 0.6f * i, -0.6f + 0.4f * i, -3.0f - 1.5f * i);  // each one farther
    glColor3fv(colours[i]);
    quad(-0.8f, -0.8f, 0.8f, 0.8f);
    glPopMatrix();
  }
}

// Defect: glEndList while a glBegin is being compiled (GL_COMPILE). The glBegin was compiled,
// not executed, so the context is not between glBegin and glEnd: Mesa raises no error and the
// list exists (the state dump records the error flag; the green square below shows glIsList).
// The list is not called: replaying a primitive left open is the caller's business (Mesa then
// stays inside Begin/End until a glEnd, which draws the primitive yet raises
// GL_INVALID_OPERATION, and ignores commands such as glReadPixels meanwhile).
GLPT_SCENE(misc_end_list_inside_begin, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  glNewList(1, GL_COMPILE);
  glColor3f(1, 0.5f, 0.2f);
  glBegin(GL_TRIANGLES);
  glVertex2f(2, 2);
  glVertex2f(26, 4);
  glVertex2f(12, 26);
  glEndList();
  // Green when list 1 exists, red when it does not.
  const bool exists = glIsList(1) == GL_TRUE;
  glColor3f(exists ? 0.2f : 1.0f, exists ? 1.0f : 0.2f, 0.2f);
  glRectf(4, 36, 28, 60);
  // Drawing goes on normally: the context is outside glBegin/glEnd and compiles nothing.
  glColor3f(0.3f, 0.6f, 1);
  glBegin(GL_TRIANGLES);
  glVertex2f(36, 36);
  glVertex2f(60, 38);
  glVertex2f(48, 60);
  glEnd();
  glNewList(2, GL_COMPILE);  // a complete list compiled afterwards, then called
  glColor3f(1, 1, 0.3f);
  glRectf(36, 4, 60, 28);
  glEndList();
  glCallList(2);
}

// Defect: unlit vertex colours keep their alpha in glReadPixels with blending off: quads of
// alpha 0.25, 0.5, 0.75 and 1 (the image's alpha channel is compared).
GLPT_SCENE(misc_unlit_colour_alpha, 64, 64) {
  clear(0.2f, 0.2f, 0.2f, 1.0f);
  ortho_pixels(64, 64);
  for (int i = 0; i < 4; ++i) {
    glColor4f(1.0f - 0.2f * i, 0.3f + 0.2f * i, 0.6f, 0.25f * (i + 1));
    const float x = 4.0f + 30.0f * static_cast<float>(i % 2),
                y = 4.0f + 30.0f * static_cast<float>(i / 2);
    glRectf(x, y, x + 26, y + 26);
  }
  // A smooth alpha ramp too.
  glBegin(GL_TRIANGLES);
  glColor4f(1, 1, 1, 0);
  glVertex2f(20, 20);
  glColor4f(1, 1, 1, 1);
  glVertex2f(44, 20);
  glColor4f(1, 1, 1, 0.5f);
  glVertex2f(32, 44);
  glEnd();
}

// Defect: state queries through other types (GL 1.5 6.1.2): the depth write mask off,
// a line width of 3.5 (glGetIntegerv rounds it), the separate specular colour control; lines of
// that width and a lit sphere drawn under that state. The state dump checks the queries.
GLPT_SCENE(misc_state_query_conversions, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  lit_perspective_light0(35.0, 1.0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  glTranslatef(0, 0, -4);
  sphere(1, 24, 12);
  glDisable(GL_LIGHTING);
  glDepthMask(GL_FALSE);
  glLineWidth(3.5f);
  glColor3f(1, 1, 0.3f);
  glBegin(GL_LINES);
  glVertex3f(-1.5f, -1.2f, 0);
  glVertex3f(1.5f, 1.2f, 0);
  glEnd();
  glColor4f(0.2f, 0.9f, 1.0f, 0.6f);
}

}  // namespace
