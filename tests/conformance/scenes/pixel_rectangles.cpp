// Pixel rectangles beyond pixels.cpp (GL 1.5 2.13, 3.6-3.7, 4.2.4, 4.3.3): the raster position
// through transforms, lighting, clipping and glWindowPos's depth range; glBitmap unpack modes and
// moves; glDrawPixels formats, types, fractional and negative zooms, depth images; glCopyPixels
// blits and drawn copies; pixel rectangles through the fragment operations and stencil images;
// the accumulation buffer under the scissor.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// These scenes are held to Mesa's exact pixels, stricter than the suite's default.
constexpr glpt::conformance::Tolerance kExact = glpt::conformance::relaxed(
    1.0, 0, "exact: glpt reproduces Mesa's pixel-rectangle and accumulation arithmetic");
#define GLPT_EXACT_SCENE(name, width, height) GLPT_SCENE_TOLERANCE(name, width, height, kExact)

void clear_all(float r, float g, float b) {
  glClearColor(r, g, b, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// ortho_pixels with z flipped: z = -1 is depth 0 (near), z = 1 is depth 1.
void pixel_projection(int width, int height) {
  ortho_pixels(width, height);
  glMatrixMode(GL_PROJECTION);
  glScalef(1, 1, -1);
  glMatrixMode(GL_MODELVIEW);
}

// A w x h RGBA8 image with a distinct colour per pixel.
std::vector<GLubyte> pattern(int w, int h) {
  std::vector<GLubyte> p(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      GLubyte* q = &p[(size_t(y) * w + x) * 4];
      q[0] = GLubyte(40 + x * 200 / std::max(1, w - 1));
      q[1] = GLubyte(40 + y * 200 / std::max(1, h - 1));
      q[2] = GLubyte(((x + y) & 1) ? 230 : 60);
      q[3] = GLubyte(255 - x * 3);
    }
  }
  return p;
}

// ---- raster position and bitmaps ----------------------------------------------------------------

GLPT_EXACT_SCENE(pixels_bitmap_text_and_unpack_modes, 96, 64) {
  clear_all(0.1f, 0.1f, 0.2f);
  pixel_projection(96, 64);
  glColor3f(1, 1, 0.3f);
  glRasterPos2i(4, 50);
  glColor3f(1, 0, 0);  // after glRasterPos: the line keeps the latched colour
  bitmap_text("GLPT 1.5");
  glRasterPos2f(4.7f, 36.2f);  // a fractional raster position: bitmaps land on floor(x + 1e-4)
  bitmap_text("ABC.");
  glColor3f(0.3f, 1, 0.5f);
  glRasterPos2f(40.99995f, 36.0f);  // within Mesa's 1e-4 of 41
  bitmap_text("XL");
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
  bitmap_text("XX");
}

GLPT_EXACT_SCENE(pixels_bitmap_raster_transforms, 64, 64) {
  clear_all(0.1f, 0.1f, 0.2f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
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

GLPT_EXACT_SCENE(pixels_bitmap_lit_raster_colour, 64, 64) {
  clear_all(0.05f, 0.05f, 0.05f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
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

GLPT_EXACT_SCENE(pixels_window_pos_depth_range, 64, 64) {
  clear_all(0.2f, 0.2f, 0.2f);
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

// Mesa's bitmap cache (st_cb_bitmap.c): small bitmaps are collected and drawn later as one quad,
// with the fragment operations validated last: state set between cached bitmaps applies to all
// of them, overlapping cached bitmaps blend once, bitmaps taller than the cache and glAccum go
// before the cached bitmaps, and a bitmap that flushes the cache lends it its state.
GLPT_EXACT_SCENE(pixels_bitmap_cache_order, 96, 64) {
  clear_all(0.2f, 0.2f, 0.3f);
  pixel_projection(96, 64);
  glColor3f(0.3f, 0.6f, 0.9f);
  glRectf(0, 0, 96, 20);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  // Blending turned on halfway through a line of text: the whole line blends.
  glColor4f(1, 1, 0.2f, 0.5f);
  glRasterPos2i(2, 4);
  bitmap_text("AB");
  glEnable(GL_BLEND);
  bitmap_text("CG");
  // Overlapping bitmaps in one cache: one blended fragment per pixel.
  GLubyte block[6 * 2];
  std::memset(block, 0xFF, sizeof block);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(40, 4);
  glBitmap(12, 6, 0, 0, 4, 2, block);
  glBitmap(12, 6, 0, 0, 0, 0, block);
  glDisable(GL_BLEND);
  // A bitmap of another colour flushes the cache with its own state: the yellow line is drawn
  // with the logic op, the scissor enable stays the cache's (off).
  glColor3f(1, 0.9f, 0.1f);
  glRasterPos2i(2, 24);
  bitmap_text("LOGIC");
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 60, 64);
  glColor3f(0.4f, 1, 1);
  glRasterPos2i(40, 24);
  bitmap_text("XOR XOR");
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_SCISSOR_TEST);
  // A bitmap taller than the cache is drawn before the cached text it covers.
  glColor3f(1, 0.3f, 0.3f);
  glRasterPos2i(2, 40);
  bitmap_text("OK");
  GLubyte tall[2 * 40];
  std::memset(tall, 0xAA, sizeof tall);
  glColor3f(0.3f, 1, 0.3f);
  glRasterPos2i(4, 36);
  glBitmap(12, 40, 0, 0, 0, 0, tall);
  // glAccum does not flush the cache: the text is not in the accumulation buffer, and comes
  // back on top of the returned image.
  glColor3f(1, 1, 1);
  glRasterPos2i(50, 44);
  bitmap_text("T1");
  glAccum(GL_LOAD, 1.0f);
  glAccum(GL_RETURN, 0.5f);
  glFlush();  // flushes the cache
  glColor3f(1, 0.5f, 1);
  glRasterPos2i(50, 54);
  bitmap_text("P5");
}

// ---- glDrawPixels
// ---------------------------------------------------------------------------------

GLPT_EXACT_SCENE(pixels_draw_formats_and_types, 96, 64) {
  clear_all(0.3f, 0.3f, 0.3f);
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

GLPT_EXACT_SCENE(pixels_draw_fractional_zoom, 96, 96) {
  clear_all(0.1f, 0.1f, 0.1f);
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

GLPT_EXACT_SCENE(pixels_draw_depth_image, 64, 64) {
  clear_all(0.1f, 0.1f, 0.3f);
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

GLPT_EXACT_SCENE(pixels_copy_colour_cases, 96, 64) {
  clear_all(0.1f, 0.1f, 0.1f);
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

GLPT_EXACT_SCENE(pixels_copy_depth, 64, 64) {
  clear_all(0.1f, 0.1f, 0.1f);
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

// Pixel transfer on glDrawPixels as Mesa draws it: scale and bias, colour maps (R and G looked up
// in a 256-entry map texture; B and A, through Mesa's map lookup, from the image itself),
// colour-index images through the I_TO_* maps with INDEX_OFFSET ignored, stencil images with
// INDEX_SHIFT ignored. The transfer state is reset before the image is read back (glReadPixels
// applies it too).
GLPT_EXACT_SCENE(pixels_draw_transfer_maps_and_indices, 96, 64) {
  clear_all(0.1f, 0.1f, 0.2f);
  pixel_projection(96, 64);
  const std::vector<GLubyte> p = pattern(20, 14);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelTransferf(GL_RED_SCALE, 0.6f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glPixelTransferf(GL_BLUE_SCALE, -1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 1.0f);
  glPixelTransferf(GL_ALPHA_SCALE, 0.5f);
  glRasterPos2i(2, 2);
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  float ramp[256], half[256];
  for (int i = 0; i < 256; ++i) {
    ramp[i] = float(i) / 255.0f;
    half[i] = ramp[i] * 0.5f + 0.25f;
  }
  const float red[4] = {0.0f, 0.3f, 0.7f, 1.0f}, green[2] = {1.0f, 0.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, red);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, green);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 256, half);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 256, ramp);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glRasterPos2i(26, 2);
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 0.0f);
  glPixelTransferf(GL_BLUE_SCALE, 1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.0f);
  glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
  glRasterPos2i(50, 2);
  glPixelZoom(2, 2);
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glPixelZoom(1, 1);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  // Colour indices (8 and 16 bits) through the I_TO_R/G/B/A maps.
  const float i_to_r[8] = {0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 1.0f, 0.2f, 0.0f};
  const float i_to_g[4] = {0.9f, 0.2f, 0.6f, 0.4f}, i_to_b[2] = {0.3f, 0.8f}, i_to_a[1] = {1.0f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 8, i_to_r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, i_to_g);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 2, i_to_b);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, i_to_a);
  std::vector<GLubyte> indices(16 * 12);
  std::vector<GLushort> indices16(16 * 12);
  for (size_t i = 0; i < indices.size(); ++i) {
    indices[i] = GLubyte((i * 7 + i / 16) % 256);
    indices16[i] = GLushort(i * 263);
  }
  glPixelTransferi(GL_INDEX_OFFSET, 3);  // ignored by Mesa's glDrawPixels
  glRasterPos2i(2, 24);
  glDrawPixels(16, 12, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices.data());
  glRasterPos2i(22, 24);
  glDrawPixels(16, 12, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, indices16.data());
  // A stencil image with INDEX_SHIFT (ignored), then colour where the stencil is 2.
  std::vector<GLubyte> stencil(16 * 12);
  for (size_t i = 0; i < stencil.size(); ++i) stencil[i] = GLubyte((i / 3) % 4);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glRasterPos2i(2, 44);
  glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 2, 0xFF);
  glColor3f(1, 0.8f, 0.2f);
  glRectf(0, 40, 30, 64);
  glDisable(GL_STENCIL_TEST);
}

// Display lists compile glBitmap and glDrawPixels with their images unpacked at compile time
// (GL 1.5 5.4): later changes to the client memory and to the unpack modes do not matter.
GLPT_EXACT_SCENE(pixels_display_list_images, 64, 64) {
  clear_all(0.15f, 0.1f, 0.1f);
  pixel_projection(64, 64);
  std::vector<GLubyte> p = pattern(24, 10);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 24);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 4);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glBitmap(0, 0, 0, 0, 14, 0, nullptr);
  glColor3f(1, 1, 0.4f);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);  // not compiled: executed at once
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  bitmap_text("GL");
  glEndList();
  std::fill(p.begin(), p.end(), GLubyte{0});
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glRasterPos2i(2, 4);
  glCallList(list);
  glPixelZoom(1.5f, -1);
  glRasterPos2i(6, 50);
  glCallList(list);
  glPixelZoom(1, 1);
  glDeleteLists(list, 1);
}

