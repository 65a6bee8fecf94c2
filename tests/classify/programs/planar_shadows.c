/* planar_shadows: classic fake planar shadows. Each caster is drawn a second time, black at
 * alpha 0.5, blended, unlit, under the modelview multiplied by a shadow matrix that projects
 * onto the ground plane y = 0.01 from a light; the stencil test (GL_EQUAL 0, then GL_INCR)
 * keeps overlapping shadow triangles from darkening a pixel twice. The two cubes' shadows come
 * from a point light (the matrix's bottom row is not (0, 0, 0, 1)), the two pillars' from a
 * directional light (w = 0). Still camera.
 *
 * Labels: ground, the still cube and the pillars `static`; the spinning cube `static` in
 * frame 0, then `moving`; the four shadows `shadow`.
 */
#include "../label_harness.h"

static void shadow_matrix(const float plane[4], const float light[4]) {
  float dot = plane[0] * light[0] + plane[1] * light[1] + plane[2] * light[2] + plane[3] * light[3];
  GLfloat m[16];
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) {
      m[col * 4 + row] = (row == col ? dot : 0.0f) - light[row] * plane[col];
    }
  }
  glMultMatrixf(m);
}

static void setup(void) {
  glClearColor(0.6f, 0.7f, 0.85f, 1.0f);
  glClearStencil(0);
  glEnable(GL_DEPTH_TEST);
}

typedef struct {
  float x, y, z, hx, hy, hz;
} Caster;
static const Caster casters[4] = {{-1.5f, 0.6f, 0.0f, 0.6f, 0.6f, 0.6f},
                                  {1.5f, 1.2f, 0.5f, 0.5f, 0.5f, 0.5f},
                                  {-3.5f, 1.0f, -2.0f, 0.2f, 1.0f, 0.2f},
                                  {3.5f, 1.0f, -2.0f, 0.2f, 1.0f, 0.2f}};
static const char* const names[4] = {"cube", "spinner", "pillar0", "pillar1"};

static void place(int i, int f) {
  glTranslatef(casters[i].x, casters[i].y, casters[i].z);
  if (i == 1) glRotatef(20.0f * (float)f, 1.0f, 1.0f, 0.0f);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  const float eye[3] = {0.0f, 5.0f, 9.0f}, center[3] = {0.0f, 0.5f, 0.0f};
  lbl_camera(55.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  lbl_light(0.2f, 1.0f, 0.3f);
  glColor3f(0.5f, 0.6f, 0.4f);
  label("static", "ground");
  lbl_grid(8, 6.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    place(i, f);
    glColor3f(0.8f, 0.3f + 0.15f * (float)i, 0.2f);
    label(i == 1 && f > 0 ? "moving" : "static", names[i]);
    lbl_box(casters[i].hx, casters[i].hy, casters[i].hz);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  static const float ground_plane[4] = {0.0f, 1.0f, 0.0f, -0.01f};
  static const float point_light[4] = {1.0f, 6.0f, 2.0f, 1.0f};
  static const float sun[4] = {0.4f, 1.0f, 0.3f, 0.0f};
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, ~0u);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
  char key[32];
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    shadow_matrix(ground_plane, i < 2 ? point_light : sun);
    place(i, f);
    snprintf(key, sizeof key, "%s_shadow", names[i]);
    label("shadow", key);
    lbl_box(casters[i].hx, casters[i].hy, casters[i].hz);
    glPopMatrix();
  }
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
