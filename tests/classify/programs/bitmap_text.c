/* bitmap_text: text drawn with glBitmap (one glBitmap per character, as glutBitmapCharacter and
 * glXUseXFont display lists do) after the world: a fixed title "SCORE" and a three-digit
 * counter whose digits change every frame. The raster position comes from glOrtho + glRasterPos2i.
 *
 * World: still camera, ground, four still boxes (`static`).
 *
 * Labels: every glBitmap `overlay`. Keys: the title's characters title0..4 (same bitmap, same
 * place every frame: same key, same id expected); the counter's digits digit<i>_f<F>, a key of
 * their own in every frame (a digit's bitmap changes: no identity across frames is asked of
 * it). The digits have another raster colour than the title, so the title never shares an entry
 * with them.
 */
#include "../label_harness.h"

/* 5x7 glyphs, top row first; '#' is a set pixel. */
static const char* const glyph_rows[][7] = {
    {" ### ", "#   #", "#  ##", "# # #", "##  #", "#   #", " ### "}, /* 0 */
    {"  #  ", " ##  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}, /* 1 */
    {" ### ", "#   #", "    #", "   # ", "  #  ", " #   ", "#####"}, /* 2 */
    {"#####", "   # ", "  #  ", "   # ", "    #", "#   #", " ### "}, /* 3 */
    {"   # ", "  ## ", " # # ", "#  # ", "#####", "   # ", "   # "}, /* 4 */
    {"#####", "#    ", "#### ", "    #", "    #", "#   #", " ### "}, /* 5 */
    {"  ## ", " #   ", "#    ", "#### ", "#   #", "#   #", " ### "}, /* 6 */
    {"#####", "    #", "   # ", "  #  ", " #   ", " #   ", " #   "}, /* 7 */
    {" ### ", "#   #", "#   #", " ### ", "#   #", "#   #", " ### "}, /* 8 */
    {" ### ", "#   #", "#   #", " ####", "    #", "   # ", " ##  "}, /* 9 */
    {" ####", "#    ", "#    ", " ### ", "    #", "    #", "#### "}, /* S 10 */
    {" ### ", "#   #", "#    ", "#    ", "#    ", "#   #", " ### "}, /* C 11 */
    {" ### ", "#   #", "#   #", "#   #", "#   #", "#   #", " ### "}, /* O 12 */
    {"#### ", "#   #", "#   #", "#### ", "# #  ", "#  # ", "#   #"}, /* R 13 */
    {"#####", "#    ", "#    ", "#### ", "#    ", "#    ", "#####"}, /* E 14 */
};
enum { kGlyphs = sizeof glyph_rows / sizeof glyph_rows[0] };
static GLubyte glyphs[kGlyphs][8]; /* 8x8 bitmaps, bottom row first, one byte a row */

static void setup(void) {
  for (int g = 0; g < kGlyphs; ++g) {
    glyphs[g][0] = 0;
    for (int r = 0; r < 7; ++r) {
      GLubyte bits = 0;
      for (int c = 0; c < 5; ++c) {
        if (glyph_rows[g][r][c] == '#') bits |= (GLubyte)(0x80 >> c);
      }
      glyphs[g][7 - r] = bits;
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glClearColor(0.1f, 0.15f, 0.2f, 1.0f);
}

static void frame(int f) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const float eye[3] = {0.0f, 4.0f, 8.0f}, center[3] = {0.0f, 0.0f, 0.0f};
  lbl_camera(60.0f, 4.0f / 3.0f, 0.5f, 50.0f, eye, center);
  lbl_light(0.3f, 1.0f, 0.5f);
  glColor3f(0.3f, 0.35f, 0.4f);
  label("static", "ground");
  lbl_grid(6, 7.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(-3.0f + 2.0f * (float)i, 0.5f, 0.0f);
    glColor3f(0.8f, 0.3f, 0.3f + 0.15f * (float)i);
    labelf("static", "box%d", i, 0);
    lbl_box(0.5f, 0.5f, 0.5f);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);

  lbl_ortho_pixels(LBL_WIDTH, LBL_HEIGHT);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1.0f, 1.0f, 0.3f);
  glRasterPos2i(8, 104);
  static const int title[5] = {10, 11, 12, 13, 14};
  for (int i = 0; i < 5; ++i) {
    labelf("overlay", "title%d", i, 0);
    glBitmap(8, 8, 0.0f, 0.0f, 8.0f, 0.0f, glyphs[title[i]]);
  }
  int score = 100 + 37 * f;
  const int digits[3] = {score / 100 % 10, score / 10 % 10, score % 10};
  glColor3f(0.4f, 1.0f, 0.4f);   /* the digits in another colour (taken by glRasterPos) */
  glRasterPos2i(8 + 6 * 8, 104); /* after a space */
  for (int i = 0; i < 3; ++i) {
    labelf("overlay", "digit%d_f%d", i, f);
    glBitmap(8, 8, 0.0f, 0.0f, 8.0f, 0.0f, glyphs[digits[i]]);
  }
}

int main(int argc, char** argv) { return label_run(argc, argv, 6, setup, frame); }
