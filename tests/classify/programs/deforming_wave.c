/* deforming_wave: a water grid whose heights change every frame (a sine wave travelling over
 * it), next to two still posts, in front of a still camera.
 *
 * The grid is one glDrawElements of GL_TRIANGLES over a 17x17 vertex array whose y values the
 * program rewrites every frame; the index array (topology) and vertex count never change. Its
 * colours also change (colour alone would not make it deforming; the positions do).
 *
 * Labels: grid frame 0 `static` (first frame), then `deforming` (new positions, same primitive
 * mode and vertex count, same modelview). Posts `static` (same vertices and modelview).
 */
#include "../label_harness.h"

enum { N = 17 };
static GLfloat positions[N * N * 3];
static GLfloat colors[N * N * 3];
static GLushort indices[(N - 1) * (N - 1) * 6];

static void setup(void) {
  int k = 0;
  for (int j = 0; j + 1 < N; ++j) {
    for (int i = 0; i + 1 < N; ++i) {
      GLushort a = (GLushort)(j * N + i), b = (GLushort)(a + 1), c = (GLushort)(a + N),
               d = (GLushort)(a + N + 1);
      GLushort q[6] = {a, c, d, a, d, b};
      memcpy(indices + k, q, sizeof q);
      k += 6;
    }
  }
  glClearColor(0.6f, 0.7f, 0.8f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {0.0f, 5.0f, 9.0f}, center[3] = {0.0f, 0.0f, 0.0f};
  lbl_camera(55.0f, 4.0f / 3.0f, 1.0f, 50.0f, eye, center);
  float phase = 0.9f * (float)f;
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      float x = -4.0f + 8.0f * (float)i / (N - 1), z = -4.0f + 8.0f * (float)j / (N - 1);
      float y = 0.4f * sinf(1.3f * x + phase) * cosf(0.9f * z + 0.5f * phase);
      GLfloat* p = positions + 3 * (j * N + i);
      p[0] = x;
      p[1] = y;
      p[2] = z;
      GLfloat* c = colors + 3 * (j * N + i);
      c[0] = 0.1f;
      c[1] = 0.35f + y;
      c[2] = 0.7f + 0.5f * y;
    }
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glColorPointer(3, GL_FLOAT, 0, colors);
  label(f == 0 ? "static" : "deforming", "water");
  glDrawElements(GL_TRIANGLES, (N - 1) * (N - 1) * 6, GL_UNSIGNED_SHORT, indices);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);

  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glTranslatef(i ? 4.8f : -4.8f, 1.0f, -2.0f);
    glColor3f(0.5f, 0.35f, 0.2f);
    labelf("static", "post%d", i, 0);
    lbl_box(0.3f, 1.5f, 0.3f);
    glPopMatrix();
  }
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
