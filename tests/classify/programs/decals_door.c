/* decals_door: a door swings open in frames 1..4 and stays open in frames 5..6; a poster and a
 * number plate are decals on the door (drawn under the door's modelview, coplanar with its front
 * face, polygon offset -1, -1, blended), so they swing with it. A sign decal on the still wall.
 * Still camera.
 *
 * Labels: the walls, lintel and floor `static`. The door: `static` in frame 0 (first frame),
 * `moving` in frames 1..4 (new rotation about its hinge, same vertices), `static` again in
 * frames 5..6 (same transform as the frame before). The poster and plate `decal` in every frame
 * (small coplanar quads with polygon offset: the decal class wins over their motion), the sign
 * `decal`.
 */
#include "../label_harness.h"

static GLuint poster, plate;

static float door_angle(int f) { return f <= 4 ? 15.0f * (float)f : 60.0f; }

static void setup(void) {
  static const GLubyte a[4] = {40, 80, 200, 230}, b[4] = {240, 240, 240, 230};
  poster = lbl_checker_texture(8, 2, a, b);
  static const GLubyte c[4] = {220, 200, 60, 255}, d[4] = {120, 100, 20, 255};
  plate = lbl_checker_texture(4, 1, c, d);
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye[3] = {1.5f, 1.6f, 5.0f}, center[3] = {0.0f, 1.2f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.3f, 50.0f, eye, center);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  lbl_light(0.4f, 0.7f, 1.0f);
  glColor3f(0.7f, 0.65f, 0.6f);
  label("static", "wall_left");
  lbl_quad_xy(-4.0f, 0.0f, -0.6f, 3.0f, 0.0f);
  label("static", "wall_right");
  lbl_quad_xy(0.6f, 0.0f, 4.0f, 3.0f, 0.0f);
  label("static", "lintel");
  lbl_quad_xy(-0.6f, 2.2f, 0.6f, 3.0f, 0.0f);
  glColor3f(0.35f, 0.3f, 0.25f);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, 2.0f);
  label("static", "floor");
  lbl_grid(4, 4.0f);
  glPopMatrix();

  /* the door: hinge at x = -0.6, z = 0 */
  glPushMatrix();
  glTranslatef(-0.6f, 0.0f, 0.0f);
  glRotatef(door_angle(f), 0.0f, 1.0f, 0.0f);
  glTranslatef(0.6f, 1.1f, 0.05f);
  glColor3f(0.5f, 0.3f, 0.15f);
  int door_moves = f >= 1 && door_angle(f) != door_angle(f - 1);
  label(door_moves ? "moving" : "static", "door");
  lbl_box(0.6f, 1.1f, 0.05f);
  glDisable(GL_LIGHTING);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -1.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  glBindTexture(GL_TEXTURE_2D, poster);
  label("decal", "door_poster");
  lbl_quad_xy(-0.35f, -0.2f, 0.35f, 0.6f, 0.05f);
  glBindTexture(GL_TEXTURE_2D, plate);
  label("decal", "door_plate");
  lbl_quad_xy(-0.15f, 0.75f, 0.15f, 0.9f, 0.05f);
  glPopMatrix();

  glBindTexture(GL_TEXTURE_2D, plate);
  label("decal", "wall_sign");
  lbl_quad_xy(1.2f, 1.6f, 2.2f, 2.0f, 0.0f);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
}

int main(int argc, char** argv) { return label_run(argc, argv, 7, setup, frame); }
