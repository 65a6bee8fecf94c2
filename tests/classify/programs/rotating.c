/* rotating: a lone cube spinning in front of a still camera (glDrawElements, colour array).
 *
 * Labels: frame 0 `static` (first frame: nothing to compare with); every later frame `moving`:
 * the same vertices under a new rotation each frame. It is the only object, and the camera
 * (the look-at part of the modelview) never changes, so the change is the object's own
 * (convention 3: a lone rotating object in front of a still camera is moving).
 */
#include "../label_harness.h"

static const GLfloat vertices[8 * 3] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                        -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
static const GLubyte colors[8 * 3] = {255, 0, 0,   0, 255, 0,   0,   0,   255, 255, 255, 0,
                                      255, 0, 255, 0, 255, 255, 255, 255, 255, 90,  90,  90};
static const GLushort indices[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                     3, 6, 2, 3, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};

static void setup(void) {
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, vertices);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, colors);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {0.0f, 1.0f, 6.0f}, center[3] = {0.0f, 0.0f, 0.0f};
  lbl_camera(50.0f, 4.0f / 3.0f, 1.0f, 50.0f, eye, center);
  glRotatef(23.0f * (float)f, 0.3f, 1.0f, 0.1f);
  label(f == 0 ? "static" : "moving", "cube");
  glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, indices);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
