/* hud_identity: a HUD drawn with identity projection and modelview (coordinates in normalized
 * device space, -1..1), depth test off, after the world: a glRectf frame bar at the top, a
 * radar quad and a blinking warning light (glRectf, its colour changes).
 *
 * World: still camera, ground and four still barrels (`static`).
 *
 * Labels: every identity-projection draw `overlay`.
 */
#include "../label_harness.h"

static void setup(void) { glClearColor(0.5f, 0.45f, 0.4f, 1.0f); }

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const float eye[3] = {2.0f, 2.5f, 7.0f}, center[3] = {0.0f, 0.5f, 0.0f};
  lbl_camera(55.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  lbl_light(0.4f, 1.0f, 0.4f);
  glColor3f(0.6f, 0.5f, 0.3f);
  label("static", "ground");
  lbl_grid(6, 8.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-3.0f + 2.0f * (float)i, 0.6f, -1.0f + 0.5f * (float)(i % 2));
    glColor3f(0.2f, 0.4f + 0.1f * (float)i, 0.25f);
    labelf("static", "barrel%d", i, 0);
    lbl_box(0.4f, 0.6f, 0.4f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glColor3f(0.05f, 0.05f, 0.1f);
  label("overlay", "top_bar");
  glRectf(-1.0f, 0.85f, 1.0f, 1.0f);
  glColor3f(0.1f, 0.4f, 0.1f);
  label("overlay", "radar");
  lbl_quad_2d(-0.95f, -0.95f, -0.6f, -0.5f);
  if (f % 2)
    glColor3f(1.0f, 0.1f, 0.1f);
  else
    glColor3f(0.3f, 0.0f, 0.0f);
  label("overlay", "warning");
  glRectf(0.8f, -0.95f, 0.95f, -0.8f);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
