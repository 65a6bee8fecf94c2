/* blend_left_on: a program that never disables GL_BLEND (as trigger-rally and torcs do): its
 * opaque world is drawn with glBlendFunc(GL_ONE, GL_ZERO), which writes every fragment as it is,
 * and a crate with a colour logic op of GL_COPY (the same). Under GL_SRC_ALPHA,
 * GL_ONE_MINUS_SRC_ALPHA: a lit barrel (material alpha 1) and a box textured with an RGBA
 * checker whose texels all have alpha 255, modulated by a colour of alpha 1 (opaque: drawn as
 * they are); a fence textured with a checker of opaque and clear texels, a box lit with a
 * material of alpha 0.5, and a translucent pane (they show what is behind them); a glow with
 * GL_ONE, GL_ONE (additive: it mixes). The camera pans.
 *
 * Labels: ground, two pillars, the crate, the barrel and the textured box `static`; the fence,
 * the glass box, the pane and the glow `blended`.
 */
#include "../label_harness.h"

static GLuint opaque_checker, fence_checker;

static void setup(void) {
  glClearColor(0.5f, 0.6f, 0.75f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND); /* and never off */
  const GLubyte brown[4] = {150, 100, 50, 255}, tan[4] = {200, 170, 120, 255};
  const GLubyte wire[4] = {90, 90, 90, 255}, hole[4] = {0, 0, 0, 0};
  opaque_checker = lbl_checker_texture(16, 4, brown, tan);
  fence_checker = lbl_checker_texture(16, 2, wire, hole);
  glBindTexture(GL_TEXTURE_2D, 0);
}

static void box_at(const char* cls, const char* name, float x, float z, float h) {
  glPushMatrix();
  glTranslatef(x, h, z);
  label(cls, name);
  lbl_box(h, h, h);
  glPopMatrix();
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

  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const GLfloat solid[4] = {0.3f, 0.5f, 0.3f, 1.0f}, glass[4] = {0.6f, 0.8f, 0.9f, 0.5f};
  glDisable(GL_COLOR_MATERIAL); /* the materials' own alpha, not the current colour's */
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, solid);
  box_at("static", "barrel", -1.5f, 1.5f, 0.35f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, glass);
  box_at("blended", "glass_box", 1.8f, 1.8f, 0.3f);
  glEnable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  glBindTexture(GL_TEXTURE_2D, opaque_checker);
  box_at("static", "textured_box", -0.6f, 2.5f, 0.3f);
  glBindTexture(GL_TEXTURE_2D, fence_checker);
  label("blended", "fence");
  lbl_quad_xy(-4.0f, 0.0f, -1.0f, 1.2f, -1.0f);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_TEXTURE_2D);

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
