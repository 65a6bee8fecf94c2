// Without a renderer (no Vulkan at all, issue 7 item 6): GL's state machine keeps answering, and
// each frame shows the colour of the last glClear of the colour buffer, in the window, in the
// PNGs (GLPT_OUTPUT) and to glReadPixels (depth and stencil: their last clear values). Nothing
// else is drawn: a minimal stand-in that shows the program runs.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "gl_shim/frame/frame_output.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "rt_core/record/frame_record.hpp"

namespace glpt {

class ClearFallback {
 public:
  ClearFallback();

  // Takes the values of the record's clears (the last of each buffer wins).
  void consume(const rec::FrameRecord& record);
  // A frame's end: the record's clears, then the colour shown in `target` (may be null) and
  // written as PNG, `width` x `height`.
  void end_frame(const rec::FrameRecord& record, uint32_t width, uint32_t height,
                 WindowTarget* target);
  // glReadPixels of (x, y, width, height) from a drawable of `drawable_width` x
  // `drawable_height`: every buffer holds its cleared value.
  void read(rec::PixelKind kind, int32_t x, int32_t y, uint32_t width, uint32_t height,
            uint32_t drawable_width, uint32_t drawable_height, FramebufferPixels& out) const;

 private:
  glm::vec4 color_{0.0f};  // as stored in an RGBA8 buffer (quantized)
  float depth_ = 1.0f;
  uint32_t stencil_ = 0;
  OutputSettings settings_;
  PngStream png_stream_;
  uint64_t frame_index_ = 0;
  bool png_failure_reported_ = false;
};

}  // namespace glpt
