// The pixel scenes: plain GL 1.5 calls, run by both runners. Each starts from a fresh context.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "scene_runner.hpp"

namespace glpt::pixel_ops {
namespace {

// ---- helpers
// -------------------------------------------------------------------------------------

void clear(float r, float g, float b) {
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// Window coordinates: one unit per pixel, z in [-1, 1] -> depth [0, 1] (near = -1 is depth 0).
void pixel_projection(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, 0, height, 1, -1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

// A 5x7 font for a few characters; rows top to bottom, bit 7 is the left column.
struct Glyph {
  char c;
  GLubyte rows[7];
};
const Glyph kFont[] = {
    {'A', {0x70, 0x88, 0x88, 0xF8, 0x88, 0x88, 0x88}},
    {'B', {0xF0, 0x88, 0x88, 0xF0, 0x88, 0x88, 0xF0}},
    {'C', {0x70, 0x88, 0x80, 0x80, 0x80, 0x88, 0x70}},
    {'G', {0x70, 0x88, 0x80, 0xB8, 0x88, 0x88, 0x78}},
    {'L', {0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0xF8}},
    {'P', {0xF0, 0x88, 0x88, 0xF0, 0x80, 0x80, 0x80}},
    {'T', {0xF8, 0x20, 0x20, 0x20, 0x20, 0x20, 0x20}},
    {'X', {0x88, 0x88, 0x50, 0x20, 0x50, 0x88, 0x88}},
    {'1', {0x20, 0x60, 0x20, 0x20, 0x20, 0x20, 0x70}},
    {'5', {0xF8, 0x80, 0xF0, 0x08, 0x08, 0x88, 0x70}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x60, 0x60}},
    {' ', {0, 0, 0, 0, 0, 0, 0}},
};

// glBitmap text at the current raster position, 6 pixels per character.
void text(const char* s) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (; *s; ++s) {
    for (const Glyph& g : kFont) {
      if (g.c != *s) continue;
      GLubyte bottom_up[7];
      for (int r = 0; r < 7; ++r) bottom_up[r] = g.rows[6 - r];
      glBitmap(5, 7, 0, 0, 6, 0, bottom_up);
    }
  }
}

// A w x h RGBA8 image with a distinct colour per pixel.
std::vector<GLubyte> pattern(int w, int h) {
  std::vector<GLubyte> p(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      GLubyte* q = &p[(size_t(y) * w + x) * 4];
      q[0] = GLubyte(40 + x * 200 / std::max(1, w - 1));
      q[1] = GLubyte(40 + y * 200 / std::max(1, h - 1));
      q[2] = GLubyte(((x + y) & 1) ? 230 : 60);
      q[3] = GLubyte(255 - x * 3);
    }
  return p;
}

// ---- raster position and bitmaps ----------------------------------------------------------------

void bitmap_glyphs() {
  clear(0.1f, 0.1f, 0.2f);
  pixel_projection(96, 64);
  glColor3f(1, 1, 0.3f);
  glRasterPos2i(4, 50);
  glColor3f(1, 0, 0);  // after glRasterPos: the line keeps the latched colour
  text("GLPT 1.5");
  glRasterPos2f(4.7f, 36.2f);  // a fractional raster position: bitmaps land on floor(x + 1e-4)
  text("ABC.");
  glColor3f(0.3f, 1, 0.5f);
  glRasterPos2f(40.99995f, 36.0f);  // within Mesa's 1e-4 of 41
  text("XL");
  // A 16x16 bitmap with an origin offset and moves; unpack row length and skips.
  GLubyte block[4 * 20];
  for (int r = 0; r < 20; ++r)
    for (int c = 0; c < 4; ++c) block[r * 4 + c] = GLubyte((r * 37 + c * 91) ^ 0x5A);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 32);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glColor3f(0.5f, 0.7f, 1);
  glRasterPos2i(20, 8);
  glBitmap(16, 16, 4, 2, 20, 3, block);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
  glBitmap(16, 16, -4.5f, 2, 0, 0, block);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  // Partly outside the window.
  glColor3f(1, 0.5f, 0);
  glRasterPos2i(88, 60);
  text("XX");
}

void bitmap_raster_transform() {
  clear(0.1f, 0.1f, 0.2f);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  GLubyte square[8];
  std::memset(square, 0xFF, sizeof square);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < 7; ++i) {
    glPushMatrix();
    glTranslatef(-2.0f + i * 0.7f, std::sin(i * 1.3f) * 1.5f, -4.0f - i * 0.5f);
    glRotatef(20.0f * i, 0, 0, 1);
    glColor3f(0.2f + 0.1f * i, 1.0f - 0.1f * i, 0.5f);
    glRasterPos3f(0.3f, 0.2f, 0.1f);
    glBitmap(8, 8, 4, 4, 0, 0, square);
    glPopMatrix();
  }
  // Invalid positions (beside and behind the view volume) draw nothing and do not move.
  glColor3f(1, 0, 0);
  glRasterPos3f(50, 0, -5);
  glBitmap(8, 8, 0, 0, -60, 0, square);
  glBitmap(0, 0, 0, 0, -60, 0, nullptr);
  glRasterPos3f(0, 0, 2);
  glBitmap(8, 8, 0, 0, 0, 0, square);
  // A zero-size bitmap moves a valid position even off the window and back.
  glColor3f(1, 1, 1);
  glRasterPos3f(0, 0, -2);
  glBitmap(0, 0, 0, 0, 200, 0, nullptr);
  glBitmap(8, 8, 0, 0, -210, -20, square);  // off-window: nothing visible, still moves
  glBitmap(8, 8, 0, 0, 0, 0, square);
}

