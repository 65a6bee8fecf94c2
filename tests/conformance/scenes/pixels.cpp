// Pixel rectangles (GL 1.5 3.6-3.7, 4.3): the raster position and glWindowPos, glBitmap text,
// glDrawPixels in several formats with unpacking, zoom, pixel transfer and depth testing,
// glCopyPixels, and the accumulation buffer.
#include <cstring>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// Text-like glyphs: the raster colour is latched from the current colour at glRasterPos time
// (a glColor after it does not change the next bitmap), glBitmap's origin offsets and moves.
GLPT_SCENE(pixels_bitmap_glyphs, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  glColor3f(1, 1, 0.3f);
  glRasterPos2i(4, 50);
  glColor3f(1, 0, 0);  // too late for the line above
  bitmap_text("GLPT 1.5");
  glRasterPos2f(4.7f, 36.2f);  // the raster position keeps its fraction; bitmaps round
  bitmap_text("OK.");
  glColor3f(0.3f, 1, 0.5f);
  glRasterPos2i(30, 36);
  bitmap_text("A1");
  // A large bitmap with an origin offset (xorig, yorig) and a move.
  GLubyte block[16 * 2];
  for (int r = 0; r < 16; ++r) {
    block[r * 2] = static_cast<GLubyte>(r % 2 == 0 ? 0xAA : 0x55);
    block[r * 2 + 1] = static_cast<GLubyte>(0xF0 >> (r % 4));
  }
  glColor3f(0.5f, 0.7f, 1);
  glRasterPos2i(20, 8);
  glBitmap(16, 16, 4, 2, 20, 3, block);
  glBitmap(16, 16, 4, 2, 0, 0, block);
}

// The raster position goes through the modelview and projection (and is lit when lighting is
// on); an invalid raster position (outside the view volume) makes glBitmap draw nothing, and a
// zero-size glBitmap moves the raster position even off-screen.
GLPT_SCENE(pixels_raster_position_transform, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  perspective(45.0, 1.0, 1.0, 20.0);
  GLubyte square[8];
  std::memset(square, 0xFF, sizeof square);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < 5; ++i) {
    glPushMatrix();
    glTranslatef(-1.5f + 0.75f * i, -0.5f + 0.3f * i, -3.0f - 0.5f * i);
    glColor3f(1, 0.2f * i, 1.0f - 0.2f * i);
    glRasterPos3f(0, 0, 0);
    glBitmap(8, 8, 4, 4, 0, 0, square);
    glPopMatrix();
  }
  glRasterPos3f(0, 0, 5);  // behind the viewer: invalid
  glBitmap(8, 8, 0, 0, 0, 0, square);
  // Lit raster position: the raster colour is the lit colour.
  glEnable(GL_LIGHTING);
  light4(GL_LIGHT0, GL_POSITION, 0, 0, 1, 0);
  light4(GL_LIGHT0, GL_DIFFUSE, 0.2f, 1, 0.4f, 1);
  glEnable(GL_LIGHT0);
  glNormal3f(0, 0, 1);
  ortho_pixels(64, 64);
  glRasterPos2i(50, 50);
  glDisable(GL_LIGHTING);
  glBitmap(8, 8, 0, 0, 0, 0, square);
  // Move off the left edge with an empty bitmap, then draw partly back on screen.
  glColor3f(1, 1, 1);
  glRasterPos2i(2, 4);
  glBitmap(0, 0, 0, 0, -6, 0, nullptr);
  glBitmap(8, 8, 0, 0, 0, 0, square);
}

