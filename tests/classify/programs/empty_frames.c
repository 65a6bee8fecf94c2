/* empty_frames: bad input for identity - frames that draw nothing (frames 1, 2 and 4 only
 * clear), between frames that draw a still world of three lit objects under a still camera and
 * a HUD quad.
 *
 * Labels: every object `static` whenever it is drawn (after an empty frame it is unchanged in
 * the world, and must get back the id it had: same key); the HUD `overlay`.
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.5f, 0.55f, 0.6f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (f == 1 || f == 2 || f == 4) return; /* nothing drawn */
  const float eye[3] = {2.0f, 3.0f, 8.0f};
  const float center[3] = {0.0f, 0.5f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 60.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.4f);
  glColor3f(0.4f, 0.5f, 0.3f);
  label("static", "ground");
  lbl_grid(6, 8.0f);
  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glTranslatef(-2.0f + 4.0f * (float)i, 0.6f, -1.0f);
    glColor3f(0.7f, 0.4f, 0.2f + 0.3f * (float)i);
    labelf("static", "crate%d", i, 0);
    lbl_box(0.6f, 0.6f, 0.6f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1.0f, 1.0f, 0.2f);
  label("overlay", "hud");
  glRectf(4.0f, 4.0f, 60.0f, 14.0f);
  glEnable(GL_DEPTH_TEST);
}

int main(int argc, char** argv) { return label_run(argc, argv, 8, setup, frame); }
