/* detail_texture: a heightfield terrain (one glBegin(GL_TRIANGLES), 12x12 cells, 288 triangles)
 * with its base texture, then a detail-texture pass over a SUBSET of its triangles (the cells
 * nearest the camera, rows 6..11: 144 triangles) with exactly the same vertex positions,
 * glDepthFunc(GL_LEQUAL), glDepthMask(GL_FALSE), blending GL_DST_COLOR / GL_ZERO (modulate),
 * a fine repeating detail texture (texture coordinates x3). Two rocks stand on the terrain.
 * Still camera.
 *
 * Labels: terrain `static`; detail pass `multipass` (a later pass over a subset of a surface's
 * triangles, same positions, LEQUAL, no depth writes, modulating blend); rocks `static`.
 */
#include "../label_harness.h"

enum { N = 12 };
static GLuint base_texture, detail_texture;

static float height(int i, int j) {
  return 0.6f * sinf(0.7f * (float)i) * cosf(0.5f * (float)j) + 0.02f * (float)(i * j % 5);
}

static void vertex(int i, int j, float tscale) {
  glTexCoord2f((float)i / N * tscale, (float)j / N * tscale);
  glVertex3f(-6.0f + (float)i, height(i, j), -6.0f + (float)j);
}

/* cells with first_row <= j < N */
static void terrain(int first_row, float tscale) {
  glBegin(GL_TRIANGLES);
  for (int j = first_row; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      vertex(i, j, tscale);
      vertex(i, j + 1, tscale);
      vertex(i + 1, j + 1, tscale);
      vertex(i, j, tscale);
      vertex(i + 1, j + 1, tscale);
      vertex(i + 1, j, tscale);
    }
  }
  glEnd();
}

static void setup(void) {
  static const GLubyte a[4] = {90, 140, 60, 255}, b[4] = {120, 110, 70, 255};
  base_texture = lbl_checker_texture(8, 4, a, b);
  static const GLubyte c[4] = {255, 255, 255, 255}, d[4] = {170, 170, 170, 255};
  detail_texture = lbl_checker_texture(8, 1, c, d);
  glClearColor(0.6f, 0.7f, 0.9f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void frame(int f) {
  (void)f;
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {0.0f, 4.0f, 9.0f}, center[3] = {0.0f, 0.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, base_texture);
  glColor3f(1.0f, 1.0f, 1.0f);
  label("static", "terrain");
  terrain(0, 4.0f);

  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glBindTexture(GL_TEXTURE_2D, detail_texture);
  label("multipass", "terrain_detail");
  terrain(N / 2, 12.0f);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_TEXTURE_2D);

  lbl_light(0.4f, 1.0f, 0.3f);
  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glTranslatef(i ? 2.5f : -3.0f, 1.0f, i ? -2.0f : 1.0f);
    glColor3f(0.5f, 0.5f, 0.55f);
    labelf("static", "rock%d", i, 0);
    lbl_box(0.6f, 0.5f, 0.5f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) { return label_run(argc, argv, 5, setup, frame); }
