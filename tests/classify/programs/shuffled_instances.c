/* shuffled_instances: six identical meshes (the same vertex array, the same state apart from the
 * modelview) at six places, drawn in a different pseudo-random order every frame (Fisher-Yates
 * with a fixed-seed LCG), as engines that sort by distance or material do. In frame 3 one of
 * them (barrel4) jumps far away (from (2, 0, -1) to (8, 0, -30)) and stays there. Still camera.
 *
 * Labels: the ground and every barrel `static`, except barrel4 in frame 3: `moving` (same
 * vertices, new transform relative to the world). Keys follow the objects, not the draw order:
 * a barrel keeps its key (and so must keep its id) wherever it falls in the order.
 */
#include "../label_harness.h"

enum { kBarrels = 6, kSides = 10 };
static GLfloat positions[kSides * 6 * 3], normals[kSides * 6 * 3];
static uint32_t rng = 2024u;

static void setup(void) {
  int k = 0;
  for (int i = 0; i < kSides; ++i) {
    float a0 = 2.0f * LBL_PI * (float)i / kSides, a1 = 2.0f * LBL_PI * (float)(i + 1) / kSides;
    const float c[6][2] = {{a0, 0}, {a1, 0}, {a1, 1.2f}, {a0, 0}, {a1, 1.2f}, {a0, 1.2f}};
    for (int v = 0; v < 6; ++v, ++k) {
      positions[3 * k] = 0.4f * cosf(c[v][0]);
      positions[3 * k + 1] = c[v][1];
      positions[3 * k + 2] = -0.4f * sinf(c[v][0]);
      normals[3 * k] = cosf(c[v][0]);
      normals[3 * k + 1] = 0.0f;
      normals[3 * k + 2] = -sinf(c[v][0]);
    }
  }
  glClearColor(0.45f, 0.5f, 0.55f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {0.0f, 3.5f, 8.0f}, center[3] = {0.0f, 0.0f, -2.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.5f);
  glColor3f(0.4f, 0.4f, 0.35f);
  label("static", "ground");
  lbl_grid(8, 10.0f);

  float places[kBarrels][3];
  for (int i = 0; i < kBarrels; ++i) {
    places[i][0] = -3.0f + 2.5f * (float)(i % 3);
    places[i][1] = 0.0f;
    places[i][2] = i < 3 ? 1.0f : -1.0f;
  }
  if (f >= 3) {
    places[4][0] = 8.0f;
    places[4][2] = -30.0f;
  }
  int order[kBarrels];
  for (int i = 0; i < kBarrels; ++i) order[i] = i;
  for (int i = kBarrels - 1; i > 0; --i) {
    int j = (int)(lbl_rand(&rng) % (uint32_t)(i + 1));
    int t = order[i];
    order[i] = order[j];
    order[j] = t;
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glNormalPointer(GL_FLOAT, 0, normals);
  glColor3f(0.7f, 0.2f, 0.15f);
  for (int n = 0; n < kBarrels; ++n) {
    int i = order[n];
    glPushMatrix();
    glTranslatef(places[i][0], places[i][1], places[i][2]);
    labelf(i == 4 && f == 3 ? "moving" : "static", "barrel%d", i, 0);
    glDrawArrays(GL_TRIANGLES, 0, kSides * 6);
    glPopMatrix();
  }
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
