/* sky_far_projection: a sky box drawn FIRST each frame under a projection of its own that
 * reaches farther than the world's (the same field of view and aspect, near 1 and far 2000
 * against the world's 0.5 and 100: a game keeping its sky beyond the world's far plane), with
 * the depth test off and lighting off, under the camera's rotation only (centred on the eye);
 * then, under the same far projection and with the depth test still off, a lit ground plane
 * reaching to the horizon; then the lit world under the world's projection. The camera walks
 * and turns.
 *
 * Labels: the six faces `sky` (before the world, unlit, no depth test, together a box around
 * the eye, under the main camera's view but for the near and far planes). The horizon ground
 * `static` (it does not move; drawn under the far projection, raster mode draws it). World:
 * ground and six houses `static` (only the camera moves).
 */
#include "../label_harness.h"

static GLuint face_textures[6];

static void setup(void) {
  lbl_sky_textures(face_textures);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float yaw = 0.2f * (float)f;
  const float eye[3] = {0.8f * (float)f, 1.8f, 8.0f - 0.4f * (float)f};
  const float center[3] = {eye[0] - 8.0f * sinf(yaw), 1.5f, eye[2] - 8.0f * cosf(yaw)};
  static const float up[3] = {0.0f, 1.0f, 0.0f};

  /* the sky, far projection, rotation of the camera only, no depth test */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lbl_perspective(70.0f, 4.0f / 3.0f, 1.0f, 2000.0f);
  glMatrixMode(GL_MODELVIEW);
  lbl_camera_rotation(eye, center, up);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  lbl_sky_box(face_textures, 500.0f);

  /* the horizon ground: far projection, the whole camera, lit, still no depth test */
  glLoadIdentity();
  lbl_look_at(eye, center, up);
  lbl_light(0.3f, 1.0f, 0.4f);
  glColor3f(0.3f, 0.45f, 0.2f);
  glPushMatrix();
  glTranslatef(0.0f, -0.01f, 0.0f);
  label("static", "horizon_ground");
  lbl_grid(4, 800.0f);
  glPopMatrix();

  /* the world: its own projection, depth test on */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lbl_perspective(70.0f, 4.0f / 3.0f, 0.5f, 100.0f);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.35f, 0.5f, 0.25f);
  label("static", "ground");
  lbl_grid(16, 20.0f);  // the world has most of the triangles: its camera is the main one
  static const float houses[6][2] = {{-5, -4}, {4, -6}, {-2, -10}, {7, 1}, {-8, -8}, {9, -9}};
  for (int i = 0; i < 6; ++i) {
    glPushMatrix();
    glTranslatef(houses[i][0], 1.0f, houses[i][1]);
    glColor3f(0.8f, 0.7f - 0.05f * (float)i, 0.5f);
    labelf("static", "house%d", i, 0);
    lbl_box(1.2f, 1.0f, 1.2f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
