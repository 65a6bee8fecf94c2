/* lightmap_multipass: Quake-style lightmapping in two passes. A room of six surfaces (floor,
 * ceiling, four walls: one glBegin(GL_QUADS) each) drawn with its base texture, then every
 * surface again with the same vertex positions and its lightmap: glDepthFunc(GL_EQUAL),
 * glDepthMask(GL_FALSE), blending GL_DST_COLOR / GL_ZERO (modulate). The camera walks through
 * the room (off its centre: the room drawn first with depth writes is not a sky).
 *
 * Labels: the six base passes `static` (the camera moves, six of six surfaces agree); the six
 * lightmap passes `multipass` (a later pass over a surface already drawn this frame, same
 * vertex positions, depth func EQUAL, no depth writes, modulating blend).
 */
#include "../label_harness.h"

static GLuint base_texture, lightmap;

static void setup(void) {
  static const GLubyte a[4] = {170, 120, 90, 255}, b[4] = {140, 95, 70, 255};
  base_texture = lbl_checker_texture(16, 4, a, b);
  static GLubyte texels[16 * 16 * 4];
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      float d = sqrtf((float)((x - 5) * (x - 5) + (y - 10) * (y - 10))) / 12.0f;
      GLubyte v = (GLubyte)(255.0f * (d > 1.0f ? 0.25f : 1.0f - 0.75f * d));
      GLubyte* t = texels + 4 * (y * 16 + x);
      t[0] = v;
      t[1] = v;
      t[2] = (GLubyte)(v * 0.8f);
      t[3] = 255;
    }
  }
  glGenTextures(1, &lightmap);
  glBindTexture(GL_TEXTURE_2D, lightmap);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

/* Surface s of the room x -5..5, y 0..4, z -5..5, texture coordinates scaled by tscale. */
static void surface(int s, float tscale) {
  static const float v[6][4][3] = {{{-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}},   /* floor */
                                   {{-5, 4, -5}, {5, 4, -5}, {5, 4, 5}, {-5, 4, 5}},   /* ceiling */
                                   {{-5, 0, -5}, {5, 0, -5}, {5, 4, -5}, {-5, 4, -5}}, /* back */
                                   {{5, 0, 5}, {-5, 0, 5}, {-5, 4, 5}, {5, 4, 5}},     /* front */
                                   {{-5, 0, 5}, {-5, 0, -5}, {-5, 4, -5}, {-5, 4, 5}}, /* left */
                                   {{5, 0, -5}, {5, 0, 5}, {5, 4, 5}, {5, 4, -5}}};    /* right */
  static const float t[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  glBegin(GL_QUADS);
  for (int k = 0; k < 4; ++k) {
    glTexCoord2f(t[k][0] * tscale, t[k][1] * tscale);
    glVertex3fv(v[s][k]);
  }
  glEnd();
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  float yaw = 0.3f * (float)f - 0.4f;
  const float eye[3] = {-2.5f + 0.3f * (float)f, 1.2f, 2.5f - 0.4f * (float)f};
  const float center[3] = {eye[0] + sinf(yaw), 1.3f, eye[2] - cosf(yaw)};
  lbl_camera(75.0f, 4.0f / 3.0f, 0.1f, 50.0f, eye, center);
  static const char* const names[6] = {"floor", "ceiling", "back", "front", "left", "right"};
  char key[32];

  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glBindTexture(GL_TEXTURE_2D, base_texture);
  for (int s = 0; s < 6; ++s) {
    snprintf(key, sizeof key, "%s_base", names[s]);
    label("static", key);
    surface(s, 3.0f);
  }

  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glBindTexture(GL_TEXTURE_2D, lightmap);
  for (int s = 0; s < 6; ++s) {
    snprintf(key, sizeof key, "%s_lightmap", names[s]);
    label("multipass", key);
    surface(s, 1.0f);
  }
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
