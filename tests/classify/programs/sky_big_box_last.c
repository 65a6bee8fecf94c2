/* sky_big_box_last: a sky box much larger than the world (half size 400; the world lies within
 * 15 units of the origin), drawn LAST, unlit, centred on the eye by translating it to the
 * camera's position in world space (the modelview keeps the full camera, translation included),
 * with the normal depth range, depth test GL_LEQUAL and depth writes on. Far plane 1000.
 *
 * Labels: the box `sky` (a box larger than the world centred on the eye, drawn after the world,
 * unlit); ground and four trees `static` (only the camera moves).
 */
#include "../label_harness.h"

static GLuint clouds;

static void setup(void) {
  static const GLubyte a[4] = {200, 210, 240, 255}, b[4] = {90, 130, 220, 255};
  clouds = lbl_checker_texture(32, 8, a, b);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {2.0f, 2.0f + 0.3f * (float)f, 12.0f - 1.0f * (float)f};
  const float center[3] = {-1.0f + 0.4f * (float)f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 1000.0f, eye, center);
  glDepthFunc(GL_LESS);
  lbl_light(0.5f, 1.0f, 0.2f);
  glColor3f(0.4f, 0.5f, 0.3f);
  label("static", "ground");
  lbl_grid(6, 15.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-5.0f + 3.5f * (float)i, 1.5f, -2.0f - 1.5f * (float)(i % 2));
    glColor3f(0.2f, 0.5f + 0.1f * (float)i, 0.2f);
    labelf("static", "tree%d", i, 0);
    lbl_box(0.6f, 1.5f, 0.6f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  glDepthFunc(GL_LEQUAL);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, clouds);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glPushMatrix();
  glTranslatef(eye[0], eye[1], eye[2]);
  glColor3f(1.0f, 1.0f, 1.0f);
  label("sky", "sky_box");
  lbl_box(400.0f, 400.0f, 400.0f); /* seen from inside: culling is off */
  glPopMatrix();
  glDisable(GL_TEXTURE_2D);
  glDepthFunc(GL_LESS);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
