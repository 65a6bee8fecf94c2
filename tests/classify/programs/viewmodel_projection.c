/* viewmodel_projection: a first-person hand holding a torch drawn after the world with its own
 * perspective projection (field of view 45 degrees, near plane 0.01, where the world uses 80
 * degrees and 0.5) in the same viewport, after clearing the depth buffer; modelview in eye
 * space, close to the eye, opaque. The camera turns on the spot and rises.
 *
 * Labels: ground and five pillars `static` (only the camera moves); arm and torch `viewmodel`.
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.15f, 0.1f, 0.2f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float yaw = 0.2f * (float)f - 0.5f;
  const float eye[3] = {0.0f, 1.6f + 0.1f * (float)f, 4.0f};
  const float center[3] = {eye[0] + 5.0f * sinf(yaw), 1.2f, eye[2] - 5.0f * cosf(yaw)};
  lbl_camera(80.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  lbl_light(-0.2f, 1.0f, 0.6f);
  glColor3f(0.35f, 0.3f, 0.3f);
  label("static", "ground");
  lbl_grid(8, 12.0f);
  for (int i = 0; i < 5; ++i) {
    glPushMatrix();
    glTranslatef(-6.0f + 3.0f * (float)i, 1.5f, -3.0f - (float)(i % 2) * 2.0f);
    glColor3f(0.6f, 0.6f - 0.08f * (float)i, 0.5f);
    labelf("static", "pillar%d", i, 0);
    lbl_box(0.4f, 1.5f, 0.4f);
    glPopMatrix();
  }

  glClear(GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lbl_perspective(45.0f, 4.0f / 3.0f, 0.01f, 10.0f);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  lbl_light(-0.2f, 1.0f, 0.6f);
  glTranslatef(-0.12f, -0.12f + 0.01f * sinf((float)f), -0.4f);
  glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
  glColor3f(0.8f, 0.6f, 0.5f);
  label("viewmodel", "arm");
  lbl_box(0.03f, 0.03f, 0.12f);
  glTranslatef(0.0f, 0.06f, -0.1f);
  glColor3f(0.5f, 0.3f, 0.1f);
  label("viewmodel", "torch");
  lbl_box(0.015f, 0.07f, 0.015f);
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
