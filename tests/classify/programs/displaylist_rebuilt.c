/* displaylist_rebuilt: a program that rebuilds its display list every frame (a new list name
 * from glGenLists, compiled with GL_COMPILE, the previous list deleted with glDeleteLists) with
 * the same content each time, then calls it. The list holds two drawing commands: a glBegin/glEnd
 * cabinet and a glDrawArrays roof (client arrays are read when the list is compiled). Three more
 * objects are drawn directly. Still camera.
 *
 * Labels (when the list is executed, one per drawing command inside it): cabinet and roof
 * `static` in every frame with the same keys (the same draws, whatever the list's name; new
 * list, same content: same id); the floor and two lamps `static`.
 */
#include "../label_harness.h"

static GLuint list;
static const GLfloat roof[] = {-1.2f, 2.0f, 0.8f,  1.2f,  2.0f, 0.8f,  0.0f, 2.8f, 0.0f,
                               1.2f,  2.0f, -0.8f, -1.2f, 2.0f, -0.8f, 0.0f, 2.8f, 0.0f,
                               -1.2f, 2.0f, -0.8f, -1.2f, 2.0f, 0.8f,  0.0f, 2.8f, 0.0f,
                               1.2f,  2.0f, 0.8f,  1.2f,  2.0f, -0.8f, 0.0f, 2.8f, 0.0f};

static void setup(void) {
  glClearColor(0.3f, 0.3f, 0.35f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  (void)f;
  GLuint rebuilt = glGenLists(1);
  glNewList(rebuilt, GL_COMPILE);
  glPushMatrix();
  glTranslatef(0.0f, 1.0f, 0.0f);
  glColor3f(0.55f, 0.35f, 0.2f);
  lbl_box(1.0f, 1.0f, 0.7f); /* cabinet */
  glPopMatrix();
  glColor3f(0.7f, 0.2f, 0.2f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, roof);
  glDrawArrays(GL_TRIANGLES, 0, 12); /* roof */
  glDisableClientState(GL_VERTEX_ARRAY);
  glEndList();
  if (list) glDeleteLists(list, 1);
  list = rebuilt;

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {3.0f, 3.0f, 7.0f}, center[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.5f);
  glColor3f(0.45f, 0.45f, 0.4f);
  label("static", "floor");
  lbl_grid(4, 5.0f);
  label("static", "cabinet");
  label("static", "roof");
  glCallList(list);
  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glTranslatef(i ? 2.5f : -2.5f, 0.8f, 1.0f);
    glColor3f(0.9f, 0.85f, 0.5f);
    labelf("static", "lamp%d", i, 0);
    lbl_box(0.15f, 0.8f, 0.15f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
