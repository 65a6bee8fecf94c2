/* atlas_text: text drawn as blended textured quads from a font atlas texture under glOrtho
 * (as Quake 3 and most engines do): one glBegin(GL_QUADS) per line of 12 characters, blended
 * SRC_ALPHA / ONE_MINUS_SRC_ALPHA, depth test off. Both lines change every frame: the ticker
 * scrolls (new positions) and shows new characters (new texture coordinates); the message line
 * bobs up and down and changes characters. Same vertex count every frame.
 *
 * World: still camera, floor and four still pillars (`static`).
 *
 * Labels: both text lines `overlay` (2-D under glOrtho; new positions or texture coordinates do
 * not make 2-D text deforming); the world `static`.
 */
#include "../label_harness.h"

static GLuint atlas;

static void setup(void) {
  /* 64x64 atlas, 8x8 cells of 8x8 texels, 64 glyphs of pseudo-random pixels */
  static GLubyte texels[64 * 64 * 4];
  uint32_t state = 4242u;
  for (int cell = 0; cell < 64; ++cell) {
    int cx = (cell % 8) * 8, cy = (cell / 8) * 8;
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        int on = x > 0 && x < 7 && y > 0 && y < 7 && (lbl_rand(&state) & 1);
        GLubyte* t = texels + 4 * ((cy + y) * 64 + cx + x);
        t[0] = t[1] = t[2] = 255;
        t[3] = on ? 255 : 0;
      }
    }
  }
  glGenTextures(1, &atlas);
  glBindTexture(GL_TEXTURE_2D, atlas);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glClearColor(0.3f, 0.2f, 0.25f, 1.0f);
}

static void text_line(float x, float y, int first_glyph, float bob, int frame_index) {
  glBegin(GL_QUADS);
  for (int i = 0; i < 12; ++i) {
    int g = (first_glyph + 5 * i) % 64;
    float s0 = (float)(g % 8) / 8.0f, t0 = (float)(g / 8) / 8.0f, d = 1.0f / 8.0f;
    float x0 = x + 8.0f * (float)i;
    float y0 = y + bob * sinf(0.8f * (float)(i + frame_index));
    glTexCoord2f(s0, t0);
    glVertex2f(x0, y0);
    glTexCoord2f(s0 + d, t0);
    glVertex2f(x0 + 8.0f, y0);
    glTexCoord2f(s0 + d, t0 + d);
    glVertex2f(x0 + 8.0f, y0 + 8.0f);
    glTexCoord2f(s0, t0 + d);
    glVertex2f(x0, y0 + 8.0f);
  }
  glEnd();
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const float eye[3] = {-3.0f, 3.0f, 7.0f}, center[3] = {0.0f, 1.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.5f);
  glColor3f(0.5f, 0.45f, 0.5f);
  label("static", "floor");
  lbl_grid(6, 7.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-3.0f + 2.0f * (float)i, 1.0f, -1.5f);
    glColor3f(0.3f, 0.6f, 0.7f - 0.1f * (float)i);
    labelf("static", "pillar%d", i, 0);
    lbl_box(0.35f, 1.0f, 0.35f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, atlas);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 1.0f, 0.6f, 1.0f);
  label("overlay", "ticker");
  text_line(120.0f - 11.0f * (float)f, 104.0f, 3 * f, 0.0f, f);
  glColor4f(0.6f, 1.0f, 1.0f, 0.8f);
  label("overlay", "message");
  text_line(32.0f, 10.0f, 7 + f, 2.0f, f);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
