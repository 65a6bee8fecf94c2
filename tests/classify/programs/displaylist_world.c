/* displaylist_world: the world compiled once into display lists (glNewList(GL_COMPILE) in
 * setup) and replayed every frame with glCallList under a moving camera. The "town" list holds
 * four drawing commands: the ground (glBegin/glEnd), two calls of the nested "tower" list at two
 * places (each one glBegin/glEnd), and a hall (glBegin/glEnd); the tower list is also called
 * twice directly from the frame. Colours and translations live inside the lists.
 *
 * Labels are given when the lists are executed, one per drawing command executed: per frame
 * town = 4 labels (ground, tower_a, tower_b, hall), then 2 more towers (tower_c, tower_d): 6.
 * All `static`: the camera moves, six of six draws agree.
 */
#include "../label_harness.h"

static GLuint town, tower;

static void setup(void) {
  tower = glGenLists(2);
  town = tower + 1;
  glNewList(tower, GL_COMPILE);
  glColor3f(0.75f, 0.7f, 0.6f);
  lbl_box(0.5f, 2.0f, 0.5f);
  glEndList();

  glNewList(town, GL_COMPILE);
  glColor3f(0.4f, 0.5f, 0.3f);
  lbl_grid(8, 12.0f); /* ground */
  glPushMatrix();
  glTranslatef(-4.0f, 2.0f, -3.0f);
  glCallList(tower); /* tower_a */
  glTranslatef(8.0f, 0.0f, 0.0f);
  glCallList(tower); /* tower_b */
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.0f, 1.0f, -5.0f);
  glColor3f(0.6f, 0.3f, 0.25f);
  lbl_box(2.5f, 1.0f, 1.5f); /* hall */
  glPopMatrix();
  glEndList();

  glClearColor(0.5f, 0.6f, 0.8f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float a = 0.3f * (float)f - 0.3f;
  const float eye[3] = {14.0f * sinf(a), 5.0f, 14.0f * cosf(a)};
  const float center[3] = {0.0f, 1.0f, -1.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.5f);
  label("static", "ground");
  label("static", "tower_a");
  label("static", "tower_b");
  label("static", "hall");
  glCallList(town);
  glPushMatrix();
  glTranslatef(-4.0f, 2.0f, 4.0f);
  label("static", "tower_c");
  glCallList(tower);
  glTranslatef(8.0f, 0.0f, 0.0f);
  label("static", "tower_d");
  glCallList(tower);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
