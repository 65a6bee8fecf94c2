// The fixed-function raster pipelines: one VkPipeline per PipelineKey, compiled on first use and
// kept (no pipeline is compiled per draw once a program's states have been seen). Compiled
// pipelines also go to a VkPipelineCache that is loaded from and saved to disk
// (pipeline_cache_file.hpp), so a program's second run compiles nothing either.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <unordered_map>
#include <vector>

#include "rt_core/raster/pipeline_cache_file.hpp"
#include "rt_core/raster/pipeline_key.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

// BGRA: the byte order X windows show (32-bit 0x..RRGGBB pixels), so presenting is a plain copy.
// Blending, logic ops and masks work per channel, so the order changes no GL result.
inline constexpr VkFormat kColorFormat = VK_FORMAT_B8G8R8A8_UNORM;
inline constexpr VkFormat kDepthStencilFormat = VK_FORMAT_D24_UNORM_S8_UINT;

class RasterPipelines {
 public:
  explicit RasterPipelines(const VulkanDevice& device);
  ~RasterPipelines();  // saves the pipeline cache
  RasterPipelines(const RasterPipelines&) = delete;
  RasterPipelines& operator=(const RasterPipelines&) = delete;

  // The pipeline for `key`, compiled now if it is new (`created` says so). Throws VulkanError.
  // Where the device sets blend state per draw, one pipeline serves every blend, colour mask and
  // logic op state of a key: then set_blend_state must follow each bind, and before each draw
  // whose key's blend state differs from the last one set.
  VkPipeline get(const PipelineKey& key, bool* created);
  void set_blend_state(VkCommandBuffer cmd, const PipelineKey& key) const;
  bool blend_is_dynamic() const { return device_.dynamic_blend() != nullptr; }

  VkPipelineLayout layout() const { return layout_.get(); }
  VkDescriptorSetLayout set_layout() const { return set_layout_.get(); }
  // The descriptors one set of set_layout() holds, by type (for pools).
  const std::vector<VkDescriptorPoolSize>& set_descriptor_counts() const { return set_counts_; }
  // Push constants: gpu::RasterPushConstants for push_constant_stages(), but its first
  // kStateIndexPushBytes (the draw's state index) for the vertex stage alone.
  static constexpr uint32_t kStateIndexPushBytes = sizeof(uint32_t);
  VkShaderStageFlags push_constant_stages() const { return push_stages_; }
  size_t size() const { return pipelines_.size(); }

  // Blending and logic ops in the fragment shader (PipelineKey::framebuffer_ops) where the device
  // reads colour attachments in rasterization order: such draws (one colour target) render in
  // render_pass(), whose colour attachment is also input attachment 0, bound at
  // GLPT_RASTER_BINDING_FRAMEBUFFER; their pipelines are made for it (uses_render_pass()), all
  // others for dynamic rendering.
  bool blends_in_shader() const { return static_cast<bool>(render_pass_); }
  VkRenderPass render_pass() const { return render_pass_.get(); }
  bool uses_render_pass(const PipelineKey& key) const;

 private:
  VkPipeline create(const PipelineKey& key);
  // `key` without what is set per draw.
  PipelineKey pipeline_of(const PipelineKey& key) const;
  static vk::RenderPass create_single_target_render_pass(VkDevice dev);

  const VulkanDevice& device_;
  vk::DescriptorSetLayout set_layout_;
  std::vector<VkDescriptorPoolSize> set_counts_;
  vk::PipelineLayout layout_;
  // The vertex and fragment shaders in variants by the varyings they declare (raster_varyings.h),
  // cheapest first: a pipeline takes the first that declares what it reads.
  struct ShaderSet {
    uint32_t varyings = 0;  // GLPT_VARYING_* bits
    vk::ShaderModule vertex, vertex_clip, fragment_smooth, fragment_flat;
    vk::ShaderModule fragment_smooth_ops, fragment_flat_ops;  // GLPT_FRAMEBUFFER_OPS (or null)
  };
  std::vector<ShaderSet> shader_sets_;
  vk::ShaderModule fragment_pixels_, fragment_pixels_depth_;
  vk::ShaderModule unfilled_lines_, unfilled_points_;  // null without geometry shaders
  // Path-traced mode's G-buffer pass (null without geometry shaders).
  vk::ShaderModule gbuffer_vertex_, gbuffer_vertex_clip_, gbuffer_geometry_, gbuffer_geometry_clip_;
  vk::ShaderModule gbuffer_fragment_smooth_, gbuffer_fragment_flat_;
  VkShaderStageFlags push_stages_ = 0;
  vk::RenderPass render_pass_;  // null without ordered framebuffer reads
  PipelineCacheFile cache_file_;
  vk::PipelineCache cache_;
  std::unordered_map<PipelineKey, vk::Pipeline, PipelineKeyHash> pipelines_;
};

}  // namespace glpt::rt
