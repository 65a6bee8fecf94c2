/* game_frame: one frame of a whole (tiny) first-person game, in the order such games issue it,
 * with a walking camera: every class in one frame, so that the classes must be told apart from
 * one another and not only from the world.
 *
 *   sky      a sky box (one glBegin of six faces) first, depth writes off, unlit, camera
 *            rotation only (centred on the eye)                                        -> sky
 *   world    floor and four pillars                                                     -> static
 *            a ceiling fan spinning (same vertices, new rotation each frame)            -> static
 *                                                                 in frame 0, then moving
 *   lightmap the floor again: GL_EQUAL, no depth writes, DST_COLOR/ZERO               -> multipass
 *   decal    a blood splat on pillar 0's front face: polygon offset -1, -1, blended    -> decal
 *   shadow   the fan projected onto the floor by a point light's shadow matrix,
 *            black, alpha 0.5                                                           -> shadow
 *   window   a large glass pane, SRC_ALPHA/ONE_MINUS_SRC_ALPHA, no depth writes        -> blended
 *   smoke    16 small camera-facing quads, additive, no depth writes                    ->
 * particles gun      in eye space, glDepthRange(0, 0.1)                                         ->
 * viewmodel HUD      a translucent panel under glOrtho and three glBitmap digits                ->
 * overlay
 *
 * Five still objects against one moving: the camera motion is the one the still ones agree on.
 */
#include "../label_harness.h"

static const GLubyte digit_bits[3][8] = {{0x00, 0x70, 0x88, 0x98, 0xA8, 0xC8, 0x88, 0x70},
                                         {0x00, 0x70, 0x20, 0x20, 0x20, 0x20, 0x60, 0x20},
                                         {0x00, 0xF8, 0x40, 0x20, 0x10, 0x08, 0x88, 0x70}};
static GLuint floor_texture, lightmap, smoke;

static void setup(void) {
  static const GLubyte a[4] = {150, 140, 120, 255}, b[4] = {110, 100, 90, 255};
  floor_texture = lbl_checker_texture(8, 2, a, b);
  static const GLubyte c[4] = {255, 255, 230, 255}, d[4] = {110, 110, 130, 255};
  lightmap = lbl_checker_texture(4, 2, c, d);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  static const GLubyte gray[3] = {120, 120, 120};
  smoke = lbl_blob_texture(16, gray, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
}

static void sky_box(void) {
  glBegin(GL_QUADS);
  for (int face = 0; face < 6; ++face) {
    static const float v[6][4][3] = {{{1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}},
                                     {{-1, -1, 1}, {-1, -1, -1}, {-1, 1, -1}, {-1, 1, 1}},
                                     {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}},
                                     {{-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}},
                                     {{1, -1, 1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}},
                                     {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}}};
    for (int k = 0; k < 4; ++k) {
      glColor3f(0.4f, 0.5f + 0.2f * v[face][k][1], 0.9f);
      glVertex3f(8.0f * v[face][k][0], 8.0f * v[face][k][1], 8.0f * v[face][k][2]);
    }
  }
  glEnd();
}

