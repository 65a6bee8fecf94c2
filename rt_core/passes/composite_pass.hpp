// The composite pass (shaders/composite.comp): the radiance channels times the G-buffer's albedo,
// plus specular and emission, through GL's fog, averaged over the accumulated frames and blended
// with the colour buffer where samples missed the pixel, into the GL colour buffer(s).
#pragma once

#include <array>

#include "rt_core/vk/compute_pipeline.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "shared_types.h"

namespace glpt::rt {

struct CompositeResources {
  const GpuBuffer* frame = nullptr;   // gpu::FrameUniforms
  const GpuBuffer* states = nullptr;  // gpu::GpuTraceState[]
  std::array<VkImageView, 4> gbuffer{};
  // gpu::DenoiseUniforms (flags 0: not denoised; else the work slots' address)
  const GpuBuffer* denoise_uniforms = nullptr;
  VkImageView front = VK_NULL_HANDLE;  // colour buffers (the same view twice when the drawable
  VkImageView back = VK_NULL_HANDLE;   // is single-buffered)
};

class CompositePass {
 public:
  explicit CompositePass(const VulkanDevice& device);

  // As PathTracePass::record.
  void record(VkCommandBuffer cmd, const CompositeResources& resources, uint32_t width,
              uint32_t height) const;

 private:
  const VulkanDevice& device_;
  ComputePipeline pipeline_;
};

}  // namespace glpt::rt
