/* skybox_first: a sky box of six separately drawn textured faces, drawn FIRST each frame with
 * depth writes off (glDepthMask(GL_FALSE)) and lighting off, under the camera's rotation only
 * (the look-at with the eye at the origin: the box is centred on the eye), then the lit world.
 * The camera walks and turns.
 *
 * Labels: the six faces `sky` (drawn before the world, unlit, depth writes off, together a box
 * around the eye). World: ground and eight houses `static` (only the camera moves); a windmill's
 * sails turn: `static` in frame 0, then `moving` (9 static objects against 1 moving: the camera
 * motion is the one the still objects agree on; the world's objects outnumber the six sky faces,
 * whose modelview follows the camera's rotation only, so the majority is the world's also when
 * the sky's draws are counted).
 */
#include "../label_harness.h"

static GLuint face_textures[6];

static void setup(void) {
  lbl_sky_textures(face_textures);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float yaw = 0.25f * (float)f;
  const float eye[3] = {1.0f * (float)f, 1.8f, 8.0f - 0.5f * (float)f};
  const float center[3] = {eye[0] - 8.0f * sinf(yaw), 1.5f, eye[2] - 8.0f * cosf(yaw)};
  static const float up[3] = {0.0f, 1.0f, 0.0f};

  /* the sky: rotation of the camera only */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lbl_perspective(70.0f, 4.0f / 3.0f, 0.5f, 100.0f);
  glMatrixMode(GL_MODELVIEW);
  lbl_camera_rotation(eye, center, up);
  glDisable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  lbl_sky_box(face_textures, 10.0f);
  glDepthMask(GL_TRUE);

  /* the world */
  glLoadIdentity();
  lbl_look_at(eye, center, up);
  lbl_light(0.3f, 1.0f, 0.4f);
  glColor3f(0.35f, 0.5f, 0.25f);
  label("static", "ground");
  lbl_grid(8, 20.0f);
  static const float houses[8][2] = {{-5, -4}, {4, -6}, {-2, -10}, {7, 1},
                                     {-8, -8}, {9, -9}, {2, -14},  {-9, 0}};
  for (int i = 0; i < 8; ++i) {
    glPushMatrix();
    glTranslatef(houses[i][0], 1.0f, houses[i][1]);
    glColor3f(0.8f, 0.7f - 0.05f * (float)i, 0.5f);
    labelf("static", "house%d", i, 0);
    lbl_box(1.2f, 1.0f, 1.2f);
    glPopMatrix();
  }
  glPushMatrix();
  glTranslatef(0.0f, 3.0f, -5.0f);
  glRotatef(25.0f * (float)f, 0.0f, 0.0f, 1.0f);
  glColor3f(0.9f, 0.9f, 0.85f);
  label(f == 0 ? "static" : "moving", "sails");
  lbl_box(2.0f, 0.2f, 0.05f);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
