// Colour buffer selection (GL 1.5 4.2.1, 4.3.2): glDrawBuffer and glReadBuffer with FRONT,
// BACK and FRONT_AND_BACK, and reading back with glReadPixels.
//
// OSMesa, the reference, is single-buffered: GL_BACK names its one colour buffer (Mesa accepts
// it and draws there). glpt may be double-buffered. So these scenes only check what both models
// agree on: what is drawn into a buffer is read back from that same buffer, and a FRONT_AND_BACK
// draw reaches both. The runner reads the final image from the read buffer the scene selected.
#include <vector>

#include "scene_util.hpp"

namespace {

using namespace glpt::conformance::util;

// Reads the `w` x `h` block at (x, y) with glReadPixels and draws it again at the current raster
// position: what glReadPixels returned becomes part of the image.
void read_and_redraw(int x, int y, int w, int h) {
  std::vector<uint8_t> pixels(static_cast<size_t>(w) * h * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
}

void pattern(float r, float g, float b) {
  glBegin(GL_TRIANGLES);
  glColor3f(r, g, b);
  glVertex2f(2, 2);
  glColor3f(g, b, r);
  glVertex2f(30, 6);
  glColor3f(b, r, g);
  glVertex2f(10, 30);
  glEnd();
}

// Draws into and reads from `buffer`: the pattern, and the block read back drawn again at
// (copy_x, copy_y).
void draw_and_read(GLenum buffer, float r, float g, float b, int copy_x, int copy_y) {
  glDrawBuffer(buffer);
  glReadBuffer(buffer);
  clear(0.1f + 0.2f * r, 0.1f, 0.3f - 0.2f * r);
  ortho_pixels(64, 64);
  pattern(r, g, b);
  glRasterPos2i(copy_x, copy_y);
  read_and_redraw(0, 0, 32, 32);
}

// Single-buffered use: draw into and read from GL_FRONT.
GLPT_SCENE(buffers_front_draw_and_read, 64, 64) { draw_and_read(GL_FRONT, 1, 0.5f, 0.1f, 32, 32); }

// Double-buffered use: draw into and read from GL_BACK.
GLPT_SCENE(buffers_back_draw_and_read, 64, 64) { draw_and_read(GL_BACK, 0.2f, 1, 0.4f, 32, 0); }

// GL_FRONT_AND_BACK draws into both: reading GL_FRONT and GL_BACK both return the drawing.
GLPT_SCENE(buffers_front_and_back, 64, 64) {
  glDrawBuffer(GL_FRONT_AND_BACK);
  clear(0.1f, 0.3f, 0.1f);
  ortho_pixels(64, 64);
  pattern(0.3f, 0.6f, 1);
  glReadBuffer(GL_FRONT);
  glRasterPos2i(32, 0);
  read_and_redraw(0, 0, 32, 32);
  glReadBuffer(GL_BACK);
  glRasterPos2i(0, 32);
  read_and_redraw(0, 0, 32, 32);
}

// Defect: glReadPixels of the back buffer after a swap. OSMesa cannot swap, so the swap is
// emulated as a double-buffered program sees it: frame 1 is drawn into GL_BACK and finished
// (glFinish stands in for glXSwapBuffers: the point where glpt renders the frame); frame 2
// redraws part of GL_BACK; then glReadPixels from GL_BACK must return frame 2's drawing where
// it drew and frame 1's elsewhere, never an older presented image or nothing. The block read
// back is drawn again at the top right so that it is part of the compared image.
GLPT_SCENE(buffers_read_back_after_swap, 64, 64) {
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_BACK);
  clear(0.2f, 0.2f, 0.2f);
  ortho_pixels(64, 64);
  pattern(1, 0.3f, 0.3f);  // frame 1
  glFinish();
  glColor3f(0.3f, 0.9f, 1);  // frame 2, drawn over part of frame 1
  glRectf(12, 0, 32, 14);
  glRasterPos2i(32, 32);
  read_and_redraw(0, 0, 32, 32);
}

// Reading with pack parameters: a block read with GL_PACK_ROW_LENGTH and SKIP_PIXELS/ROWS into
// the middle of a larger client image, then drawn whole.
GLPT_SCENE(buffers_read_pixels_pack_state, 64, 64) {
  clear(0.1f, 0.1f, 0.1f);
  ortho_pixels(64, 64);
  pattern(1, 0.8f, 0.2f);
  std::vector<uint8_t> image(40 * 40 * 4, 90);
  glPixelStorei(GL_PACK_ROW_LENGTH, 40);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 6);
  glPixelStorei(GL_PACK_SKIP_ROWS, 4);
  glReadPixels(0, 0, 30, 30, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(22, 22);
  glDrawPixels(40, 40, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
}

}  // namespace
