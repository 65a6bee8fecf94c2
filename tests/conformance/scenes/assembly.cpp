// Primitive assembly as Mesa does it (rt_core/record/decompose.hpp): which diagonal splits a
// quad and in which order a quad strip's triangles are drawn depend on how the primitives were
// given (immediate mode or display list), on the shading and on whether the draw module's
// pipeline runs (clipping, unfilled polygons). Every quad here has four different corner colours
// that do not lie on a plane, so the other diagonal changes its whole interior.
#include <cmath>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

const float kCorners[4][3] = {
    {1, 0.15f, 0.1f}, {0.1f, 0.2f, 0.25f}, {0.2f, 1, 0.3f}, {0.9f, 0.9f, 1}};

// A convex, non-parallelogram quad centred on (cx, cy) with kCorners (rotated by `shift`).
void corner_quad(float cx, float cy, float r, int shift, bool colours = true) {
  const float dx[4] = {-1, 1, 0.8f, -0.7f}, dy[4] = {-0.9f, -1, 1, 0.75f};
  for (int i = 0; i < 4; ++i) {
    if (colours) glColor3fv(kCorners[(i + shift) % 4]);
    glVertex2f(cx + r * dx[i], cy + r * dy[i]);
  }
}

// Four quads, each its own glBegin/glEnd (Mesa merges them into one draw).
void four_quads(float r = 13.0f) {
  for (int q = 0; q < 4; ++q) {
    glBegin(GL_QUADS);
    corner_quad(16.0f + 32.0f * static_cast<float>(q % 2),
                16.0f + 32.0f * static_cast<float>(q / 2), r, q);
    glEnd();
  }
}

void begin_scene(float r = 0.05f, float g = 0.05f, float b = 0.08f) {
  clear(r, g, b);
  ortho_pixels(64, 64);
}

// Immediate mode, smooth: llvmpipe draws each quad as (0,1,2), (0,2,3).
GLPT_SCENE(assembly_quads_immediate, 64, 64) {
  begin_scene();
  four_quads();
}

// The same quads from a display list: Mesa compiles them to an indexed draw, split (0,1,3),
// (1,2,3).
GLPT_SCENE(assembly_quads_display_list, 64, 64) {
  begin_scene();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  four_quads();
  glEndList();
  glCallList(list);
  glDeleteLists(list, 1);
}

// GL_COMPILE_AND_EXECUTE draws while compiling the way immediate mode does; calling the list
// afterwards draws it indexed (over the first drawing, shifted).
GLPT_SCENE(assembly_quads_compile_and_execute, 64, 64) {
  begin_scene();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_QUADS);
  corner_quad(18, 18, 14, 0);
  glEnd();
  glEndList();
  glTranslatef(28, 28, 0);
  glCallList(list);
  glDeleteLists(list, 1);
}

// Flat shading: a colour given per vertex is a constant-interpolated input of Mesa's fragment
// shader, so even immediate-mode quads split along 1-3; a colour set only before glBegin is a
// constant of the shader and the quads split along 0-2. The diagonal shows in the per-vertex fog
// coordinates (linear fog towards white).
GLPT_SCENE(assembly_flat_quads_colour_per_vertex_or_constant, 64, 64) {
  begin_scene();
  glShadeModel(GL_FLAT);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, 1);
  fog_colour(1, 1, 1);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  const float fog[4] = {0.05f, 0.9f, 0.15f, 0.7f};
  const float dx[4] = {-1, 1, 0.8f, -0.7f}, dy[4] = {-0.9f, -1, 1, 0.75f};
  for (int q = 0; q < 4; ++q) {
    const float cx = 16.0f + 32.0f * static_cast<float>(q % 2);
    const float cy = 16.0f + 32.0f * static_cast<float>(q / 2);
    const bool per_vertex = q >= 2;
    glColor3f(0.2f, 0.3f, 0.9f);
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; ++i) {
      if (per_vertex) glColor3fv(kCorners[i]);
      glFogCoordf(fog[(i + q) % 4]);
      glVertex2f(cx + 13 * dx[i], cy + 13 * dy[i]);
    }
    glEnd();
    glFlush();  // no batching across the two kinds
  }
}

