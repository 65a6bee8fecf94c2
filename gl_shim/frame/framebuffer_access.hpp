// Reading the drawable's buffers back into the front end: glReadPixels, glCopyTexImage*,
// glCopyTexSubImage* and the feedback of pixel paths all go through here.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;

// A rectangle of one buffer, rows bottom to top, width * height values. Pixels outside the
// drawable are undefined in GL; they are reported in `inside` (false) and hold zeros.
struct FramebufferPixels {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec4> color;   // PixelKind::kColor: RGBA as stored, each in [0, 1]
  std::vector<float> depth;       // PixelKind::kDepth: window z in [0, 1]
  std::vector<uint32_t> stencil;  // PixelKind::kStencil
  std::vector<uint8_t> inside;    // 1 where (x, y) lies in the drawable
};

// Renders everything recorded so far (a read is a flush point of the frame record), then reads
// the rectangle (x, y, width, height) in window coordinates of `buffer` (GL_FRONT, GL_BACK,
// GL_FRONT_LEFT, ...: the read buffer as glReadBuffer resolved it). Returns false when there is
// nothing to read from (no drawable bound, or no renderer); `out` is then empty.
bool read_framebuffer(Context& ctx, rec::PixelKind kind, uint32_t buffer, int32_t x, int32_t y,
                      uint32_t width, uint32_t height, FramebufferPixels& out);

// Sets out.inside for the rectangle at (x, y) of out.width x out.height: 1 where a pixel lies in
// a drawable of `drawable_width` x `drawable_height`.
void mark_inside_drawable(FramebufferPixels& out, int32_t x, int32_t y, uint32_t drawable_width,
                          uint32_t drawable_height);

}  // namespace glpt
