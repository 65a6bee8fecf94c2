/* viewmodel_depthrange: a first-person gun (body and barrel, two draws) drawn after the world in
 * eye space (modelview loaded without the camera) with its own narrow depth range
 * glDepthRange(0, 0.1), so the world never cuts into it; same projection and viewport as the
 * world. The gun bobs as the camera walks and turns.
 *
 * Labels: ground and four crates `static` (only the camera moves); the gun's two draws
 * `viewmodel` in every frame (frame 0 included).
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.5f, 0.55f, 0.6f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float yaw = 0.15f * (float)f;
  const float eye[3] = {0.4f * (float)f, 1.7f, 6.0f - 0.6f * (float)f};
  const float center[3] = {eye[0] + sinf(yaw), 1.6f, eye[2] - cosf(yaw)};
  lbl_camera(70.0f, 4.0f / 3.0f, 0.1f, 100.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.5f);
  glColor3f(0.4f, 0.45f, 0.35f);
  label("static", "ground");
  lbl_grid(8, 12.0f);
  static const float crates[4][2] = {{-2, -2}, {2, -3}, {-1, -6}, {3, -8}};
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(crates[i][0], 0.5f, crates[i][1]);
    glColor3f(0.6f, 0.45f, 0.25f + 0.1f * (float)i);
    labelf("static", "crate%d", i, 0);
    lbl_box(0.5f, 0.5f, 0.5f);
    glPopMatrix();
  }

  /* the gun, in eye space */
  glLoadIdentity();
  lbl_light(0.3f, 1.0f, 0.5f);
  glDepthRange(0.0, 0.1);
  float bob = 0.02f * sinf(2.0f * (float)f);
  glTranslatef(0.25f, -0.22f + bob, -0.5f);
  glRotatef(-4.0f, 0.0f, 1.0f, 0.0f);
  glColor3f(0.25f, 0.25f, 0.3f);
  label("viewmodel", "gun_body");
  lbl_box(0.06f, 0.08f, 0.2f);
  glTranslatef(0.0f, 0.04f, -0.3f);
  glColor3f(0.4f, 0.4f, 0.45f);
  label("viewmodel", "gun_barrel");
  lbl_box(0.025f, 0.025f, 0.15f);
  glDepthRange(0.0, 1.0);
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