// llvmpipe clips triangles without a guard band: one quad reaching past the right edge sends
// the whole batch (all four quads) through the draw module's pipeline, which splits every quad
// along 1-3. After a state change the next batch is not clipped and splits along 0-2.
GLPT_SCENE(assembly_quads_partly_outside_the_view, 64, 64) {
  begin_scene();
  glBegin(GL_QUADS);
  corner_quad(16, 16, 13, 0);
  corner_quad(16, 48, 13, 1);
  corner_quad(56, 16, 13, 2);  // crosses x = 64
  glEnd();
  glLineWidth(2);  // a state change: a new batch
  glBegin(GL_QUADS);
  corner_quad(40, 46, 12, 3);
  glEnd();
}

// The same through the near plane, in perspective, and through a user clip plane.
GLPT_SCENE(assembly_quads_near_and_user_clipped, 64, 64) {
  clear(0.05f, 0.05f, 0.08f);
  perspective(50.0, 1.0, 1.0, 20.0);
  glEnable(GL_DEPTH_TEST);
  glTranslatef(0, 0, -4);
  glBegin(GL_QUADS);
  for (int q = 0; q < 2; ++q) {
    const float x = q == 0 ? -0.9f : 0.9f;
    glColor3fv(kCorners[q]);
    glVertex3f(x - 0.8f, -1.2f, 0);
    glColor3fv(kCorners[q + 1]);
    glVertex3f(x + 0.7f, -1.1f, 0);
    glColor3fv(kCorners[q + 2]);
    glVertex3f(x + 0.8f, 0.2f, q == 0 ? 3.5f : 0.3f);  // the first quad crosses the near plane
    glColor3fv(kCorners[(q + 3) % 4]);
    glVertex3f(x - 0.6f, 0.1f, 0.2f);
  }
  glEnd();
  const double plane[4] = {-1, -0.3, 0, 0.8};  // keeps x + 0.3 y <= 0.8
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glBegin(GL_QUADS);
  glColor3fv(kCorners[0]);
  glVertex3f(-0.3f, 0.5f, 0);
  glColor3fv(kCorners[1]);
  glVertex3f(1.5f, 0.4f, 0);
  glColor3fv(kCorners[2]);
  glVertex3f(1.3f, 1.4f, 0.2f);
  glColor3fv(kCorners[3]);
  glVertex3f(-0.2f, 1.3f, 0);
  glEnd();
}

// Unfilled back faces run the draw module's pipeline for every polygon: the filled front quads
// split along 1-3 in immediate mode too.
GLPT_SCENE(assembly_quads_with_back_faces_unfilled, 64, 64) {
  begin_scene();
  glPolygonMode(GL_BACK, GL_LINE);
  four_quads();
}

// Bow-tie quads (self-intersecting) in a quad strip: its two triangles overlap, so their order
// shows. llvmpipe draws (2i, 2i+1, 2i+3) then (2i+2, 2i, 2i+3); the draw module's pipeline (here
// for the clipped strip at the top) the other way round.
GLPT_SCENE(assembly_quad_strip_triangle_order, 64, 64) {
  begin_scene();
  for (int strip = 0; strip < 2; ++strip) {
    const float y0 = strip == 0 ? 6.0f : 36.0f;
    const float height = strip == 0 ? 22.0f : 34.0f;  // the top strip leaves the view
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i < 8; ++i) {
      const bool up = ((i / 2) % 2 == 0) == (i % 2 == 1);
      glColor3fv(kCorners[i % 4]);
      glVertex2f(4.0f + 8.0f * static_cast<float>(i / 2) + static_cast<float>(i % 2),
                 up ? y0 + height : y0);
    }
    glEnd();
  }
}

// Polygons, fans and strips split the same way on every path: immediate mode and a display list
// side by side.
void fan_strip_polygon() {
  glBegin(GL_POLYGON);
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * kPi * i / 6 + 0.2;
    glColor3fv(kCorners[i % 4]);
    glVertex2f(static_cast<float>(16 + 13 * std::cos(a)),
               static_cast<float>(48 + 12 * std::sin(a)));
  }
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1);
  glVertex2f(16, 15);
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * kPi * i / 7 + 0.5;
    glColor3fv(kCorners[i % 4]);
    glVertex2f(static_cast<float>(16 + 14 * std::cos(a)),
               static_cast<float>(15 + 12 * std::sin(a)));
  }
  glEnd();
}