static void fan_transform(int f) {
  glTranslatef(0.0f, 2.6f, -2.0f);
  glRotatef(35.0f * (float)f, 0.0f, 1.0f, 0.0f);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float yaw = 0.1f * (float)f - 0.2f;
  const float eye[3] = {0.3f * (float)f, 1.6f, 6.0f - 0.4f * (float)f};
  const float center[3] = {eye[0] + sinf(yaw), 1.5f, eye[2] - cosf(yaw)};
  static const float up[3] = {0.0f, 1.0f, 0.0f};
  float right[3], upv[3], forward[3];
  lbl_camera_basis(eye, center, up, right, upv, forward);

  /* sky */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lbl_perspective(70.0f, 4.0f / 3.0f, 0.1f, 100.0f);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const float origin[3] = {0.0f, 0.0f, 0.0f};
  lbl_look_at(origin, forward, up);
  glDisable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  label("sky", "sky");
  sky_box();
  glDepthMask(GL_TRUE);

  /* world */
  glLoadIdentity();
  lbl_look_at(eye, center, up);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBindTexture(GL_TEXTURE_2D, floor_texture);
  label("static", "floor");
  lbl_grid(6, 6.0f);
  glDisable(GL_TEXTURE_2D);
  lbl_light(0.3f, 1.0f, 0.6f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(i % 2 ? 2.5f : -2.5f, 1.5f, i < 2 ? -1.0f : -4.0f);
    glColor3f(0.6f, 0.55f, 0.5f + 0.1f * (float)i);
    labelf("static", "pillar%d", i, 0);
    lbl_box(0.4f, 1.5f, 0.4f);
    glPopMatrix();
  }
  glPushMatrix();
  fan_transform(f);
  glColor3f(0.3f, 0.3f, 0.35f);
  label(f == 0 ? "static" : "moving", "fan");
  lbl_box(1.2f, 0.04f, 0.15f);
  glPopMatrix();
  glDisable(GL_LIGHTING);

  /* lightmap pass over the floor */
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBindTexture(GL_TEXTURE_2D, lightmap);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  label("multipass", "floor_lightmap");
  lbl_grid(6, 6.0f);
  glDepthFunc(GL_LESS);
  glDisable(GL_TEXTURE_2D);

  /* decal on pillar 0's front face (z = -1 + 0.4) */
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -1.0f);
  glColor4f(0.6f, 0.0f, 0.0f, 0.8f);
  label("decal", "splat");
  lbl_quad_xy(-2.75f, 1.2f, -2.3f, 1.7f, -0.6f);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);

  /* planar shadow of the fan on the floor, from a point light above it */
  {
    static const float plane[4] = {0.0f, 1.0f, 0.0f, -0.01f};
    static const float light[4] = {0.5f, 4.0f, -1.5f, 1.0f};
    float dot = plane[1] * light[1] + plane[3] * light[3];
    GLfloat m[16];
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row)
        m[col * 4 + row] = (row == col ? dot : 0.0f) - light[row] * plane[col];
    glPushMatrix();
    glMultMatrixf(m);
    fan_transform(f);
    glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
    label("shadow", "fan_shadow");
    lbl_box(1.2f, 0.04f, 0.15f);
    glPopMatrix();
  }

  /* window */
  glDepthMask(GL_FALSE);
  glColor4f(0.5f, 0.8f, 0.9f, 0.3f);
  label("blended", "window");
  lbl_quad_xy(-1.5f, 0.3f, 1.5f, 2.3f, -3.0f);

  /* smoke */
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBindTexture(GL_TEXTURE_2D, smoke);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor3f(1.0f, 1.0f, 1.0f);
  label("particles", "smoke");
  glBegin(GL_QUADS);
  for (int i = 0; i < 16; ++i) {
    float t = (float)((f + i) % 8) * 0.25f;
    float p[3] = {1.5f + 0.3f * sinf((float)i), 0.2f + 0.8f * t, -1.5f + 0.3f * cosf((float)i)};
    static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
      float sx = 0.08f * corners[k][0], sy = 0.08f * corners[k][1];
      glTexCoord2f(0.5f + 0.5f * corners[k][0], 0.5f + 0.5f * corners[k][1]);
      glVertex3f(p[0] + sx * right[0] + sy * upv[0], p[1] + sx * right[1] + sy * upv[1],
                 p[2] + sx * right[2] + sy * upv[2]);
    }
  }
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);

  /* gun */
  glLoadIdentity();
  lbl_light(0.3f, 1.0f, 0.6f);
  glDepthRange(0.0, 0.1);
  glTranslatef(0.2f, -0.2f + 0.015f * sinf(2.0f * (float)f), -0.45f);
  glColor3f(0.2f, 0.22f, 0.25f);
  label("viewmodel", "gun");
  lbl_box(0.05f, 0.06f, 0.22f);
  glDepthRange(0.0, 1.0);
  glDisable(GL_LIGHTING);

  /* HUD */
  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
  label("overlay", "hud_panel");
  lbl_quad_2d(0.0f, 0.0f, 40.0f, 14.0f);
  glDisable(GL_BLEND);
  glColor3f(1.0f, 0.9f, 0.2f);
  glRasterPos2i(4, 3);
  for (int i = 0; i < 3; ++i) {
    labelf("overlay", "hud_digit%d_f%d", i, f); /* the bitmap changes: a new key every frame */
    glBitmap(8, 8, 0.0f, 0.0f, 8.0f, 0.0f, digit_bits[(i + f) % 3]);
  }
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
