/* culled_object: a walking camera over six objects; the statue (object 3) is culled by the
 * program (not drawn at all) in frames 2 and 3, as a portal or frustum culler would do, and
 * drawn again from frame 4 on, at the same place. Another object (the well) appears only from
 * frame 1 on.
 *
 * Labels: every draw `static`: the statue when it comes back is unchanged in the world (and must
 * get the id it had in frames 0 and 1: same key); the well in frame 1, its first frame, is
 * `static` too. Only the camera moves (at least five still objects agree in every frame).
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.55f, 0.6f, 0.7f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {-1.0f + 0.4f * (float)f, 2.0f, 9.0f - 0.8f * (float)f};
  const float center[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 60.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.4f);
  glColor3f(0.4f, 0.5f, 0.3f);
  label("static", "ground");
  lbl_grid(8, 10.0f);
  static const float objects[5][4] = {{-3, 0.5f, -2, 0.5f},
                                      {3, 0.8f, -3, 0.8f},
                                      {-1, 0.4f, 2, 0.4f},
                                      {1.5f, 1.0f, 0, 0.3f},
                                      {-4, 0.7f, 3, 0.7f}};
  static const char* const names[5] = {"rock", "hut", "crate", "statue", "shed"};
  for (int i = 0; i < 5; ++i) {
    if (i == 3 && (f == 2 || f == 3)) continue; /* culled */
    glPushMatrix();
    glTranslatef(objects[i][0], objects[i][1], objects[i][2]);
    glColor3f(0.6f + 0.05f * (float)i, 0.5f, 0.4f - 0.05f * (float)i);
    label("static", names[i]);
    lbl_box(objects[i][3], i == 3 ? 1.0f : objects[i][3], objects[i][3]);
    glPopMatrix();
  }
  if (f >= 1) {
    glPushMatrix();
    glTranslatef(3.5f, 0.3f, 2.5f);
    glColor3f(0.4f, 0.4f, 0.5f);
    label("static", "well");
    lbl_box(0.5f, 0.3f, 0.5f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 7, setup, frame); }