GLPT_SCENE(assembly_polygons_fans_strips_immediate_and_list, 64, 64) {
  begin_scene();
  fan_strip_polygon();
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 8; ++i) {
    glColor3fv(kCorners[i % 4]);
    glVertex2f(34.0f + 4.0f * static_cast<float>(i), i % 2 ? 30.0f : 4.0f + static_cast<float>(i));
  }
  glEnd();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  fan_strip_polygon();
  glEndList();
  glTranslatef(32, 0, 0);
  glCallList(list);
  glDeleteLists(list, 1);
}

// 1100 small quads in one glBegin/glEnd: Mesa's draw module takes them 4096 vertices (1024
// quads) at a time. A vertex past the right edge in the first batch splits its quads along 1-3;
// the 76 quads of the second batch (the top rows) still split along 0-2.
GLPT_SCENE(assembly_quads_large_batch, 128, 64) {
  clear(0.05f, 0.05f, 0.08f);
  ortho_pixels(128, 64);
  const float dx[4] = {0, 3.3f, 3.0f, 0.4f}, dy[4] = {0, 0.2f, 1.7f, 1.6f};
  glBegin(GL_QUADS);
  for (int q = 0; q < 1100; ++q) {
    const float x = 3.5f * static_cast<float>(q % 36), y = 1.8f * static_cast<float>(q / 36);
    for (int i = 0; i < 4; ++i) {
      glColor3fv(kCorners[(i + q) % 4]);
      const bool outside = q == 35 && i == 2;  // the last quad of the first row
      glVertex2f(x + (outside ? 9.0f : dx[i]), y + dy[i]);
    }
  }
  glEnd();
}

// lp_setup_analyse_triangles: Mesa draws nothing of a 9-vertex triangle list drawn in immediate
// mode, smooth, whose last triangle has one window y (it takes it for a Windows Aero window
// border). 12 vertices, or the same 9 from a display list, are drawn.
GLPT_SCENE(assembly_nine_vertex_triangle_list_defect, 64, 64) {
  begin_scene();
  auto nine = [](float x0, float y0) {
    glBegin(GL_TRIANGLES);
    for (int t = 0; t < 2; ++t) {
      glColor3fv(kCorners[t]);
      glVertex2f(x0 + 2, y0 + 2 + 12 * t);
      glColor3fv(kCorners[t + 1]);
      glVertex2f(x0 + 28, y0 + 4 + 12 * t);
      glColor3fv(kCorners[t + 2]);
      glVertex2f(x0 + 14, y0 + 13 + 12 * t);
    }
    glColor3f(1, 1, 1);
    glVertex2f(x0 + 2, y0 + 28);
    glVertex2f(x0 + 30, y0 + 28);
    glVertex2f(x0 + 16, y0 + 28);
    glEnd();
  };
  nine(0, 0);  // not drawn by Mesa
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  nine(32, 0);
  glEndList();
  glCallList(list);  // drawn
  glDeleteLists(list, 1);
  glShadeModel(GL_FLAT);
  nine(0, 32);  // drawn: the colour is interpolated as a constant
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);  // 12 vertices: drawn
  glColor3f(0.4f, 0.4f, 0.4f);
  glVertex2f(34, 34);
  glVertex2f(60, 36);
  glVertex2f(47, 46);
  glEnd();
  nine(32, 32);  // merged with the triangle above: 12 vertices
}

// Mesa applies each vertex's edge flag in every polygon mode, strips and fans included (GL 1.5
// says they are ignored there): in line mode the edges starting at a vertex with the flag off
// are missing.
GLPT_SCENE(assembly_edge_flags_on_strips_and_fans, 64, 64) {
  begin_scene();
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 8; ++i) {
    glEdgeFlag(i % 3 != 1);
    glColor3fv(kCorners[i % 4]);
    glVertex2f(4.0f + 8.0f * static_cast<float>(i / 2), i % 2 ? 28.0f : 4.0f);
  }
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  glEdgeFlag(GL_TRUE);
  glColor3f(1, 1, 1);
  glVertex2f(16, 46);
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * kPi * i / 7;
    glEdgeFlag(i % 2 == 0);
    glColor3fv(kCorners[i % 4]);
    glVertex2f(static_cast<float>(16 + 14 * std::cos(a)),
               static_cast<float>(46 + 14 * std::sin(a)));
  }
  glEnd();
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < 8; ++i) {
    glEdgeFlag(i % 4 != 2);
    glColor3fv(kCorners[i % 4]);
    glVertex2f(36.0f + 8.0f * static_cast<float>(i / 2), i % 2 ? 60.0f : 34.0f);
  }
  glEnd();
  glEdgeFlag(GL_TRUE);
}