// Texturing of pixel rectangles as Mesa does it: the fragments take the *current* texture
// coordinates, untransformed (glDrawPixels and glCopyPixels unit 0's, (0, 0, 0, 1) on the other
// units; bitmaps every unit's), not the raster position's.
GLPT_EXACT_SCENE(pixels_textured_rectangles, 64, 64) {
  clear_all(0.2f, 0.2f, 0.25f);
  pixel_projection(64, 64);
  const std::vector<uint8_t> image =
      gradient(32, 32, Rgba8{250, 30, 30, 255}, Rgba8{30, 250, 30, 255}, Rgba8{30, 30, 250, 255},
               Rgba8{250, 250, 250, 128}, 4);
  glActiveTexture(GL_TEXTURE1);
  texture_2d(GL_RGBA, 32, 32, image, GL_NEAREST, GL_REPEAT);
  glActiveTexture(GL_TEXTURE0);
  texture_2d(GL_RGBA, 32, 32, image, GL_LINEAR, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  const std::vector<GLubyte> p = pattern(12, 10);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.25f, 0.1f, 0);  // moves the raster position's coordinates, not Mesa's
  glMatrixMode(GL_MODELVIEW);
  glTexCoord2f(0.3f, 0.7f);
  glRasterPos2i(2, 2);
  glTexCoord4f(0.8f, 0.2f, 0.0f, 2.0f);  // current after the raster position: this one counts
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glPixelZoom(2, 1.5f);  // not a plain copy: the fragments are textured
  glRasterPos2i(18, 2);
  glTexCoord2f(0.55f, 0.45f);
  glCopyPixels(2, 2, 12, 10, GL_COLOR);
  glPixelZoom(1, 1);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  GLubyte square[8 * 2];
  std::memset(square, 0xFF, sizeof square);
  glTexCoord2f(0.1f, 0.9f);
  glRasterPos2i(2, 30);
  glBitmap(8, 8, 0, 0, 10, 0, square);
  glTexCoord2f(0.6f, 0.3f);
  glRasterPos2i(14, 30);
  glBitmap(8, 8, 0, 0, 10, 0, square);
  // Unit 1 as well: bitmaps take its current coordinates, images (0, 0).
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glActiveTexture(GL_TEXTURE0);
  glMultiTexCoord2f(GL_TEXTURE1, 0.4f, 0.35f);
  glRasterPos2i(30, 30);
  glBitmap(8, 8, 0, 0, 0, 0, square);
  glRasterPos2i(42, 30);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glActiveTexture(GL_TEXTURE1);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
}

