/* skybox_last: the world first, then a sky box drawn LAST (as Quake 3 and many later engines
 * do, to save fill): one glBegin(GL_QUADS) of all six faces, unlit, vertex colours, under the
 * camera's rotation only (centred on the eye), with glDepthRange(1, 1) and glDepthFunc(GL_LEQUAL)
 * so it shows only where the world left the far-plane depth. The camera moves.
 *
 * Labels: the sky box `sky` (after the world, at the far plane, centred on the eye, unlit);
 * ground and four rocks `static`.
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void sky_box(float h) {
  static const float v[6][4][3] = {{{1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}},
                                   {{-1, -1, 1}, {-1, -1, -1}, {-1, 1, -1}, {-1, 1, 1}},
                                   {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}},
                                   {{-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}},
                                   {{1, -1, 1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}},
                                   {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}}};
  glBegin(GL_QUADS);
  for (int face = 0; face < 6; ++face) {
    for (int k = 0; k < 4; ++k) {
      float y = v[face][k][1];
      glColor3f(0.9f - 0.3f * y, 0.5f - 0.1f * y, 0.3f + 0.4f * y);
      glVertex3f(v[face][k][0] * h, y * h, v[face][k][2] * h);
    }
  }
  glEnd();
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {-3.0f + 1.2f * (float)f, 2.5f, 9.0f};
  const float center[3] = {0.0f, 1.0f, 0.0f};
  static const float up[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  glDepthFunc(GL_LESS);
  lbl_light(-0.4f, 1.0f, 0.3f);
  glColor3f(0.55f, 0.45f, 0.35f);
  label("static", "ground");
  lbl_grid(6, 10.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-4.0f + 2.7f * (float)i, 0.5f, -1.0f - 1.0f * (float)(i % 3));
    glRotatef(20.0f * (float)i, 0.0f, 1.0f, 0.0f);
    glColor3f(0.5f, 0.5f, 0.5f + 0.1f * (float)i);
    labelf("static", "rock%d", i, 0);
    lbl_box(0.7f, 0.5f, 0.6f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  lbl_camera_rotation(eye, center, up);
  glDepthRange(1.0, 1.0);
  glDepthFunc(GL_LEQUAL);
  label("sky", "sky_box");
  sky_box(5.0f);
  glDepthRange(0.0, 1.0);
  glDepthFunc(GL_LESS);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