void bitmap_lit_raster_color() {
  clear(0.05f, 0.05f, 0.05f);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const float position[4] = {2, 3, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  const float spot[3] = {0, -0.5f, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spot);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 70.0f);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.05f);
  glEnable(GL_COLOR_MATERIAL);
  GLubyte square[12 * 2];
  std::memset(square, 0xFF, sizeof square);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < 16; ++i) {
    glLoadIdentity();
    glTranslatef(-1.5f + (i % 4) * 1.0f, -1.5f + (i / 4) * 1.0f, -5.0f);
    glColor3f(0.3f + 0.04f * i, 0.9f - 0.05f * i, 0.4f);
    glNormal3f(0.2f * (i % 3), 0.3f, 1.0f);
    glRasterPos3f(0.1f, 0.1f, 0.2f);
    glBitmap(12, 12, 6, 6, 0, 0, square);
  }
}

void window_pos_depth() {
  clear(0.2f, 0.2f, 0.2f);
  pixel_projection(64, 64);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.2f, 0.4f, 1.0f);
  quad(8, 8, 56, 56, 0.0f);  // depth 0.5
  GLubyte square[16 * 2];
  std::memset(square, 0xFF, sizeof square);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < 6; ++i) {
    glColor3f(1.0f, 0.2f * i, 0.0f);
    glWindowPos3f(2.0f + i * 10.0f, 2.0f + i * 8.0f, 0.2f * i);  // depths 0 .. 1
    glBitmap(16, 16, 0, 0, 0, 0, square);
  }
  glDepthRange(0.6, 0.2);  // reversed: glWindowPos z 0 -> depth 0.6
  glColor3f(0, 1, 0);
  glWindowPos2f(30.5f, 4.5f);
  glBitmap(16, 16, 0, 0, 0, 0, square);
}

// ---- glDrawPixels
// ---------------------------------------------------------------------------------

