/* hud_ortho_nodepthwrite: a translucent HUD drawn after the world under glOrtho with depth
 * writes off (glDepthMask(GL_FALSE)) and the depth test off, blended (SRC_ALPHA,
 * ONE_MINUS_SRC_ALPHA); textured icons; glRecti.
 *
 * World: a still camera, a floor and three still boxes (`static`), one spinning fan in front
 * (`static` in frame 0, then `moving`: new rotation, same vertices; three of four objects still,
 * so the camera is still).
 *
 * Labels: HUD panel, the two icons and the ammo bar `overlay` (glOrtho; blending in 2-D is not
 * `blended`, which is for translucent surfaces in the 3-D view).
 */
#include "../label_harness.h"

static GLuint icon;

static void setup(void) {
  static const GLubyte a[4] = {255, 220, 0, 255}, b[4] = {40, 40, 40, 128};
  icon = lbl_checker_texture(8, 2, a, b);
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  const float eye[3] = {0.0f, 3.0f, 8.0f}, center[3] = {0.0f, 0.5f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 100.0f, eye, center);
  lbl_light(0.5f, 1.0f, 0.3f);
  glColor3f(0.5f, 0.5f, 0.55f);
  label("static", "floor");
  lbl_grid(4, 6.0f);
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-3.0f + 3.0f * (float)i, 0.5f, -2.5f);
    glColor3f(0.2f + 0.3f * (float)i, 0.4f, 0.8f - 0.2f * (float)i);
    labelf("static", "box%d", i, 0);
    lbl_box(0.5f, 0.5f, 0.5f);
    glPopMatrix();
  }
  glPushMatrix();
  glTranslatef(0.0f, 1.5f, 1.5f);
  glRotatef(30.0f * (float)f, 0.0f, 0.0f, 1.0f);
  glColor3f(0.8f, 0.8f, 0.2f);
  label(f == 0 ? "static" : "moving", "fan");
  lbl_box(1.2f, 0.15f, 0.05f);
  glPopMatrix();
  glDisable(GL_LIGHTING);

  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0.0f, 0.0f, 0.2f, 0.5f);
  label("overlay", "panel");
  lbl_quad_2d(4.0f, 4.0f, 156.0f, 24.0f);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, icon);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  label("overlay", "icon_armor");
  lbl_quad_2d(8.0f, 8.0f, 20.0f, 20.0f);
  label("overlay", "icon_ammo");
  lbl_quad_2d(100.0f, 8.0f, 112.0f, 20.0f);
  glDisable(GL_TEXTURE_2D);
  glColor4f(1.0f, 0.6f, 0.0f, 0.8f);
  label("overlay", "ammo_bar");
  glRecti(116, 10, 116 + 36 - 5 * f, 18);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