// glWindowPos sets the raster position in window coordinates directly, ignoring the matrices,
// with the current colour, and with depth from z for the depth test.
GLPT_SCENE(pixels_window_pos, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  perspective(45.0, 1.0, 1.0, 20.0);
  glTranslatef(5, 5, -30);  // ignored by glWindowPos
  const std::vector<uint8_t> image = gradient(12, 12, Rgba8{255, 0, 0, 255}, Rgba8{0, 255, 0, 255},
                                              Rgba8{0, 0, 255, 255}, Rgba8{255, 255, 255, 255}, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glWindowPos2i(3, 5);
  glDrawPixels(12, 12, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glWindowPos2f(40.6f, 8.2f);
  glDrawPixels(12, 12, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  GLubyte square[8];
  std::memset(square, 0xFF, sizeof square);
  glColor3f(1, 0.8f, 0.2f);
  glWindowPos2i(20, 40);
  glBitmap(8, 8, 0, 0, 0, 0, square);
  // Depth: a quad at depth 0.5, then pixels at depth 0.25 (drawn) and 0.75 (hidden).
  glEnable(GL_DEPTH_TEST);
  ortho_pixels(64, 64);
  glColor3f(0.4f, 0.4f, 0.4f);
  glRectf(30, 30, 62, 62);
  glWindowPos3f(34, 34, 0.25f);
  glDrawPixels(12, 12, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glWindowPos3f(48, 48, 0.75f);
  glDrawPixels(12, 12, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
}

// glDrawPixels of a 20x14 image in `format` at the default unpack alignment of 4 (rows of odd
// byte length are padded), and of a sub-rectangle selected with ROW_LENGTH and SKIP_*.
void draw_pixels_scene(GLenum format) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  constexpr int kWidth = 21, kHeight = 14;
  const std::vector<uint8_t> rgba =
      gradient(kWidth, kHeight, Rgba8{250, 30, 30, 255}, Rgba8{30, 250, 30, 120},
               Rgba8{30, 30, 250, 200}, Rgba8{250, 250, 250, 40}, 5);
  const std::vector<uint8_t> packed = convert(rgba, format);
  const size_t components = packed.size() / (kWidth * kHeight);
  // Rows padded to a multiple of 4 bytes, as the default GL_UNPACK_ALIGNMENT expects.
  const size_t row = (kWidth * components + 3) / 4 * 4;
  std::vector<uint8_t> aligned(row * kHeight, 0);
  for (int y = 0; y < kHeight; ++y) {
    std::memcpy(&aligned[y * row], &packed[y * kWidth * components], kWidth * components);
  }
  glRasterPos2i(4, 44);
  glDrawPixels(kWidth, kHeight, format, GL_UNSIGNED_BYTE, aligned.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(34, 44);
  glDrawPixels(kWidth, kHeight, format, GL_UNSIGNED_BYTE, packed.data());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, kWidth);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glRasterPos2i(6, 6);
  glDrawPixels(12, 8, format, GL_UNSIGNED_BYTE, packed.data());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  // Partly outside the window: clipped, not shifted.
  glRasterPos2i(50, 20);
  glDrawPixels(kWidth, kHeight, format, GL_UNSIGNED_BYTE, packed.data());
}

GLPT_SCENE(pixels_draw_rgba, 64, 64) { draw_pixels_scene(GL_RGBA); }
GLPT_SCENE(pixels_draw_rgb, 64, 64) { draw_pixels_scene(GL_RGB); }
GLPT_SCENE(pixels_draw_luminance, 64, 64) { draw_pixels_scene(GL_LUMINANCE); }
GLPT_SCENE(pixels_draw_luminance_alpha, 64, 64) { draw_pixels_scene(GL_LUMINANCE_ALPHA); }

// Pixel zoom (GL 1.5 3.6.4): 2x, 3x1, a fractional zoom and negative zooms that mirror.
GLPT_SCENE(pixels_draw_zoom, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  const std::vector<uint8_t> image =
      gradient(8, 8, Rgba8{250, 30, 30, 255}, Rgba8{30, 250, 30, 255}, Rgba8{30, 30, 250, 255},
               Rgba8{250, 250, 30, 255}, 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const float zooms[5][2] = {{2, 2}, {3, 1}, {1.5f, 2.5f}, {-2, 2}, {2, -1.5f}};
  const int positions[5][2] = {{2, 2}, {22, 2}, {40, 30}, {36, 8}, {4, 44}};
  for (int i = 0; i < 5; ++i) {
    glPixelZoom(zooms[i][0], zooms[i][1]);
    glRasterPos2i(positions[i][0], positions[i][1]);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  }
}

// Pixel transfer on glDrawPixels: scale and bias per channel, then a colour lookup through
// pixel maps (GL_MAP_COLOR).
GLPT_SCENE(pixels_draw_transfer, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  const std::vector<uint8_t> image =
      gradient(24, 24, Rgba8{250, 30, 30, 255}, Rgba8{30, 250, 30, 255}, Rgba8{30, 30, 250, 255},
               Rgba8{250, 250, 250, 255}, 6);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(4, 36);
  glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.3f);
  glPixelTransferf(GL_BLUE_SCALE, -1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 1.0f);
  glRasterPos2i(36, 36);
  glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glPixelTransferf(GL_RED_SCALE, 1);
  glPixelTransferf(GL_GREEN_BIAS, 0);
  glPixelTransferf(GL_BLUE_SCALE, 1);
  glPixelTransferf(GL_BLUE_BIAS, 0);
  // A posterizing map for red and an inverting one for green.
  const float red_map[4] = {0.0f, 0.3f, 0.7f, 1.0f};
  const float green_map[2] = {1.0f, 0.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, red_map);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, green_map);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glRasterPos2i(20, 4);
  glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
}

// glDrawPixels fragments take the raster position's depth and pass the depth test like any
// other: an image drawn across a sloped quad is hidden where the quad is nearer.
GLPT_SCENE(pixels_draw_with_depth_test, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_QUADS);
  glColor3f(0.3f, 0.3f, 0.8f);
  glVertex3f(2, 2, -0.8f);
  glVertex3f(62, 2, 0.8f);
  glVertex3f(62, 62, 0.8f);
  glVertex3f(2, 62, -0.8f);
  glEnd();
  const std::vector<uint8_t> image =
      gradient(40, 40, Rgba8{250, 200, 30, 255}, Rgba8{250, 60, 30, 255}, Rgba8{250, 250, 150, 255},
               Rgba8{200, 40, 40, 255}, 8);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos3f(12, 12, 0);  // depth 0.5: behind the right half of the quad
  glDrawPixels(40, 40, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
}

// glCopyPixels copies a block of the colour buffer, with zoom, and onto an overlapping region.
GLPT_SCENE(pixels_copy, 64, 64) {
  clear(0.1f, 0.1f, 0.2f);
  ortho_pixels(64, 64);
  rgb_triangle(2, 2, 22, 4, 8, 22);
  glRasterPos2i(30, 2);
  glCopyPixels(0, 0, 24, 24, GL_COLOR);
  glPixelZoom(1.5f, 1.5f);
  glRasterPos2i(2, 28);
  glCopyPixels(0, 0, 24, 24, GL_COLOR);
  glPixelZoom(1, 1);
  glRasterPos2i(36, 10);  // overlaps its own source
  glCopyPixels(30, 2, 24, 24, GL_COLOR);
}

// The accumulation buffer: LOAD a frame at 0.5, ACCUM a second at 0.5, RETURN at 1; MULT and
// ADD adjust the accumulated values before a second RETURN into a scissored half.
GLPT_SCENE(accum_load_accum_return, 64, 64) {
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  glColor3f(1, 0.2f, 0.2f);
  glRectf(4, 4, 40, 40);
  glAccum(GL_LOAD, 0.5f);
  clear(0.1f, 0.1f, 0.1f);
  glColor3f(0.2f, 0.4f, 1);
  glRectf(24, 24, 60, 60);
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 64, 20);
  glAccum(GL_MULT, 1.5f);
  glAccum(GL_ADD, 0.1f);
  glAccum(GL_RETURN, 1.0f);
}

// GL_RETURN with a value above one and the accumulation clear colour: values saturate on return,
// and a clear of the accumulation buffer to a colour shows after a RETURN.
GLPT_SCENE(accum_clear_and_return_scale, 64, 64) {
  glClearAccum(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_ACCUM_BUFFER_BIT);
  clear(0, 0, 0);
  ortho_pixels(64, 64);
  static const float kCorners[4][4] = {
      {0, 0, 0, 1}, {1, 0, 0, 1}, {0.5f, 0.5f, 1, 1}, {0, 1, 0, 1}};
  coloured_quad(8, 8, 56, 56, kCorners);
  glAccum(GL_ACCUM, 0.6f);
  glAccum(GL_RETURN, 2.0f);
}

// A motion-blur sequence: eight positions of a moving square accumulated at 1/8 each.
GLPT_SCENE(accum_motion_blur, 64, 64) {
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  ortho_pixels(64, 64);
  for (int frame = 0; frame < 8; ++frame) {
    clear(0.1f, 0.1f, 0.2f);
    glColor3f(1, 0.8f, 0.2f);
    const float x = 6.0f + 4.0f * frame, y = 20.0f + 2.0f * frame;
    glRectf(x, y, x + 14, y + 14);
    glColor3f(0.3f, 1, 0.5f);
    glRectf(50, 6, 58, 58);  // still: stays sharp
    glAccum(GL_ACCUM, 1.0f / 8);
  }
  glAccum(GL_RETURN, 1.0f);
}

}  // namespace
