/* menu: a game's main menu: a full-window 2-D background and three buttons under glOrtho (depth
 * test off), a small spinning 3-D model (a ship) in perspective in a sub-viewport
 * (glViewport(96, 44, 56, 56)) with the depth test on, then a mouse cursor quad under glOrtho in
 * the full viewport again.
 *
 * Labels: background, buttons and cursor `overlay`; the ship `static` in frame 0, then `moving`
 * (a lone rotating object under a still camera, in its own viewport's 3-D view). The highlighted
 * button changes colour every frame: a colour change keeps a draw's identity (same key). Each
 * button has its own modelview, so which buttons glpt may merge into one entry (consecutive
 * blocks with identical state) is the same in every frame.
 */
#include "../label_harness.h"

static void ship(void) {
  static const float nose[3] = {0, 0, -1.2f}, tail_l[3] = {-0.8f, 0, 0.6f},
                     tail_r[3] = {0.8f, 0, 0.6f};
  static const float top[3] = {0, 0.4f, 0.4f}, bottom[3] = {0, -0.2f, 0.4f};
  glBegin(GL_TRIANGLES);
  glNormal3f(-0.4f, 0.8f, 0.0f);
  glVertex3fv(nose);
  glVertex3fv(tail_l);
  glVertex3fv(top);
  glNormal3f(0.4f, 0.8f, 0.0f);
  glVertex3fv(nose);
  glVertex3fv(top);
  glVertex3fv(tail_r);
  glNormal3f(-0.3f, -0.9f, 0.0f);
  glVertex3fv(nose);
  glVertex3fv(bottom);
  glVertex3fv(tail_l);
  glNormal3f(0.3f, -0.9f, 0.0f);
  glVertex3fv(nose);
  glVertex3fv(tail_r);
  glVertex3fv(bottom);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glVertex3fv(tail_l);
  glVertex3fv(bottom);
  glVertex3fv(top);
  glVertex3fv(tail_r);
  glVertex3fv(top);
  glVertex3fv(bottom);
  glEnd();
}

static void setup(void) { glClearColor(0.0f, 0.0f, 0.0f, 1.0f); }

static void frame(int f) {
  glViewport(0, 0, LBL_WIDTH, LBL_HEIGHT);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  label("overlay", "background");
  glBegin(GL_QUADS);
  glColor3f(0.1f, 0.05f, 0.2f);
  glVertex2f(0.0f, 0.0f);
  glVertex2f(160.0f, 0.0f);
  glColor3f(0.3f, 0.1f, 0.4f);
  glVertex2f(160.0f, 120.0f);
  glVertex2f(0.0f, 120.0f);
  glEnd();
  for (int i = 0; i < 3; ++i) {
    /* each button under its own translation: consecutive buttons never have identical state,
     * whichever one is highlighted */
    glPushMatrix();
    glTranslatef(12.0f, 80.0f - 26.0f * (float)i, 0.0f);
    if (i == f % 3)
      glColor3f(0.9f, 0.8f, 0.2f);
    else
      glColor3f(0.5f, 0.45f, 0.6f);
    labelf("overlay", "button%d", i, 0);
    lbl_quad_2d(0.0f, 0.0f, 72.0f, 18.0f);
    glPopMatrix();
  }

  glViewport(96, 44, 56, 56);
  const float eye[3] = {0.0f, 1.0f, 3.5f}, center[3] = {0.0f, 0.0f, 0.0f};
  lbl_camera(45.0f, 1.0f, 0.5f, 20.0f, eye, center);
  glEnable(GL_DEPTH_TEST);
  lbl_light(0.3f, 1.0f, 0.6f);
  glRotatef(40.0f * (float)f, 0.0f, 1.0f, 0.0f);
  glColor3f(0.3f, 0.7f, 0.9f);
  label(f == 0 ? "static" : "moving", "ship");
  ship();
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);

  glViewport(0, 0, LBL_WIDTH, LBL_HEIGHT);
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  float cx = 40.0f + 9.0f * (float)f, cy = 30.0f + 4.0f * (float)f;
  glColor3f(1.0f, 1.0f, 1.0f);
  label("overlay", "cursor");
  glBegin(GL_TRIANGLES);
  glVertex2f(cx, cy);
  glVertex2f(cx + 4.0f, cy - 9.0f);
  glVertex2f(cx + 8.0f, cy - 5.0f);
  glEnd();
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
