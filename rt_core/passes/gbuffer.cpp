#include "rt_core/passes/gbuffer.hpp"

namespace glpt::rt {

void GBuffer::ensure(VulkanDevice& device, uint32_t width, uint32_t height) {
  if (width == width_ && height == height_ && images_[0]) return;
  for (GpuImage& image : images_) image = GpuImage();
  width_ = height_ = 0;
  if (width == 0 || height == 0) return;
  for (int a = 0; a < GLPT_GBUFFER_ATTACHMENTS; ++a) {
    GpuImageInfo info;
    info.format = kGBufferFormats[a];
    info.extent = {width, height, 1};
    info.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                 VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    images_[a] = GpuImage::create(device, info);
  }
  device.submit_and_wait([&](VkCommandBuffer cmd) {
    for (const GpuImage& image : images_) image.initial_barrier(cmd);
  });
  width_ = width;
  height_ = height;
}

GBufferTargets GBuffer::targets(const std::vector<uint8_t>* traced, glm::vec2 jitter) const {
  GBufferTargets targets;
  for (int a = 0; a < GLPT_GBUFFER_ATTACHMENTS; ++a) {
    targets.images[a] = images_[a].handle();
    targets.views[a] = images_[a].view();
  }
  targets.traced = traced;
  targets.jitter = jitter;
  return targets;
}

}  // namespace glpt::rt
