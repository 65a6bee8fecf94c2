// Selection and feedback (GL 1.5 5.2, 5.3): what they report, drawn afterwards in GL_RENDER so
// that a wrong value shows in pixels, and that nothing they are given is drawn.
#include <vector>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// A lit sphere and a culled, clipped, unfilled mix captured in GL_3D_COLOR feedback under a
// perspective projection, then redrawn from the buffer in window coordinates: polygons with
// their reported colours, lines and points in white. What feedback was given is drawn nowhere
// else (the clear in feedback mode is ignored too).
GLPT_SCENE(render_modes_feedback_redrawn, 64, 64) {
  clear(0.1f, 0.1f, 0.15f);
  static GLfloat buffer[20000];
  glFeedbackBuffer(20000, GL_3D_COLOR, buffer);
  lit_perspective_light0(45.0, 1.0);
  glRenderMode(GL_FEEDBACK);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glPushMatrix();
  glTranslatef(-0.3f, 0.2f, -4.0f);
  sphere(1.2f, 12, 8);  // partly outside the view volume: clipped
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glColor3f(0.2f, 0.9f, 0.3f);
  glBegin(GL_QUADS);
  glVertex3f(0.4f, -1.2f, -3.0f);
  glVertex3f(1.6f, -1.2f, -3.5f);
  glVertex3f(1.6f, -0.2f, -3.5f);
  glVertex3f(0.4f, -0.2f, -3.0f);
  glVertex3f(-1.6f, -1.2f, -3.0f);  // clockwise: back face, points
  glVertex3f(-1.6f, -0.2f, -3.0f);
  glVertex3f(-0.4f, -0.2f, -3.0f);
  glVertex3f(-0.4f, -1.2f, -3.0f);
  glEnd();
  const GLint n = glRenderMode(GL_RENDER);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  constexpr int kVertex = 7;  // x, y, z, r, g, b, a
  for (GLint i = 0; i < n;) {
    const float token = buffer[i++];
    if (token == GL_POLYGON_TOKEN) {
      const int count = static_cast<int>(buffer[i++]);
      glBegin(GL_POLYGON);
      for (int k = 0; k < count; ++k, i += kVertex) {
        glColor4fv(&buffer[i + 3]);
        glVertex2f(buffer[i], buffer[i + 1]);
      }
      glEnd();
    } else if (token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN) {
      glColor3f(1, 1, 1);
      glBegin(GL_LINES);
      glVertex2f(buffer[i], buffer[i + 1]);
      glVertex2f(buffer[i + kVertex], buffer[i + kVertex + 1]);
      glEnd();
      i += 2 * kVertex;
    } else if (token == GL_POINT_TOKEN) {
      glColor3f(1, 1, 0);
      glPointSize(3);
      glBegin(GL_POINTS);
      glVertex2f(buffer[i], buffer[i + 1]);
      glEnd();
      i += kVertex;
    } else {
      break;  // not expected here
    }
  }
}

// Picking: a 4x4 grid of named quads at different depths and a sphere, selected through a
// pick matrix around four points; each quad is then drawn with a colour from its hits (picked
// quads brighter, blue from the hit's minimum depth). Selection itself draws nothing.
GLPT_SCENE(render_modes_selection_picking, 64, 64) {
  clear(0.05f, 0.05f, 0.05f);
  static GLuint buffer[512];
  auto draw_grid = [](bool names) {
    for (int row = 0; row < 4; ++row) {
      for (int column = 0; column < 4; ++column) {
        if (names) glLoadName(GLuint(row * 4 + column + 1));
        glColor3f(0.25f + 0.2f * column, 0.25f + 0.2f * row, 0.3f);
        const float x = -1.0f + 0.5f * column, y = -1.0f + 0.5f * row;
        quad(x + 0.05f, y + 0.05f, x + 0.45f, y + 0.45f, -0.2f * float(row + column) / 6.0f);
      }
    }
  };
  float hit_depth[17] = {};
  bool picked[17] = {};
  const float picks[4][2] = {{10, 10}, {40, 25}, {33, 33}, {60, 60}};
  for (const auto& p : picks) {
    glSelectBuffer(512, buffer);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    // gluPickMatrix(p.x, p.y, 3, 3, viewport): a 3x3 pixel region scaled to the view volume.
    glTranslatef((64 - 2 * p[0]) / 3.0f, (64 - 2 * p[1]) / 3.0f, 0);
    glScalef(64 / 3.0f, 64 / 3.0f, 1);
    glOrtho(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    draw_grid(true);
    glLoadName(100);
    sphere(0.3f, 8, 6);  // over the middle of the grid, no quad of its own
    const GLint hits = glRenderMode(GL_RENDER);
    for (GLint h = 0, at = 0; h < hits && at < 512; ++h) {
      const GLuint depth = buffer[at];
      const GLuint min_z = buffer[at + 1];
      for (GLuint k = 0; k < depth; ++k) {
        const GLuint name = buffer[at + 3 + k];
        if (name >= 1 && name <= 16) {
          picked[name] = true;
          hit_depth[name] = float(min_z) / 4294967295.0f;
        }
      }
      at += 3 + int(depth);
    }
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  draw_grid(false);
  for (int name = 1; name <= 16; ++name) {
    if (!picked[name]) continue;
    const int row = (name - 1) / 4, column = (name - 1) % 4;
    const float x = -1.0f + 0.5f * column, y = -1.0f + 0.5f * row;
    glColor3f(1, 1, hit_depth[name]);
    quad(x + 0.15f, y + 0.15f, x + 0.35f, y + 0.35f, 0.5f);
  }
}

}  // namespace
