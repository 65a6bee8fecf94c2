/* sky_behind_world_range: the world drawn in glDepthRange(0, 0.999) and, after it, a small sky
 * dome in glDepthRange(0.999, 1) under the camera's rotation alone (no translation), so every
 * fragment of the dome lies behind every depth the world can have (trigger-rally draws its sky
 * this way). The dome (radius 3, four GL_TRIANGLE_STRIP rings) is far smaller than the world and
 * drawn last: neither the far-plane rule nor the enclosing-box rule finds it; its depth range
 * does. Unlit, vertex colours. The camera moves, turning.
 *
 * Labels: the four rings `sky`; the ground and three huts `static` (only the camera moves).
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void ring(int r) {
  float e0 = LBL_PI * 0.5f * (float)r / 4.0f, e1 = LBL_PI * 0.5f * (float)(r + 1) / 4.0f;
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 16; ++i) {
    float a = 2.0f * LBL_PI * (float)i / 16.0f;
    glColor3f(0.2f + 0.15f * (float)r, 0.4f + 0.1f * (float)r, 0.9f);
    glVertex3f(3.0f * cosf(e1) * cosf(a), 3.0f * sinf(e1), 3.0f * cosf(e1) * sinf(a));
    glVertex3f(3.0f * cosf(e0) * cosf(a), 3.0f * sinf(e0), 3.0f * cosf(e0) * sinf(a));
  }
  glEnd();
}

static void frame(int f) {
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  float yaw = 0.1f * (float)f;
  const float eye[3] = {0.5f * (float)f, 1.7f, 8.0f - 0.5f * (float)f};
  const float center[3] = {eye[0] + sinf(yaw), 1.5f, eye[2] - cosf(yaw)};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.1f, 1000.0f, eye, center);
  glDepthRange(0.0, 0.999);
  lbl_light(0.2f, 1.0f, 0.5f);
  glColor3f(0.35f, 0.5f, 0.3f);
  label("static", "ground");
  lbl_grid(8, 40.0f);
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-4.0f + 4.0f * (float)i, 1.0f, -6.0f - 3.0f * (float)i);
    glColor3f(0.7f, 0.5f + 0.1f * (float)i, 0.3f);
    labelf("static", "hut%d", i, 0);
    lbl_box(1.0f, 1.0f, 1.0f);
    glPopMatrix();
  }

  /* the dome around the eye: the camera's rotation without its translation */
  glDisable(GL_LIGHTING);
  glDepthRange(0.999, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  static const float origin[3] = {0.0f, 0.0f, 0.0f}, up[3] = {0.0f, 1.0f, 0.0f};
  const float ahead[3] = {center[0] - eye[0], center[1] - eye[1], center[2] - eye[2]};
  lbl_look_at(origin, ahead, up);
  for (int r = 0; r < 4; ++r) {
    labelf("sky", "dome%d", r, 0);
    ring(r);
  }
  glDepthRange(0.0, 1.0);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