// Mesa compiles consecutive line strips of a display list into one line list: the stipple
// pattern restarts at every segment. Drawn directly (left) the pattern runs along each strip.
GLPT_SCENE(assembly_display_list_stippled_line_strips, 64, 64) {
  begin_scene();
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x1F3F);
  auto strips = [] {
    for (int s = 0; s < 3; ++s) {
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i < 5; ++i) {
        glColor3fv(kCorners[(i + s) % 4]);
        glVertex2f(3.5f + 6.0f * static_cast<float>(i),
                   8.5f + 20.0f * static_cast<float>(s) + (i % 2 ? 9.0f : 0.0f));
      }
      glEnd();
    }
  };
  strips();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  strips();
  glEndList();
  glTranslatef(32, 0, 0);
  glCallList(list);
  glDeleteLists(list, 1);
}

// Consecutive glBegin/glEnd blocks of different modes under one state, as glxgears draws its
// gears: glpt draws such a run as one Vulkan draw (rt_core/raster/draw_merging.hpp), each block
// still in Mesa's own triangles and order. Lit and flat shaded: each block's normal is one value
// given before glBegin (constant within the block, different between blocks), some blocks give
// colours per vertex and some once. Lit (bottom) and unlit (top), directly (left) and from a
// display list (right: indexed).
GLPT_SCENE(assembly_mixed_modes_under_one_state, 64, 64) {
  begin_scene();
  light4(GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1.0f, 0.0f);
  glEnable(GL_LIGHT0);
  glShadeModel(GL_FLAT);
  auto blocks = [] {
    glNormal3f(0.0f, 0.0f, 1.0f);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i < 5; ++i) {
      glColor3fv(kCorners[i % 4]);
      glVertex2f(2.0f + 6.0f * static_cast<float>(i), 2.0f + (i % 2 ? 1.5f : 0.0f));
      glVertex2f(2.5f + 6.0f * static_cast<float>(i), 12.0f);
    }
    glEnd();
    glNormal3f(0.6f, 0.0f, 0.8f);
    glBegin(GL_QUADS);
    corner_quad(8.0f, 22.0f, 6.0f, 1);
    corner_quad(22.0f, 22.0f, 6.0f, 2, false);
    glEnd();
    glNormal3f(0.0f, 0.6f, 0.8f);
    glColor3f(0.8f, 0.5f, 0.2f);
    glBegin(GL_POLYGON);
    for (int i = 0; i < 6; ++i) {
      const float a = static_cast<float>(i) * 1.0472f;
      glVertex2f(10.0f + 7.0f * std::cos(a), 40.0f + 6.0f * std::sin(a));
    }
    glEnd();
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(-0.5f, 0.0f, 0.85f);
    glVertex2f(24.0f, 40.0f);
    for (int i = 0; i < 5; ++i) {
      glColor3fv(kCorners[(i + 1) % 4]);
      glVertex2f(24.0f + 7.0f * std::cos(0.9f * static_cast<float>(i)),
                 40.0f + 7.0f * std::sin(0.9f * static_cast<float>(i)));
    }
    glEnd();
    glShadeModel(GL_SMOOTH);  // a new state: the next block starts another run
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 6; ++i) {
      glNormal3f(0.1f * static_cast<float>(i), 0.0f, 1.0f);
      glVertex2f(2.0f + 5.0f * static_cast<float>(i), 52.0f + (i % 2 ? 8.0f : 0.0f));
    }
    glEnd();
    glBegin(GL_TRIANGLES);
    glVertex2f(3.0f, 62.0f);
    glVertex2f(28.0f, 61.0f);
    glVertex2f(15.0f, 58.5f);
    glEnd();
    glShadeModel(GL_FLAT);
  };
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  blocks();
  glEndList();
  for (int lit = 0; lit < 2; ++lit) {
    if (lit)
      glEnable(GL_LIGHTING);
    else
      glDisable(GL_LIGHTING);
    glPushMatrix();
    glTranslatef(0.0f, lit ? 0.0f : 32.0f, 0.0f);
    glScalef(1.0f, 0.5f, 1.0f);
    blocks();
    glTranslatef(32.0f, 0.0f, 0.0f);
    glCallList(list);
    glPopMatrix();
  }
  glDeleteLists(list, 1);
}

}  // namespace
