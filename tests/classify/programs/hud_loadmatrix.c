/* hud_loadmatrix: a HUD whose projection is an orthographic matrix written by hand and loaded
 * with glLoadMatrixf (pixel coordinates, origin at the top left, y down), not glOrtho; a
 * glDrawPixels icon; a minimap quad. Depth test off for the HUD.
 *
 * World: a camera that walks forward over a floor with four still crates (`static`: only the
 * camera moves, five of five objects agree).
 *
 * Labels: HUD panel, minimap, glDrawPixels icon and the minimap's player marker `overlay`.
 */
#include "../label_harness.h"

static GLubyte icon_pixels[16 * 16 * 4];

static void setup(void) {
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      GLubyte* p = icon_pixels + 4 * (y * 16 + x);
      int inside = (x - 8) * (x - 8) + (y - 8) * (y - 8) < 49;
      p[0] = inside ? 255 : 30;
      p[1] = inside ? (GLubyte)(16 * x) : 30;
      p[2] = inside ? 40 : 30;
      p[3] = 255;
    }
  }
  glClearColor(0.25f, 0.3f, 0.35f, 1.0f);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const float eye[3] = {0.0f, 1.7f, 10.0f - 1.0f * (float)f};
  const float center[3] = {0.3f, 1.2f, -10.0f};
  lbl_camera(65.0f, 4.0f / 3.0f, 0.3f, 100.0f, eye, center);
  lbl_light(0.2f, 1.0f, 0.2f);
  glColor3f(0.45f, 0.4f, 0.35f);
  label("static", "floor");
  lbl_grid(10, 15.0f);
  static const float crates[4][2] = {{-2, -3}, {2, -6}, {-3, -9}, {1.5f, 0}};
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(crates[i][0], 0.7f, crates[i][1]);
    glColor3f(0.55f, 0.4f, 0.2f + 0.1f * (float)i);
    labelf("static", "crate%d", i, 0);
    lbl_box(0.7f, 0.7f, 0.7f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  /* ortho(0, W, H, 0, -1, 1) by hand, column-major */
  const GLfloat ortho[16] = {
      2.0f / LBL_WIDTH, 0, 0, 0, 0, -2.0f / LBL_HEIGHT, 0, 0, 0, 0, -1, 0, -1, 1, 0, 1};
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(ortho);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glColor3f(0.1f, 0.1f, 0.1f);
  label("overlay", "panel");
  lbl_quad_2d(0.0f, 96.0f, 160.0f, 120.0f);
  glColor3f(0.2f, 0.35f, 0.2f);
  label("overlay", "minimap");
  lbl_quad_2d(120.0f, 4.0f, 156.0f, 40.0f);
  glColor3f(1.0f, 1.0f, 0.0f);
  label("overlay", "marker");
  lbl_quad_2d(136.0f, 30.0f - 2.0f * (float)f, 140.0f, 34.0f - 2.0f * (float)f);
  /* y down: the raster position is the icon's lower left corner in window terms */
  glRasterPos2i(6, 116);
  label("overlay", "icon");
  glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_BYTE, icon_pixels);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