// ---- fragment operations on pixel rectangles -------------------------------------------------

// A w x h RGBA8 image whose alpha rises from 0 at the left to 255 at the right.
std::vector<GLubyte> alpha_ramp(int w, int h) {
  std::vector<GLubyte> p = pattern(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) p[(size_t(y) * w + x) * 4 + 3] = GLubyte(x * 255 / (w - 1));
  }
  return p;
}

// glDrawPixels and glBitmap fragments go through alpha test, blending, logic op and the colour
// mask like any other fragment.
GLPT_EXACT_SCENE(pixels_draw_fragment_operations, 96, 64) {
  clear_all(0.2f, 0.3f, 0.4f);
  pixel_projection(96, 64);
  glColor3f(0.9f, 0.9f, 0.2f);
  glRectf(0, 32, 96, 64);
  const std::vector<GLubyte> p = alpha_ramp(20, 14);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.4f);
  glRasterPos2i(2, 2);
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glDisable(GL_ALPHA_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glRasterPos2i(26, 24);  // across the edge of the yellow band
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glPixelZoom(1.5f, -1);
  glRasterPos2i(50, 50);
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glPixelZoom(1, 1);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glRasterPos2i(50, 2);
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glRasterPos2i(74, 8);
  glDrawPixels(20, 14, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glColor3f(0.5f, 1, 1);
  glRasterPos2i(4, 40);
  bitmap_text("XOR");
  glDisable(GL_COLOR_LOGIC_OP);
  glEnable(GL_BLEND);
  glColor4f(1, 1, 1, 0.5f);
  glRasterPos2i(4, 52);
  bitmap_text("BLEND");
  glDisable(GL_BLEND);
}

// Bitmaps take the raster position's fog distance and secondary colour (colour sum); fog of a
// perspective raster position depends on its eye distance.
GLPT_EXACT_SCENE(pixels_bitmap_fog_and_colour_sum, 64, 64) {
  clear_all(0.1f, 0.1f, 0.1f);
  perspective(50.0, 1.0, 1.0, 20.0);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 12.0f);
  fog_colour(0.4f, 0.5f, 0.9f);
  GLubyte square[10 * 2];
  std::memset(square, 0xFF, sizeof square);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(1, 0.3f, 0.1f);
  for (int i = 0; i < 6; ++i) {
    glRasterPos3f(-2.0f + 0.8f * i, 1.0f, -2.5f - 1.8f * i);
    glBitmap(10, 10, 5, 5, 0, 0, square);
  }
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.15f);
  glEnable(GL_COLOR_SUM);
  glSecondaryColor3f(0.0f, 0.4f, 0.3f);
  for (int i = 0; i < 6; ++i) {
    glRasterPos3f(-2.0f + 0.8f * i, -1.0f, -2.5f - 1.8f * i);
    glBitmap(10, 10, 5, 5, 0, 0, square);
  }
}

