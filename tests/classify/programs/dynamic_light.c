/* dynamic_light: Quake-style dynamic lights. A textured floor (one glBegin(GL_TRIANGLES), 10x10
 * cells) and back wall (8x4 cells) are drawn, with three pillars; then a light that circles over
 * the floor adds its light in an additive pass (glBlendFunc(GL_ONE, GL_ONE), glDepthFunc(GL_EQUAL),
 * glDepthMask(GL_FALSE), untextured, vertex colour = the light's falloff) over only the floor
 * and wall triangles within its radius: a subset of each surface's triangles, with the same
 * vertex positions, and a different subset every frame as the light moves. Still camera.
 *
 * Labels: floor, wall and pillars `static`; the floor's and the wall's light passes `multipass`.
 * The light always reaches some floor triangles; the wall pass is drawn (and labelled) only in
 * the frames where the light reaches the wall. The light passes' keys name the frame
 * (floor_light_f<F>): their triangle count changes from frame to frame, so no identity across
 * frames is asked of them.
 */
#include "../label_harness.h"

static GLuint tiles;
static float light[3];
static const float radius = 3.2f;

static void floor_vertex(int i, int j) {
  glTexCoord2f((float)i * 0.5f, (float)j * 0.5f);
  glVertex3f(-5.0f + (float)i, 0.0f, -5.0f + (float)j);
}
static void wall_vertex(int i, int j) {
  glTexCoord2f((float)i * 0.5f, (float)j * 0.5f);
  glVertex3f(-4.0f + (float)i, (float)j, -5.0f);
}
static float falloff(float x, float y, float z) {
  float dx = x - light[0], dy = y - light[1], dz = z - light[2];
  float d = sqrtf(dx * dx + dy * dy + dz * dz) / radius;
  return d >= 1.0f ? 0.0f : 1.0f - d;
}
static void lit_vertex(float x, float y, float z) {
  float a = falloff(x, y, z);
  glColor3f(a, 0.8f * a, 0.4f * a);
  glVertex3f(x, y, z);
}
/* cell corners within the light's radius: does any corner get light? */
static int floor_cell_lit(int i, int j) {
  return falloff(-5.0f + (float)i + 0.5f, 0.0f, -5.0f + (float)j + 0.5f) > 0.0f;
}
static int wall_cell_lit(int i, int j) {
  return falloff(-4.0f + (float)i + 0.5f, (float)j + 0.5f, -5.0f) > 0.0f;
}

static void floor_pass(int lit) {
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < 10; ++j) {
    for (int i = 0; i < 10; ++i) {
      if (lit && !floor_cell_lit(i, j)) continue;
      const int c[6][2] = {{i, j}, {i, j + 1}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i + 1, j}};
      for (int k = 0; k < 6; ++k) {
        if (lit)
          lit_vertex(-5.0f + (float)c[k][0], 0.0f, -5.0f + (float)c[k][1]);
        else
          floor_vertex(c[k][0], c[k][1]);
      }
    }
  }
  glEnd();
}

static void wall_pass(int lit) {
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 8; ++i) {
      if (lit && !wall_cell_lit(i, j)) continue;
      const int c[6][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}};
      for (int k = 0; k < 6; ++k) {
        if (lit)
          lit_vertex(-4.0f + (float)c[k][0], (float)c[k][1], -5.0f);
        else
          wall_vertex(c[k][0], c[k][1]);
      }
    }
  }
  glEnd();
}

static int any_wall_cell_lit(void) {
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 8; ++i)
      if (wall_cell_lit(i, j)) return 1;
  return 0;
}

static void setup(void) {
  static const GLubyte a[4] = {110, 110, 120, 255}, b[4] = {80, 80, 90, 255};
  tiles = lbl_checker_texture(8, 4, a, b);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float a = 0.9f * (float)f;
  light[0] = 2.5f * cosf(a);
  light[1] = 1.0f;
  light[2] = -1.5f + 2.5f * sinf(a);
  const float eye[3] = {0.0f, 5.0f, 8.0f}, center[3] = {0.0f, 0.5f, -1.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tiles);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(0.7f, 0.7f, 0.7f);
  label("static", "floor");
  floor_pass(0);
  label("static", "wall");
  wall_pass(0);
  glDisable(GL_TEXTURE_2D);
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-3.5f + 3.5f * (float)i, 1.0f, 2.0f);
    glColor3f(0.4f, 0.3f + 0.15f * (float)i, 0.5f);
    labelf("static", "pillar%d", i, 0);
    lbl_box(0.3f, 1.0f, 0.3f);
    glPopMatrix();
  }

  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  labelf("multipass", "floor_light_f%d", f, 0);
  floor_pass(1);
  if (any_wall_cell_lit()) {
    labelf("multipass", "wall_light_f%d", f, 0);
    wall_pass(1);
  }
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

int main(int argc, char** argv) { return label_run(argc, argv, 8, setup, frame); }
