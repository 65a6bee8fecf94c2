/* sky_depthrange: a sky dome drawn in the MIDDLE of the frame (after some of the world, before
 * the rest) with glDepthRange(1, 1) and glDepthFunc(GL_LEQUAL): every fragment at the far plane.
 * The dome is four GL_QUAD_STRIP rings (four draws) of radius 40 around the world origin, NOT
 * centred on the eye (the camera moves around inside it): the depth range alone makes it sky.
 * Unlit, vertex colours.
 *
 * Labels: the four rings `sky` (glDepthRange(1, 1), anywhere in the frame); the ground, the two
 * huts drawn before and the two drawn after the dome `static` (only the camera moves).
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void ring(int r) {
  float e0 = LBL_PI * 0.5f * (float)r / 4.0f, e1 = LBL_PI * 0.5f * (float)(r + 1) / 4.0f;
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 16; ++i) {
    float a = 2.0f * LBL_PI * (float)i / 16.0f;
    glColor3f(0.3f + 0.15f * (float)r, 0.5f + 0.1f * (float)r, 0.9f);
    glVertex3f(40.0f * cosf(e1) * cosf(a), -2.0f + 40.0f * sinf(e1), 40.0f * cosf(e1) * sinf(a));
    glColor3f(0.3f + 0.15f * (float)r, 0.5f + 0.1f * (float)r, 0.9f);
    glVertex3f(40.0f * cosf(e0) * cosf(a), -2.0f + 40.0f * sinf(e0), 40.0f * cosf(e0) * sinf(a));
  }
  glEnd();
}

static void hut(int i) {
  glPushMatrix();
  glTranslatef(-6.0f + 4.0f * (float)i, 1.0f, -3.0f + 2.0f * (float)(i % 2));
  glColor3f(0.7f, 0.5f + 0.1f * (float)i, 0.3f);
  labelf("static", "hut%d", i, 0);
  lbl_box(1.0f, 1.0f, 1.0f);
  glPopMatrix();
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float a = 0.2f * (float)f;
  const float eye[3] = {10.0f * sinf(a), 3.0f, 10.0f * cosf(a)};
  const float center[3] = {0.0f, 2.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 200.0f, eye, center);
  glDepthFunc(GL_LESS);
  lbl_light(0.2f, 1.0f, 0.5f);
  glColor3f(0.3f, 0.45f, 0.3f);
  label("static", "ground");
  lbl_grid(8, 16.0f);
  hut(0);
  hut(1);
  glDisable(GL_LIGHTING);

  glDepthRange(1.0, 1.0);
  glDepthFunc(GL_LEQUAL);
  for (int r = 0; r < 4; ++r) {
    labelf("sky", "dome%d", r, 0);
    ring(r);
  }
  glDepthRange(0.0, 1.0);
  glDepthFunc(GL_LESS);

  glEnable(GL_LIGHTING);
  hut(2);
  hut(3);
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
