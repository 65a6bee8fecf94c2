/* blend_left_on: a program that never disables GL_BLEND (as trigger-rally does): its opaque
 * world is drawn with glBlendFunc(GL_ONE, GL_ZERO), which writes every fragment as it is, and a
 * crate with a colour logic op of GL_COPY (the same); its one translucent pane with
 * GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA; a glow with GL_ONE, GL_ONE (additive: it mixes). The
 * camera pans.
 *
 * Labels: ground, two pillars and the crate `static`; the pane and the glow `blended`.
 */
#include "../label_harness.h"

static void setup(void) {
  glClearColor(0.5f, 0.6f, 0.75f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);  /* and never off */
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {-3.0f + 0.8f * (float)f, 2.0f, 8.0f};
  const float center[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.3f, 80.0f, eye, center);
  glBlendFunc(GL_ONE, GL_ZERO);
  lbl_light(0.3f, 1.0f, 0.6f);
  glColor3f(0.45f, 0.5f, 0.4f);
  label("static", "ground");
  lbl_grid(6, 12.0f);
  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glTranslatef(i == 0 ? -3.0f : 3.0f, 1.5f, -2.0f);
    glColor3f(0.7f, 0.6f - 0.2f * (float)i, 0.5f);
    label("static", i == 0 ? "pillar0" : "pillar1");
    lbl_box(0.4f, 1.5f, 0.4f);
    glPopMatrix();
  }
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_COPY);
  glPushMatrix();
  glTranslatef(0.5f, 0.4f, 1.0f);
  glColor3f(0.6f, 0.4f, 0.2f);
  label("static", "crate");
  lbl_box(0.4f, 0.4f, 0.4f);
  glPopMatrix();
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_LIGHTING);

  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glColor4f(0.3f, 0.7f, 0.8f, 0.4f);
  label("blended", "pane");
  lbl_quad_xy(-2.0f, 0.0f, 2.0f, 2.5f, -0.5f);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(0.4f, 0.3f, 0.1f, 1.0f);
  label("blended", "glow");
  lbl_quad_xy(-4.0f, 3.5f, 4.0f, 4.5f, -3.0f);
  glDepthMask(GL_TRUE);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
