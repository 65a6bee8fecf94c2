// The trace pass (shaders/path_trace.comp): the light transport of every pixel the G-buffer
// covers (next-event estimation, bounces, ambient occlusion), written as this frame's radiance
// channels (shared_types.h, GLPT_CHANNEL_*: a buffer at FrameUniforms::buffers.zw), which the
// composite pass turns into colours.
#pragma once

#include <array>

#include "rt_core/vk/compute_pipeline.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "shared_types.h"

namespace glpt::rt {

struct PathTraceResources {
  VkAccelerationStructureKHR scene = VK_NULL_HANDLE;
  const GpuBuffer* instances = nullptr;      // gpu::GpuInstance[]
  const GpuBuffer* lights = nullptr;         // gpu::GpuLight[]
  const GpuBuffer* emitters = nullptr;       // gpu::GpuEmitter[]
  const GpuBuffer* clip_planes = nullptr;    // gpu::GpuClipPlanes[]
  const GpuBuffer* states = nullptr;         // gpu::GpuTraceState[]
  const GpuBuffer* counters = nullptr;       // gpu::GpuCounters, zeroed by the caller
  const GpuBuffer* frame = nullptr;          // gpu::FrameUniforms
  const GpuBuffer* denoise_tiles = nullptr;  // the denoiser's tile list (GLPT_DN_BINDING_TILES)
  const GpuBuffer* blue_noise = nullptr;     // kBlueNoiseMask (GLPT_PT_BINDING_BLUE_NOISE)
  std::array<VkImageView, 4> gbuffer{};      // gbuffer_layout.h attachments
  // Combined image samplers of the texture tables, one per target (every entry valid: dummies
  // where unused).
  std::array<VkDescriptorImageInfo, GLPT_TRACE_TEXTURES> textures{};
  std::array<VkDescriptorImageInfo, GLPT_TRACE_TEXTURES_OTHER> textures_1d{};
  std::array<VkDescriptorImageInfo, GLPT_TRACE_TEXTURES_OTHER> textures_3d{};
  std::array<VkDescriptorImageInfo, GLPT_TRACE_TEXTURES_OTHER> textures_cube{};
};

class PathTracePass {
 public:
  explicit PathTracePass(const VulkanDevice& device);

  // Points the descriptor set at `resources` and records the dispatches over width x height
  // pixels: one over every pixel, or, when `grid_width` x `grid_height` (the coarse grid of
  // FrameUniforms::trace_grid) is smaller than the window, the grid pass over its cells and then
  // the fill pass over the window. Rewriting the set every frame is cheap and means buffers may
  // be re-created freely; it is safe because the previous use of the set has completed (the
  // tracer waits for its previous trace before recording the next).
  void record(VkCommandBuffer cmd, const PathTraceResources& resources, uint32_t width,
              uint32_t height, uint32_t grid_width, uint32_t grid_height) const;

 private:
  const VulkanDevice& device_;
  ComputePipeline pipeline_;
};

}  // namespace glpt::rt
