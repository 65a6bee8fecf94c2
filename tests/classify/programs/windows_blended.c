/* windows_blended: translucent glass panels in the 3-D view: a bus shelter of three large
 * freestanding panes (3 x 2 units; not coplanar with any opaque surface), tinted, blended
 * SRC_ALPHA / ONE_MINUS_SRC_ALPHA, depth test on, drawn after the opaque world (back to front):
 * the back pane with depth writes on, the two side panes with depth writes off (large and
 * freestanding, so not decals: a decal is a small quad lying on a surface). The camera walks
 * past.
 *
 * Labels: ground, bench, two buildings and a lamp post `static` (only the camera moves); the
 * three panes `blended`.
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.55f, 0.65f, 0.8f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {-4.0f + 1.2f * (float)f, 1.7f, 7.0f};
  const float center[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.3f, 80.0f, eye, center);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  lbl_light(0.3f, 1.0f, 0.6f);
  glColor3f(0.45f, 0.45f, 0.45f);
  label("static", "ground");
  lbl_grid(6, 12.0f);
  static const float objects[4][6] = {{0, 0.25f, -0.5f, 1.2f, 0.25f, 0.3f},
                                      {-6, 2.5f, -6, 2.0f, 2.5f, 2.0f},
                                      {5, 3.0f, -7, 2.0f, 3.0f, 2.0f},
                                      {2.5f, 1.5f, 1.5f, 0.1f, 1.5f, 0.1f}};
  static const char* const names[4] = {"bench", "building0", "building1", "lamp_post"};
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(objects[i][0], objects[i][1], objects[i][2]);
    glColor3f(0.6f - 0.1f * (float)i, 0.5f, 0.4f + 0.1f * (float)i);
    label("static", names[i]);
    lbl_box(objects[i][3], objects[i][4], objects[i][5]);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0.3f, 0.7f, 0.8f, 0.35f);
  label("blended", "pane_back"); /* this one with depth writes on */
  lbl_quad_xy(-1.5f, 0.0f, 1.5f, 2.0f, -1.2f);
  glDepthMask(GL_FALSE);
  glColor4f(0.4f, 0.8f, 0.6f, 0.35f);
  label("blended", "pane_left");
  glBegin(GL_QUADS);
  glVertex3f(-1.5f, 0.0f, 0.8f);
  glVertex3f(-1.5f, 0.0f, -1.2f);
  glVertex3f(-1.5f, 2.0f, -1.2f);
  glVertex3f(-1.5f, 2.0f, 0.8f);
  glEnd();
  glColor4f(0.8f, 0.7f, 0.3f, 0.35f);
  label("blended", "pane_right");
  glBegin(GL_QUADS);
  glVertex3f(1.5f, 0.0f, -1.2f);
  glVertex3f(1.5f, 0.0f, 0.8f);
  glVertex3f(1.5f, 2.0f, 0.8f);
  glVertex3f(1.5f, 2.0f, -1.2f);
  glEnd();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