// Stencil images: glDrawPixels(GL_STENCIL_INDEX) under the stencil write mask, glCopyPixels of
// stencil, then colour through stencil tests against the written values.
GLPT_EXACT_SCENE(pixels_stencil_image, 64, 64) {
  clear_all(0.1f, 0.1f, 0.1f);
  pixel_projection(64, 64);
  std::vector<GLubyte> stencil(24 * 20);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 24; ++x) stencil[size_t(y) * 24 + x] = GLubyte((x / 6 + y / 5) % 4 + 1);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(4, 4);
  glDrawPixels(24, 20, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  glStencilMask(0x02);  // only bit 1 of the values is written
  glRasterPos2i(36, 4);
  glDrawPixels(24, 20, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  glStencilMask(0xFF);
  glPixelZoom(1.5f, 1.25f);
  glRasterPos2i(2, 30);
  glCopyPixels(4, 4, 24, 20, GL_STENCIL);
  glPixelZoom(1, 1);
  glRasterPos2i(40, 34);
  glCopyPixels(4, 4, 24, 20, GL_STENCIL);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  const float colours[5][3] = {
      {0.3f, 0.3f, 0.3f}, {1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.2f, 0.4f, 1}, {1, 1, 0.2f}};
  for (int v = 0; v < 5; ++v) {
    glStencilFunc(GL_EQUAL, v, 0xFF);
    glColor3fv(colours[v]);
    glRectf(0, 0, 64, 64);
  }
}

// ---- the accumulation buffer
// ---------------------------------------------------------------------

GLPT_EXACT_SCENE(accum_motion_blur_rotating, 64, 64) {
  pixel_projection(64, 64);
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  const int frames = 7;
  for (int i = 0; i < frames; ++i) {
    clear_all(0.1f, 0.1f, 0.2f);
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

GLPT_EXACT_SCENE(accum_operations_scissored, 64, 64) {
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
  clear_all(0, 0, 0);
  glAccum(GL_RETURN, 1.4f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(40, 40, 20, 20);
  glAccum(GL_RETURN, 0.5f);
}

// GL_RETURN writes through the colour mask; GL_LOAD of a partly masked frame.
GLPT_EXACT_SCENE(accum_return_colour_mask, 64, 64) {
  pixel_projection(64, 64);
  clear_all(0.2f, 0.4f, 0.6f);
  glColor3f(1, 0.6f, 0.1f);
  glRectf(8, 8, 40, 40);
  glAccum(GL_LOAD, 1.0f);
  clear_all(0, 0, 0);
  glColor3f(0.1f, 0.9f, 0.5f);
  glRectf(24, 24, 56, 56);
  glAccum(GL_ACCUM, 0.5f);
  clear_all(0.9f, 0.9f, 0.9f);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glAccum(GL_RETURN, 0.8f);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 32, 64, 32);
  glAccum(GL_RETURN, 1.2f);
}

}  // namespace

// ---- depth values as 32-bit integers
// ---------------------------------------------------------------------------------

namespace {

// Shows the current depth buffer's values, read as GL_UNSIGNED_INT, byte for byte as colours:
// any difference in the clear value's conversion or in the read's scaling shows exactly.
void show_depth_as_bytes(int width, int height) {
  std::vector<GLuint> depth(size_t(width) * height);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glWindowPos2i(0, 0);
  glDrawPixels(width, height, GL_RGBA, GL_UNSIGNED_BYTE, depth.data());
}

}  // namespace

GLPT_EXACT_SCENE(pixels_depth_clears_read_as_uint, 40, 16) {
  const double values[] = {0.0, 0.1, 1.0 / 3.0, 0.5, 0.7, 0.999, 1.0, 0.123456789, 0.75, 0.2};
  glEnable(GL_SCISSOR_TEST);
  for (int i = 0; i < 10; ++i) {
    glScissor(4 * i, 0, 4, 16);
    glClearDepth(values[i]);
    glClear(GL_DEPTH_BUFFER_BIT);
  }
  show_depth_as_bytes(40, 16);
}

// Whole-buffer clears (no scissor) convert the clear depth differently from scissored ones: each
// value is cleared over the whole buffer, read back, and shown in a column of its own.
GLPT_EXACT_SCENE(pixels_depth_full_clears_read_as_uint, 40, 16) {
  const double values[] = {0.0, 0.1, 1.0 / 3.0, 0.5, 0.7, 0.999, 1.0, 0.123456789, 0.75, 0.2};
  std::vector<GLuint> columns(40 * 16);
  for (int i = 0; i < 10; ++i) {
    glClearDepth(values[i]);
    glClear(GL_DEPTH_BUFFER_BIT);
    std::vector<GLuint> depth(4 * 16);
    glReadPixels(4 * i, 0, 4, 16, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 4; ++x) columns[size_t(y) * 40 + 4 * i + x] = depth[size_t(y) * 4 + x];
  }
  glWindowPos2i(0, 0);
  glDrawPixels(40, 16, GL_RGBA, GL_UNSIGNED_BYTE, columns.data());
}

GLPT_EXACT_SCENE(pixels_drawn_depth_read_as_uint, 40, 16) {
  clear_all(0, 0, 0);
  pixel_projection(40, 16);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  for (int i = 0; i < 10; ++i) quad(4 * i, 0, 4 * i + 4, 16, -1.0f + 0.2f * i + 0.013f);
  show_depth_as_bytes(40, 16);
}
