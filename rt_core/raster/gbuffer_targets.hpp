// Path-traced mode's G-buffer as the raster renderer draws into it (rt_core/passes/gbuffer.hpp
// owns the images; shaders/gbuffer_layout.h says what each attachment holds).
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "gbuffer_layout.h"

namespace glpt::rt {

inline constexpr std::array<VkFormat, GLPT_GBUFFER_ATTACHMENTS> kGBufferFormats{
    VK_FORMAT_R32G32B32A32_SFLOAT,  // POSITION
    VK_FORMAT_R32G32B32A32_UINT,    // SURFACE
    VK_FORMAT_R32G32B32A32_UINT,    // MATERIAL0
    VK_FORMAT_R32G32B32A32_UINT,    // MATERIAL1
};

// What RasterRenderer::execute needs to draw a record's traced draws into the G-buffer.
struct GBufferTargets {
  std::array<VkImage, GLPT_GBUFFER_ATTACHMENTS> images{};
  std::array<VkImageView, GLPT_GBUFFER_ATTACHMENTS> views{};
  // Per command of the record: 1 if it is a Draw that goes into the G-buffer (a traced draw).
  const std::vector<uint8_t>* traced = nullptr;
  // Sub-pixel offset of the G-buffer's projection (pixels): anti-aliasing by accumulation.
  glm::vec2 jitter{0.0f};
};

}  // namespace glpt::rt
