// Path-traced mode's G-buffer: the images the G-buffer pass (the raster pipelines with
// GLPT_GBUFFER shaders) writes and the trace pass reads, one per attachment of
// shaders/gbuffer_layout.h, sized like the drawable. Their contents are per record.
#pragma once

#include <array>
#include <cstdint>

#include "rt_core/raster/gbuffer_targets.hpp"
#include "rt_core/vk/gpu_image.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

class GBuffer {
 public:
  // (Re)creates the images when the size changes. Throws VulkanError.
  void ensure(VulkanDevice& device, uint32_t width, uint32_t height);

  // The attachments for RasterRenderer::execute.
  GBufferTargets targets(const std::vector<uint8_t>* traced, glm::vec2 jitter) const;
  const GpuImage& image(int attachment) const { return images_[attachment]; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  std::array<GpuImage, GLPT_GBUFFER_ATTACHMENTS> images_;
  uint32_t width_ = 0, height_ = 0;
};

}  // namespace glpt::rt
