// The tonemap dispatch (shaders/tonemap.comp): accumulated radiance -> RGBA8 in a host-visible
// buffer, rows bottom-to-top like glReadPixels.
#pragma once

#include "rt_core/vk/compute_pipeline.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

struct TonemapResources {
  const GpuBuffer* accumulation = nullptr;  // vec4[width * height]
  const GpuBuffer* output = nullptr;        // uint32_t[width * height]
  const GpuBuffer* frame = nullptr;         // gpu::FrameUniforms
};

class TonemapPass {
 public:
  explicit TonemapPass(const VulkanDevice& device);

  // Points the descriptor set at `resources` and records the dispatch (see PathTracePass).
  void record(VkCommandBuffer cmd, const TonemapResources& resources, uint32_t width,
              uint32_t height) const;

 private:
  const VulkanDevice& device_;
  ComputePipeline pipeline_;
};

}  // namespace glpt::rt
