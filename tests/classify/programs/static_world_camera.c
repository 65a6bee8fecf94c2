/* static_world_camera: a still world seen by a moving camera (it orbits and rises).
 *
 * Covers: camera motion folded into the modelview (lookAt, then each object's translation), so
 * every draw's modelview changes every frame while nothing moves in the world; the three vertex
 * array drawing commands next to glBegin/glEnd.
 *
 * Labels: all seven draws are `static` in every frame: same vertices, same object-to-world
 * transform; only the camera moves, and seven of seven objects agree on that camera motion.
 * Frame 0: `static` (first frame).
 */
#include "../label_harness.h"

static const GLfloat pyramid[] = {
    /* 4 sides of a square pyramid, base half size 1, height 2 (GL_TRIANGLES, 12 vertices) */
    -1, 0, 1,  1,  0, 1,  0, 2, 0, 1,  0, 1,  1,  0, -1, 0, 2, 0,
    1,  0, -1, -1, 0, -1, 0, 2, 0, -1, 0, -1, -1, 0, 1,  0, 2, 0};
static const GLfloat prism_vertices[] = {-1, 0, -1, 1, 0, -1, 0, 1.5f, -1,
                                         -1, 0, 1,  1, 0, 1,  0, 1.5f, 1};
static const GLushort prism_indices[] = {0, 2, 1, 3, 4, 5, 0, 1, 4, 0, 4, 3,
                                         1, 2, 5, 1, 5, 4, 2, 0, 3, 2, 3, 5};
static GLfloat column_vertices[8 * 2 * 3];
static GLushort column_indices[8 * 6];

static void setup(void) {
  /* an octagonal column, radius 0.4, height 3, side walls only */
  for (int i = 0; i < 8; ++i) {
    float a = 2.0f * LBL_PI * (float)i / 8.0f;
    for (int k = 0; k < 2; ++k) {
      column_vertices[(i * 2 + k) * 3 + 0] = 0.4f * cosf(a);
      column_vertices[(i * 2 + k) * 3 + 1] = 3.0f * (float)k;
      column_vertices[(i * 2 + k) * 3 + 2] = 0.4f * sinf(a);
    }
    int j = (i + 1) % 8;
    GLushort q[6] = {(GLushort)(i * 2), (GLushort)(j * 2),     (GLushort)(j * 2 + 1),
                     (GLushort)(i * 2), (GLushort)(j * 2 + 1), (GLushort)(i * 2 + 1)};
    memcpy(column_indices + 6 * i, q, sizeof q);
  }
  glClearColor(0.3f, 0.4f, 0.6f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glEnableClientState(GL_VERTEX_ARRAY);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float a = 0.35f * (float)f;
  const float eye[3] = {12.0f * sinf(a), 4.0f + 0.5f * (float)f, 12.0f * cosf(a)};
  const float center[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.5f);

  glColor3f(0.4f, 0.6f, 0.3f);
  label("static", "ground");
  lbl_grid(8, 10.0f);

  static const float boxes[3][3] = {{-4, 1, -3}, {3, 0.5f, -4}, {-2, 0.75f, 4}};
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(boxes[i][0], boxes[i][1], boxes[i][2]);
    glColor3f(0.8f, 0.3f + 0.2f * (float)i, 0.2f);
    labelf("static", "box%d", i, 0);
    lbl_box(1.0f, boxes[i][1], 1.0f);
    glPopMatrix();
  }

  glDisable(GL_LIGHTING);
  glPushMatrix();
  glTranslatef(4.0f, 0.0f, 3.0f);
  glColor3f(0.9f, 0.8f, 0.2f);
  glVertexPointer(3, GL_FLOAT, 0, pyramid);
  label("static", "pyramid");
  glDrawArrays(GL_TRIANGLES, 0, 12);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -7.0f);
  glColor3f(0.5f, 0.2f, 0.7f);
  glVertexPointer(3, GL_FLOAT, 0, prism_vertices);
  label("static", "prism");
  glDrawElements(GL_TRIANGLES, 24, GL_UNSIGNED_SHORT, prism_indices);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(6.0f, 0.0f, -1.0f);
  glColor3f(0.7f, 0.7f, 0.75f);
  glVertexPointer(3, GL_FLOAT, 0, column_vertices);
  label("static", "column");
  glDrawRangeElements(GL_TRIANGLES, 0, 15, 48, GL_UNSIGNED_SHORT, column_indices);
  glPopMatrix();
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
