// The trace pass (shaders/path_trace.comp): lights every pixel the G-buffer covers (shadow rays,
// diffuse bounces, ambient occlusion), accumulates the samples, and writes the average into the
// colour buffers; pixels no sample covered keep what the clears and raster draws left there.
#pragma once

#include "rt_core/vk/compute_pipeline.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "shared_types.h"

namespace glpt::rt {

struct PathTraceResources {
  VkAccelerationStructureKHR scene = VK_NULL_HANDLE;
  const GpuBuffer* instances = nullptr;     // gpu::GpuInstance[]
  const GpuBuffer* lights = nullptr;        // gpu::GpuLight[]
  const GpuBuffer* states = nullptr;        // gpu::GpuTraceState[]
  const GpuBuffer* accumulation = nullptr;  // vec4[2 * width * height]
  const GpuBuffer* counters = nullptr;      // gpu::GpuCounters, zeroed by the caller
  const GpuBuffer* frame = nullptr;         // gpu::FrameUniforms
  VkImageView gbuffer[4] = {};              // gbuffer_layout.h attachments
  VkImageView front = VK_NULL_HANDLE;       // colour buffers (the same view twice when the
  VkImageView back = VK_NULL_HANDLE;        // drawable is single-buffered)
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