void drawpixels_formats() {
  clear(0.3f, 0.3f, 0.3f);
  pixel_projection(96, 64);
  const std::vector<GLubyte> p = pattern(12, 10);
  std::vector<GLubyte> rgb, lum, lum_alpha, one;
  for (size_t i = 0; i < p.size(); i += 4) {
    rgb.insert(rgb.end(), {p[i], p[i + 1], p[i + 2]});
    lum.push_back(p[i]);
    lum_alpha.insert(lum_alpha.end(), {p[i + 1], p[i + 3]});
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(2, 2);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glRasterPos2i(16, 2);
  glDrawPixels(12, 10, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  glRasterPos2i(30, 2);
  glDrawPixels(12, 10, GL_BGR, GL_UNSIGNED_BYTE, rgb.data());
  glRasterPos2i(44, 2);
  glDrawPixels(12, 10, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum.data());
  glRasterPos2i(58, 2);
  glDrawPixels(12, 10, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, lum_alpha.data());
  glRasterPos2i(72, 2);
  glDrawPixels(12, 10, GL_ALPHA, GL_UNSIGNED_BYTE, lum.data());  // RGB 0, alpha from the image
  glRasterPos2i(2, 16);
  glDrawPixels(12, 10, GL_GREEN, GL_UNSIGNED_BYTE, lum.data());
  glRasterPos2i(16, 16);
  glDrawPixels(12, 10, GL_BGRA, GL_UNSIGNED_BYTE, p.data());
  // Other element types: floats (out of range values clamp), shorts, signed bytes.
  std::vector<float> f(12 * 10 * 4);
  for (size_t i = 0; i < f.size(); ++i) f[i] = float(i % 23) / 15.0f - 0.2f;
  glRasterPos2i(30, 16);
  glDrawPixels(12, 10, GL_RGBA, GL_FLOAT, f.data());
  std::vector<GLushort> us(12 * 10 * 3);
  for (size_t i = 0; i < us.size(); ++i) us[i] = GLushort(i * 2741u);
  glRasterPos2i(44, 16);
  glDrawPixels(12, 10, GL_RGB, GL_UNSIGNED_SHORT, us.data());
  std::vector<GLbyte> sb(12 * 10 * 3);
  for (size_t i = 0; i < sb.size(); ++i) sb[i] = GLbyte(int(i * 37) % 256 - 128);
  glRasterPos2i(58, 16);
  glDrawPixels(12, 10, GL_RGB, GL_BYTE, sb.data());
  // Unpack modes: alignment 4 with 3-byte pixels, row length, skips.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 12);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glRasterPos2i(72, 16);
  glDrawPixels(9, 6, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  // Rounded raster positions (half away from zero), partly off-window, glWindowPos.
  glRasterPos2f(2.5f, 30.49f);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glRasterPos2f(89.5f, 58.5f);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glWindowPos2i(-5, 44);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
}

void drawpixels_zoom() {
  clear(0.1f, 0.1f, 0.1f);
  pixel_projection(96, 96);
  const std::vector<GLubyte> p = pattern(6, 5);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const struct {
    float x, y, zx, zy;
  } cases[] = {
      {2, 2, 2, 3},        {20.4f, 2.6f, 2.5f, 1.5f}, {50, 20, -1.5f, -2},    {60, 2, 3.3f, 0.7f},
      {2, 40, 0.5f, 0.5f}, {20, 58, -0.6f, -0.75f},   {40, 40, 1.25f, -3.1f}, {70, 40, 4, 4},
      {5, 70, -3, 2.2f}};
  for (const auto& c : cases) {
    glPixelZoom(c.zx, c.zy);
    glRasterPos2f(c.x, c.y);
    glDrawPixels(6, 5, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  }
  glPixelZoom(0, 2);  // no fragments
  glRasterPos2i(80, 80);
  glDrawPixels(6, 5, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
}

void drawpixels_depth() {
  clear(0.1f, 0.1f, 0.3f);
  pixel_projection(64, 64);
  glEnable(GL_DEPTH_TEST);
  // A ramp in depth, then images at a raster depth that cuts through it.
  glBegin(GL_QUADS);
  glColor3f(0.8f, 0.8f, 0.2f);
  glVertex3f(0, 0, -1);
  glVertex3f(64, 0, 1);
  glVertex3f(64, 32, 1);
  glVertex3f(0, 32, -1);
  glEnd();
  const std::vector<GLubyte> p = pattern(16, 16);
  glPixelZoom(3, 1.5f);
  glRasterPos3f(4, 4, 0.1f);
  glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glPixelZoom(1, 1);
  // A depth image (raster colour, image depth) through the depth test, then colour against it.
  std::vector<float> depth(32 * 24);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      depth[size_t(y) * 32 + x] = float(x) / 31.0f * 0.8f + float(y % 3) * 0.05f;
  glColor3f(1, 0.3f, 0.3f);
  glRasterPos3f(16, 36, 0);
  glDrawPixels(32, 24, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  glColor3f(0.2f, 1, 0.2f);
  quad(12, 40, 52, 56, -0.2f);  // depth 0.4
  std::vector<GLushort> depth16(8 * 8);
  for (size_t i = 0; i < depth16.size(); ++i) depth16[i] = GLushort(i * 1000);
  glDepthFunc(GL_ALWAYS);
  glColor3f(0.4f, 0.4f, 1);
  glWindowPos2i(50, 2);
  glDrawPixels(8, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, depth16.data());
  glDepthFunc(GL_LESS);
  glColor3f(1, 1, 1);
  quad(48, 0, 60, 12, 0.0f);
}

// ---- glCopyPixels
// ---------------------------------------------------------------------------------

void copypixels_color() {
  clear(0.1f, 0.1f, 0.1f);
  pixel_projection(96, 64);
  const std::vector<GLubyte> p = pattern(16, 12);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(2, 2);
  glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glRasterPos2i(22, 2);
  glCopyPixels(2, 2, 16, 12, GL_COLOR);  // a plain copy
  glRasterPos2i(6, 5);
  glCopyPixels(2, 2, 16, 12, GL_COLOR);  // overlapping its source
  glPixelZoom(2, -1.5f);
  glRasterPos2i(42, 30);
  glCopyPixels(22, 2, 16, 12, GL_COLOR);  // zoomed, flipped
  glPixelZoom(1, 1);
  glRasterPos2i(80, 40);
  glCopyPixels(-4, -3, 16, 12, GL_COLOR);  // source partly outside: only the inside is defined
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 30, 30, 34);
  glRasterPos2i(10, 44);
  glCopyPixels(22, 2, 16, 12, GL_COLOR);  // scissored
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);  // a depth test that can fail: drawn as fragments, not copied
  glColor3f(1, 1, 1);
  quad(60, 0, 96, 10, -0.5f);
  glRasterPos3f(62, 2, 0.0f);
  glCopyPixels(2, 2, 16, 12, GL_COLOR);
}

void copypixels_depth() {
  clear(0.1f, 0.1f, 0.1f);
  pixel_projection(64, 64);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.5f, 0);
  glVertex3f(2, 2, -0.9f);
  glVertex3f(30, 2, 0.9f);
  glVertex3f(2, 30, 0.0f);
  glEnd();
  glRasterPos2i(32, 32);
  glCopyPixels(0, 0, 32, 32, GL_DEPTH);  // no zoom, no overlap: Mesa copies the depth values
  glRasterPos2i(20, 20);
  glPixelZoom(1.5f, 1.5f);
  glColor3f(0.3f, 0.3f, 1);
  glCopyPixels(0, 0, 16, 16, GL_DEPTH);  // zoomed: fragments with the raster colour
  glPixelZoom(1, 1);
  // Colour where the copied depth lets it through.
  glColor3f(0.5f, 1, 0.5f);
  quad(0, 0, 64, 64, 0.1f);
}

// ---- the accumulation buffer
// ---------------------------------------------------------------------

void accum_motion_blur() {
  pixel_projection(64, 64);
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  const int frames = 7;
  for (int i = 0; i < frames; ++i) {
    clear(0.1f, 0.1f, 0.2f);
    glPushMatrix();
    glTranslatef(12.0f + i * 5.0f, 20.0f + i * 2.5f, 0);
    glRotatef(i * 9.0f, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.8f, 0.2f);
    glVertex2f(-8, -8);
    glColor3f(0.2f, 0.8f, 1);
    glVertex2f(10, -6);
    glColor3f(1, 0.2f, 0.8f);
    glVertex2f(0, 12);
    glEnd();
    glPopMatrix();
    glAccum(GL_ACCUM, 1.0f / frames);
  }
  glAccum(GL_RETURN, 1.0f);
}

void accum_operations() {
  pixel_projection(64, 64);
  const std::vector<GLubyte> p = pattern(64, 64);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(0, 0);
  glDrawPixels(64, 64, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glAccum(GL_LOAD, 0.5f);
  glClearAccum(0.25f, -0.5f, 0.1f, 0.3f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(8, 8, 24, 40);
  glClear(GL_ACCUM_BUFFER_BIT);  // scissored
  glScissor(20, 0, 40, 50);
  glAccum(GL_ACCUM, 0.75f);
  glAccum(GL_MULT, 1.3f);
  glScissor(0, 30, 64, 34);
  glAccum(GL_ADD, -0.2f);
  glDisable(GL_SCISSOR_TEST);
  clear(0, 0, 0);
  glAccum(GL_RETURN, 1.4f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(40, 40, 20, 20);
  glAccum(GL_RETURN, 0.5f);
}

}  // namespace

const std::vector<Scene>& scenes() {
  static const std::vector<Scene> all = {
      {"bitmap_glyphs", 96, 64, bitmap_glyphs},
      {"bitmap_raster_transform", 64, 64, bitmap_raster_transform},
      {"bitmap_lit_raster_color", 64, 64, bitmap_lit_raster_color},
      {"window_pos_depth", 64, 64, window_pos_depth},
      {"drawpixels_formats", 96, 64, drawpixels_formats},
      {"drawpixels_zoom", 96, 96, drawpixels_zoom},
      {"drawpixels_depth", 64, 64, drawpixels_depth},
      {"copypixels_color", 96, 64, copypixels_color},
      {"copypixels_depth", 64, 64, copypixels_depth},
      {"accum_motion_blur", 64, 64, accum_motion_blur},
      {"accum_operations", 64, 64, accum_operations},
  };
  return all;
}

}  // namespace glpt::pixel_ops
