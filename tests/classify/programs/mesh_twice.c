/* mesh_twice: one mesh (a statue, glBegin/glEnd with the same vertices) drawn twice in every
 * frame at two places, consecutively, with the same state apart from the modelview, plus a
 * plinth under each. Still camera.
 *
 * Labels: every draw `static`. The two statue draws are two draws: two keys (statue_a,
 * statue_b), so two different ids, each stable over the frames; they must not be taken for one
 * object (same vertices) nor swap ids between frames.
 */
#include "../label_harness.h"

static void statue(void) {
  /* an octahedron on a post, as GL_TRIANGLES */
  static const float top[3] = {0, 2.0f, 0}, bottom[3] = {0, 1.0f, 0};
  static const float ring[4][3] = {
      {0.5f, 1.5f, 0}, {0, 1.5f, -0.5f}, {-0.5f, 1.5f, 0}, {0, 1.5f, 0.5f}};
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 4; ++i) {
    const float* a = ring[i];
    const float* b = ring[(i + 1) % 4];
    glNormal3f(a[0] + b[0], 0.7f, a[2] + b[2]);
    glVertex3fv(a);
    glVertex3fv(b);
    glVertex3fv(top);
    glNormal3f(a[0] + b[0], -0.7f, a[2] + b[2]);
    glVertex3fv(b);
    glVertex3fv(a);
    glVertex3fv(bottom);
  }
  glNormal3f(0, 0, 1);
  glVertex3f(-0.1f, 0.0f, 0.0f);
  glVertex3f(0.1f, 0.0f, 0.0f);
  glVertex3f(0.0f, 1.2f, 0.0f);
  glEnd();
}

static void setup(void) {
  glClearColor(0.2f, 0.25f, 0.3f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  (void)f;
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {0.0f, 2.5f, 6.0f}, center[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  lbl_light(0.4f, 1.0f, 0.7f);
  glColor3f(0.3f, 0.3f, 0.3f);
  label("static", "floor");
  lbl_grid(4, 5.0f);
  glColor3f(0.85f, 0.75f, 0.3f);
  glPushMatrix();
  glTranslatef(-1.5f, 0.3f, 0.0f);
  label("static", "statue_a");
  statue();
  glPopMatrix();
  glPushMatrix();
  glTranslatef(1.5f, 0.3f, 0.0f);
  label("static", "statue_b");
  statue();
  glPopMatrix();
  glColor3f(0.6f, 0.6f, 0.62f);
  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glTranslatef(i ? 1.5f : -1.5f, 0.15f, 0.0f);
    labelf("static", "plinth%d", i, 0);
    lbl_box(0.4f, 0.15f, 0.4f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 5, setup, frame); }
