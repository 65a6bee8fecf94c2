/* lightmap_multitexture: the same lightmapped room as lightmap_multipass, but in ONE pass:
 * texture unit 0 holds the base texture, unit 1 the lightmap (GL_MODULATE), texture coordinates
 * through glMultiTexCoord2f (GL 1.3 multitexture). The camera walks through the room.
 *
 * Labels: the six surfaces `static` (opaque, single pass; the camera moves, six of six agree).
 */
#include "../label_harness.h"

static GLuint base_texture, lightmap;

static void setup(void) {
  static const GLubyte a[4] = {120, 130, 170, 255}, b[4] = {90, 100, 140, 255};
  base_texture = lbl_checker_texture(16, 4, a, b);
  static GLubyte texels[16 * 16 * 4];
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      float d = sqrtf((float)((x - 10) * (x - 10) + (y - 6) * (y - 6))) / 12.0f;
      GLubyte v = (GLubyte)(255.0f * (d > 1.0f ? 0.25f : 1.0f - 0.75f * d));
      GLubyte* t = texels + 4 * (y * 16 + x);
      t[0] = (GLubyte)(v * 0.9f);
      t[1] = v;
      t[2] = v;
      t[3] = 255;
    }
  }
  glActiveTexture(GL_TEXTURE1);
  glGenTextures(1, &lightmap);
  glBindTexture(GL_TEXTURE_2D, lightmap);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, base_texture);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
}

static void surface(int s) {
  static const float v[6][4][3] = {{{-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}},
                                   {{-5, 4, -5}, {5, 4, -5}, {5, 4, 5}, {-5, 4, 5}},
                                   {{-5, 0, -5}, {5, 0, -5}, {5, 4, -5}, {-5, 4, -5}},
                                   {{5, 0, 5}, {-5, 0, 5}, {-5, 4, 5}, {5, 4, 5}},
                                   {{-5, 0, 5}, {-5, 0, -5}, {-5, 4, -5}, {-5, 4, 5}},
                                   {{5, 0, -5}, {5, 0, 5}, {5, 4, 5}, {5, 4, -5}}};
  static const float t[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  glBegin(GL_QUADS);
  for (int k = 0; k < 4; ++k) {
    glMultiTexCoord2f(GL_TEXTURE0, t[k][0] * 3.0f, t[k][1] * 3.0f);
    glMultiTexCoord2f(GL_TEXTURE1, t[k][0], t[k][1]);
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
  for (int s = 0; s < 6; ++s) {
    label("static", names[s]);
    surface(s);
  }
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
