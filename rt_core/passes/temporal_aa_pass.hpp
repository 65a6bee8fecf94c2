// Temporal anti-aliasing (shaders/temporal_aa.comp), the last stage of the SVGF pipeline: the
// colour buffer the composite pass wrote, blended with its own history reprojected by the
// denoiser's motion (SvgfDenoiser::motion_address), into the colour buffer. Frames it runs on are
// drawn at a sub-pixel jitter (PathTracer), so the history averages each pixel's area.
// docs/denoiser.md, "Anti-aliasing".
//
// The history belongs to one drawable: `prepare` is told whose frame comes, and a new size or
// owner starts without history, as does any frame after one the pass did not run on.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "rt_core/vk/compute_pipeline.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "shared_types.h"

namespace glpt::rt {

struct TemporalAaResources {
  const GpuBuffer* uniforms = nullptr;   // gpu::TemporalAaUniforms
  VkImageView colour = VK_NULL_HANDLE;   // the colour buffer the composite wrote (BGRA8)
  const GpuBuffer* tiles = nullptr;      // SvgfDenoiser::tiles(): the tiles it filtered
  VkImageView surface = VK_NULL_HANDLE;  // the G-buffer's SURFACE
};

class TemporalAaPass {
 public:
  explicit TemporalAaPass(const VulkanDevice& device) : device_(device) {}
  TemporalAaPass(const TemporalAaPass&) = delete;
  TemporalAaPass& operator=(const TemporalAaPass&) = delete;

  // Sizes the histories for a width x height frame of `owner`'s and compiles the pass on first
  // use. Returns whether the previous frame's history can be reprojected: the pass ran on the
  // frame before, at this size and for this owner. Throws VulkanError.
  bool prepare(uint32_t width, uint32_t height, const void* owner);
  // The histories' device addresses for the next record (TemporalAaUniforms::buffers.zw and
  // histories.xy; buffers.xy, the denoiser's motion, is kept), after prepare().
  void write_addresses(gpu::TemporalAaUniforms& uniforms) const;
  // Records both dispatches (resolve, then, unless `write_back` is false, the copy into the
  // colour buffer). This frame's history becomes the previous one for the next record.
  void record(VkCommandBuffer cmd, const TemporalAaResources& resources, uint32_t width,
              uint32_t height, bool write_back);
  // The next frame starts without history (a frame the pass did not run on, a failure).
  void forget_history() noexcept { history_valid_ = false; }
  // Whether the last frame recorded a history (a next frame of its size and owner continues it).
  bool has_history() const { return history_valid_; }

 private:
  const VulkanDevice& device_;
  std::unique_ptr<ComputePipeline> pipeline_;  // compiled on first use
  std::array<GpuBuffer, 2> histories_;         // by parity: [parity_] is this frame's
  uint32_t width_ = 0, height_ = 0;
  const void* owner_ = nullptr;
  bool history_valid_ = false;
  uint32_t parity_ = 0;
};

}  // namespace glpt::rt
