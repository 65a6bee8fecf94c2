#include "gl_shim/frame/clear_fallback.hpp"

#include <cmath>
#include <variant>
#include <vector>

#include "gl/gl_enums.h"

namespace glpt {

ClearFallback::ClearFallback() : settings_(OutputSettings::from_environment()) {
  create_png_directory(settings_);
}

void ClearFallback::consume(const rec::FrameRecord& record) {
  for (const rec::Command& command : record.commands) {
    const auto* clear = std::get_if<rec::Clear>(&command);
    if (clear == nullptr) continue;
    if (clear->mask & GL_COLOR_BUFFER_BIT) {
      // A NaN component (glClearColor keeps it; glm::clamp would too) clears to 0, as Vulkan's
      // conversion to a UNORM buffer makes it for the renderer.
      glm::vec4 c = clear->color;
      for (int i = 0; i < 4; ++i) c[i] = std::isnan(c[i]) ? 0.0f : c[i];
      color_ = glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f) / 255.0f;
    }
    if (clear->mask & GL_DEPTH_BUFFER_BIT) depth_ = static_cast<float>(clear->depth);
    if (clear->mask & GL_STENCIL_BUFFER_BIT)
      stencil_ = static_cast<uint32_t>(clear->stencil) & 0xFF;
  }
}

void ClearFallback::end_frame(const rec::FrameRecord& record, uint32_t width, uint32_t height,
                              WindowTarget* target) {
  consume(record);
  const bool want_png = !settings_.png_dir.empty() && frame_index_ % settings_.png_every == 0;
  if (width > 0 && height > 0 && (target != nullptr || want_png)) {
    const glm::vec4 bytes = color_ * 255.0f;
    std::vector<uint8_t> rgba(size_t{width} * height * 4);
    for (size_t i = 0; i < rgba.size(); i += 4)
      for (int c = 0; c < 4; ++c) rgba[i + c] = static_cast<uint8_t>(bytes[c]);
    if (target != nullptr) target->present(rgba.data(), width, height);
    if (want_png)
      write_frame_png(settings_, png_stream_, frame_index_, width, height, rgba,
                      &png_failure_reported_);
  }
  ++frame_index_;
}

void ClearFallback::read(rec::PixelKind kind, int32_t x, int32_t y, uint32_t width, uint32_t height,
                         uint32_t drawable_width, uint32_t drawable_height,
                         FramebufferPixels& out) const {
  out = FramebufferPixels();
  const size_t n = size_t{width} * height;
  out.width = width;
  out.height = height;
  mark_inside_drawable(out, x, y, drawable_width, drawable_height);
  switch (kind) {
    case rec::PixelKind::kColor:
      out.color.assign(n, color_);
      break;
    case rec::PixelKind::kDepth:
      out.depth.assign(n, depth_);
      break;
    case rec::PixelKind::kStencil:
      out.stencil.assign(n, stencil_);
      break;
  }
}

}  // namespace glpt
