/* decals_overlap: bullet holes accumulating on a wall, one more every frame, overlapping each
 * other: small textured quads coplanar with the wall, drawn with glEnable(GL_POLYGON_OFFSET_FILL)
 * and glPolygonOffset(-1, -1), blended SRC_ALPHA / ONE_MINUS_SRC_ALPHA, depth writes off. One
 * opaque poster decal (polygon offset, unblended, depth writes on) and a scorch mark on the floor
 * drawn without polygon offset but with depth writes off and GL_LEQUAL. The camera sways.
 *
 * Labels: wall, floor and two crates `static` (the camera moves; four of four agree); every
 * decal `decal` (hole<i> exists from frame i on: a new draw in a later frame).
 */
#include "../label_harness.h"

static GLuint hole, poster;

static void setup(void) {
  static const GLubyte black[3] = {20, 15, 10};
  hole = lbl_blob_texture(16, black, 0);
  static const GLubyte a[4] = {230, 60, 40, 255}, b[4] = {250, 220, 90, 255};
  poster = lbl_checker_texture(8, 2, a, b);
  glClearColor(0.5f, 0.6f, 0.7f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {-1.0f + 0.5f * (float)f, 1.8f, 6.0f - 0.2f * (float)f};
  const float center[3] = {0.0f, 1.5f, -2.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.3f, 50.0f, eye, center);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  lbl_light(0.3f, 0.8f, 1.0f);
  glColor3f(0.75f, 0.72f, 0.65f);
  label("static", "wall");
  lbl_quad_xy(-4.0f, 0.0f, 4.0f, 3.5f, -2.0f);
  glColor3f(0.4f, 0.4f, 0.42f);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, 2.0f);
  label("static", "floor");
  lbl_grid(4, 4.0f);
  glPopMatrix();
  for (int i = 0; i < 2; ++i) {
    glPushMatrix();
    glTranslatef(i ? 2.5f : -2.8f, 0.5f, 0.0f);
    glColor3f(0.55f, 0.4f, 0.2f);
    labelf("static", "crate%d", i, 0);
    lbl_box(0.5f, 0.5f, 0.5f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -1.0f);
  glBindTexture(GL_TEXTURE_2D, poster);
  glColor3f(1.0f, 1.0f, 1.0f);
  label("decal", "poster");
  lbl_quad_xy(-3.0f, 1.0f, -2.0f, 2.4f, -2.0f);

  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glBindTexture(GL_TEXTURE_2D, hole);
  for (int i = 0; i <= f && i < 8; ++i) {
    /* each hole under its own translation (as a decal system places each decal), so a new hole
     * never merges into the entry of the one before it */
    glPushMatrix();
    glTranslatef(0.3f * (float)i - 0.6f, 1.6f + 0.25f * sinf(2.1f * (float)i), -2.0f);
    labelf("decal", "hole%d", i, 0);
    lbl_quad_xy(-0.3f, -0.3f, 0.3f, 0.3f, 0.0f);
    glPopMatrix();
  }
  glDisable(GL_POLYGON_OFFSET_FILL);

  glDepthFunc(GL_LEQUAL);
  glPushMatrix();
  glTranslatef(0.5f, 0.0f, 1.0f);
  label("decal", "scorch");
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f);
  glVertex3f(-0.6f, 0.0f, 0.6f);
  glTexCoord2f(1.0f, 0.0f);
  glVertex3f(0.6f, 0.0f, 0.6f);
  glTexCoord2f(1.0f, 1.0f);
  glVertex3f(0.6f, 0.0f, -0.6f);
  glTexCoord2f(0.0f, 1.0f);
  glVertex3f(-0.6f, 0.0f, -0.6f);
  glEnd();
  glPopMatrix();
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
