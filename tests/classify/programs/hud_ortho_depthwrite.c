/* hud_ortho_depthwrite: a HUD drawn after the 3-D world under glOrtho (pixel coordinates) with
 * the depth test and depth writes left ON (as many old games do: the HUD lies at the near end
 * of the ortho depth range, so it passes the world's depths).
 *
 * World: ground and four pillars seen by a camera that strafes sideways (all `static`).
 * HUD: a health bar frame, its fill (its width changes every frame: positions change, still
 * overlay), a crosshair of two glRectf, all at ortho z 0.5..0.6 with depth writes on.
 *
 * Labels: world `static`; every HUD draw `overlay` (glOrtho), whatever the depth state.
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.4f, 0.5f, 0.7f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {-2.0f + 0.6f * (float)f, 2.0f, 9.0f};
  const float center[3] = {-2.0f + 0.6f * (float)f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  lbl_light(-0.3f, 1.0f, 0.7f);
  glColor3f(0.3f, 0.55f, 0.3f);
  label("static", "ground");
  lbl_grid(8, 12.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-4.5f + 3.0f * (float)i, 1.5f, -2.0f * (float)(i % 2));
    glColor3f(0.7f, 0.7f, 0.6f - 0.1f * (float)i);
    labelf("static", "pillar%d", i, 0);
    lbl_box(0.5f, 1.5f, 0.5f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  /* The HUD: depth test and depth writes still on. */
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glColor3f(0.1f, 0.1f, 0.1f);
  label("overlay", "health_frame");
  lbl_quad_xy(6.0f, 6.0f, 66.0f, 16.0f, 0.5f);
  glColor3f(0.9f, 0.15f, 0.1f);
  label("overlay", "health_fill");
  lbl_quad_xy(8.0f, 8.0f, 8.0f + 56.0f * (1.0f - 0.12f * (float)f), 14.0f, 0.6f);
  glColor3f(1.0f, 1.0f, 1.0f);
  label("overlay", "cross_h");
  glRectf(75.0f, 59.0f, 85.0f, 61.0f);
  label("overlay", "cross_v");
  glRectf(79.0f, 55.0f, 81.0f, 65.0f);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
