// The path tracing dispatch (shaders/path_trace.comp): traces the frame's samples for every
// viewport pixel and adds them to the accumulation buffer, counting rays on the GPU.
#pragma once

#include "rt_core/vk/compute_pipeline.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

struct PathTraceResources {
  VkAccelerationStructureKHR scene = VK_NULL_HANDLE;
  const GpuBuffer* instances = nullptr;     // gpu::GpuInstance[]
  const GpuBuffer* lights = nullptr;        // gpu::GpuLight[]
  const GpuBuffer* accumulation = nullptr;  // vec4[width * height]
  const GpuBuffer* counters = nullptr;      // gpu::GpuCounters, zeroed by the caller
  const GpuBuffer* frame = nullptr;         // gpu::FrameUniforms
};

class PathTracePass {
 public:
  explicit PathTracePass(const VulkanDevice& device);

  // Points the descriptor set at `resources` and records the dispatch over width x height
  // pixels. Rewriting the set every frame is cheap and means buffers may be re-created freely;
  // it is safe because the previous use of the set has completed (every submission is waited).
  void record(VkCommandBuffer cmd, const PathTraceResources& resources, uint32_t width,
              uint32_t height) const;

 private:
  const VulkanDevice& device_;
  ComputePipeline pipeline_;
};

}  // namespace glpt::rt
