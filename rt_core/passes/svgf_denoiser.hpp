// SVGF (Schied et al., "Spatiotemporal Variance-Guided Filtering", HPG 2017) over the trace
// pass's three radiance channels: temporal accumulation with reprojection through each draw's
// previous transforms (shaders/svgf_temporal.comp), then an edge-avoiding a-trous wavelet filter
// guided by the variance (shaders/svgf_atrous.comp). The composite pass multiplies the albedo
// back in. docs/denoiser.md has the parameters, the measurements and what differs from the paper.
//
// The history (guides and colour/moment histories of the last frame) belongs to one drawable:
// `prepare` is told whose frame comes, and a new size or owner starts without history.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "rt_core/vk/compute_pipeline.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "shared_types.h"

namespace glpt::rt {

struct DenoiseResources {
  const GpuBuffer* uniforms = nullptr;    // gpu::DenoiseUniforms
  const GpuBuffer* states = nullptr;      // gpu::GpuStateHistory[], per record state
  VkImageView position = VK_NULL_HANDLE;  // G-buffer POSITION and SURFACE
  VkImageView surface = VK_NULL_HANDLE;
  // The trace's TLAS and instance table: deformed surfaces reproject through their triangles.
  VkAccelerationStructureKHR scene = VK_NULL_HANDLE;
  const GpuBuffer* instances = nullptr;  // gpu::GpuInstance[]
};

class SvgfDenoiser {
 public:
  explicit SvgfDenoiser(const VulkanDevice& device) : device_(device) {}
  SvgfDenoiser(const SvgfDenoiser&) = delete;
  SvgfDenoiser& operator=(const SvgfDenoiser&) = delete;

  // Sizes the buffers for a width x height frame of `owner`'s (any pointer naming the drawable)
  // and compiles the passes on first use. Returns whether the previous frame's history can be
  // reprojected (same size and owner, not forgotten). Throws VulkanError.
  bool prepare(uint32_t width, uint32_t height, const void* owner);
  // Whether the device can filter a width x height frame: the work slots (and the two colour
  // histories, 15 layers of vec4: 240 bytes a pixel) are one allocation, kept within 2 GiB
  // (8.9 million pixels: 4096 x 2160 fits, 4096 x 4096 would need 4 GB; tests/extremes). Larger
  // frames are shown unfiltered, as under GLPT_DENOISER=off.
  bool fits(uint32_t width, uint32_t height) const;
  // Records, ahead of the trace pass that fills it, this frame's empty tile list (tiles(): the
  // tiles with a pixel the denoiser filters, GLPT_DN_BINDING_TILES), and after prepare() made
  // new buffers their cleared guides and motion. Call it for every frame record() follows.
  void record_before_trace(VkCommandBuffer cmd);
  const GpuBuffer& tiles() const { return tiles_; }
  // The tiles the last record filtered: read once it completed.
  uint32_t listed_tiles() const { return tiles_ ? tiles_.as<uint32_t>()[0] : 0u; }
  // Records the temporal pass and `iterations` a-trous iterations over the listed tiles; the
  // result is in work() at slot 0 (no iteration) or 1 + (iterations - 1) % 2. This frame's history
  // becomes the previous one for the next record. `specular`: the frame filters the specular
  // channel (GLPT_DN_NO_SPECULAR clear); without it the history holds no specular channel.
  void record(VkCommandBuffer cmd, const DenoiseResources& resources, uint32_t iterations,
              bool specular);
  // Whether the previous frame's history has a specular channel (else the next frame's
  // specular starts afresh: GLPT_DN_PREVIOUS_NO_SPECULAR).
  bool history_has_specular() const { return history_has_specular_; }
  // The work slots of the next record's colour history and of the previous one's
  // (DenoiseUniforms::slots).
  uint32_t history_slot() const { return GLPT_DN_SLOTS + parity_; }
  uint32_t previous_history_slot() const { return GLPT_DN_SLOTS + (parity_ ^ 1u); }
  // The frame stamps of the next record's guides and of the previous one's
  // (DenoiseUniforms::slots.zw, DenoiseGuide::meta.y): 24 bits, never 0.
  uint32_t stamp() const { return stamp_; }
  uint32_t previous_stamp() const { return previous_stamp_; }
  // The per-pixel buffers' device addresses for the next record (DenoiseUniforms::guides,
  // histories, moments, buffers: shared_types.h), after prepare().
  void write_addresses(gpu::DenoiseUniforms& uniforms) const;
  // Where the last record's pixels were in the frame before (the motion buffer, as
  // GL_EXT_buffer_reference_uvec2 takes its address), and the stamp that record's texels carry.
  glm::uvec2 motion_address() const;
  uint32_t recorded_stamp() const { return previous_stamp_; }
  // The next frame starts without history (a failure, a cut the caller knows of).
  void forget_history() noexcept { history_valid_ = false; }

 private:
  const VulkanDevice& device_;
  // Compiled on first use: programs that never denoise never pay for them.
  std::unique_ptr<ComputePipeline> temporal_, atrous_;
  // The per-pixel buffers (shared_types.h, DenoiseUniforms), by parity: [parity_] is this
  // frame's.
  std::array<GpuBuffer, 2> guides_, histories_, moments_;
  GpuBuffer work_;
  GpuBuffer motion_;
  GpuBuffer tiles_;  // GLPT_DN_BINDING_TILES, sized with the others
  VkDeviceSize tile_count_ = 0;
  bool buffers_need_clear_ = false;  // created since the last record(): guides and motion
  uint32_t width_ = 0, height_ = 0;
  const void* owner_ = nullptr;
  bool history_valid_ = false;
  bool history_has_specular_ = false;
  uint32_t parity_ = 0;
  uint32_t stamp_ = 1, previous_stamp_ = 0;
};

}  // namespace glpt::rt
