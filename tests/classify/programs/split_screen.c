/* split_screen: two players' views side by side: glViewport(0, 0, 80, 120) and
 * glViewport(80, 0, 80, 120), each with its own perspective projection (aspect 2/3) and its own
 * moving camera over the same world of five objects; then a 2-D divider bar under glOrtho in the
 * full window (viewport restored), depth test off.
 *
 * Labels: in both views the ground and four crates `static` (each view's camera moves; in each
 * view five of five objects agree); an object seen in both views is two draws (keys v0_* and
 * v1_*); the divider `overlay`.
 */
#include "../label_harness.h"

static void world(int view) {
  char key[32];
  lbl_light(0.3f, 1.0f, 0.5f);
  glColor3f(0.35f, 0.5f, 0.3f);
  snprintf(key, sizeof key, "v%d_ground", view);
  label("static", key);
  lbl_grid(6, 10.0f);
  static const float crates[4][2] = {{-3, -2}, {2, -4}, {0, 2}, {4, 1}};
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(crates[i][0], 0.6f, crates[i][1]);
    glColor3f(0.7f, 0.4f + 0.1f * (float)i, 0.2f);
    snprintf(key, sizeof key, "v%d_crate%d", view, i);
    label("static", key);
    lbl_box(0.6f, 0.6f, 0.6f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

static void setup(void) { glClearColor(0.5f, 0.6f, 0.75f, 1.0f); }

static void frame(int f) {
  glViewport(0, 0, LBL_WIDTH, LBL_HEIGHT);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  for (int view = 0; view < 2; ++view) {
    glViewport(view * LBL_WIDTH / 2, 0, LBL_WIDTH / 2, LBL_HEIGHT);
    float a = (view ? -0.2f : 0.25f) * (float)f + (view ? 2.5f : 0.0f);
    const float eye[3] = {9.0f * sinf(a), 3.0f + (float)view, 9.0f * cosf(a)};
    const float center[3] = {0.0f, 0.5f, 0.0f};
    lbl_camera(60.0f, (LBL_WIDTH / 2.0f) / LBL_HEIGHT, 0.5f, 60.0f, eye, center);
    world(view);
  }
  glViewport(0, 0, LBL_WIDTH, LBL_HEIGHT);
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glColor3f(0.05f, 0.05f, 0.05f);
  label("overlay", "divider");
  glRectf(78.0f, 0.0f, 82.0f, 120.0f);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
