/* screen_before_world: a 2-D screen drawn BEFORE the 3-D world (a flight simulator's cockpit
 * style): a full-window gradient backdrop under glOrtho with the depth test off, then a cockpit
 * frame (a bottom panel and a top bar) under glOrtho with depth writes on and glDepthFunc
 * GL_ALWAYS at the near end of the depth range, so the world drawn afterwards (GL_LESS) cannot
 * cover it. Then the 3-D world under a perspective camera that banks and climbs.
 *
 * Labels: backdrop, panel and top bar `overlay` (glOrtho, 2-D; drawn first but not a sky: not a
 * box around the camera under the perspective projection); the terrain and four towers
 * `static` (only the camera moves).
 */
#include "../label_harness.h"

static void setup(void) { glClearColor(0.0f, 0.0f, 0.0f, 1.0f); }

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  label("overlay", "backdrop");
  glBegin(GL_QUADS);
  glColor3f(0.7f, 0.8f, 0.95f);
  glVertex2f(0.0f, 0.0f);
  glVertex2f(160.0f, 0.0f);
  glColor3f(0.2f, 0.3f, 0.7f);
  glVertex2f(160.0f, 120.0f);
  glVertex2f(0.0f, 120.0f);
  glEnd();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glColor3f(0.25f, 0.25f, 0.22f);
  label("overlay", "panel");
  lbl_quad_xy(0.0f, 0.0f, 160.0f, 28.0f, 0.99f);
  label("overlay", "top_bar");
  lbl_quad_xy(0.0f, 112.0f, 160.0f, 120.0f, 0.99f);

  glDepthFunc(GL_LESS);
  const float eye[3] = {0.0f, 6.0f + 0.5f * (float)f, 20.0f - 1.5f * (float)f};
  const float center[3] = {0.0f, 2.0f, 0.0f};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lbl_perspective(60.0f, 4.0f / 3.0f, 1.0f, 200.0f);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(4.0f * (float)f, 0.0f, 0.0f, 1.0f); /* bank */
  static const float up[3] = {0.0f, 1.0f, 0.0f};
  lbl_look_at(eye, center, up);
  lbl_light(0.3f, 1.0f, 0.2f);
  glColor3f(0.3f, 0.5f, 0.25f);
  label("static", "terrain");
  lbl_grid(10, 30.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-9.0f + 6.0f * (float)i, 2.5f, -4.0f * (float)(i % 2));
    glColor3f(0.75f, 0.7f - 0.1f * (float)i, 0.6f);
    labelf("static", "tower%d", i, 0);
    lbl_box(0.8f, 2.5f, 0.8f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
