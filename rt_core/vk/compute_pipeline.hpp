// A compute pipeline with one descriptor set (layout, pool, set), built from embedded SPIR-V.
// Shared plumbing of the passes (path_trace_pass, composite_pass).
#pragma once

#include <cstdint>
#include <span>

#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"
#include "shared_types.h"  // GLPT_TILE_SIZE

namespace glpt::rt {

class ComputePipeline {
 public:
  // `bindings` are all compute-stage bindings of set 0; `push_constant_bytes` of push constants
  // (0: none); `tile`: the workgroup size, given to the shader as the specialization constants
  // GLPT_SPEC_TILE_WIDTH and GLPT_SPEC_TILE_HEIGHT. Throws VulkanError.
  ComputePipeline(const VulkanDevice& device, std::span<const uint32_t> spirv,
                  std::span<const VkDescriptorSetLayoutBinding> bindings,
                  uint32_t push_constant_bytes = 0,
                  VkExtent2D tile = {GLPT_TILE_SIZE, GLPT_TILE_SIZE});

  VkPipeline pipeline() const { return pipeline_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  VkDescriptorSet descriptor_set() const { return descriptor_set_; }

  // Writes `writes` into the set, binds the pipeline and its set and dispatches enough
  // workgroups (tiles) to cover width x height invocations.
  void update_and_dispatch(VkDevice device, VkCommandBuffer cmd,
                           std::span<const VkWriteDescriptorSet> writes, uint32_t width,
                           uint32_t height) const;
  // The same in steps, for passes dispatched several times with other push constants: write the
  // set once, then bind and dispatch (with push) per iteration.
  void update(VkDevice device, std::span<const VkWriteDescriptorSet> writes) const;
  void dispatch(VkCommandBuffer cmd, const void* push_constants, uint32_t push_bytes,
                uint32_t width, uint32_t height) const;
  // The same with the workgroup counts read from `buffer` at `offset` (VkDispatchIndirectCommand).
  void dispatch_indirect(VkCommandBuffer cmd, const void* push_constants, uint32_t push_bytes,
                         VkBuffer buffer, VkDeviceSize offset) const;

 private:
  // Binds the pipeline and its set and pushes `push_bytes` of push constants (if any).
  void bind(VkCommandBuffer cmd, const void* push_constants, uint32_t push_bytes) const;

  vk::DescriptorSetLayout set_layout_;
  vk::PipelineLayout layout_;
  vk::Pipeline pipeline_;
  vk::DescriptorPool pool_;
  VkDescriptorSet descriptor_set_ = VK_NULL_HANDLE;  // freed with pool_
  VkExtent2D tile_;
};

// A compute-stage binding of set 0 (`count` descriptors).
constexpr VkDescriptorSetLayoutBinding compute_binding(uint32_t index, VkDescriptorType type,
                                                       uint32_t count = 1) {
  return {index, type, count, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
}

// Helpers for vkUpdateDescriptorSets.
VkWriteDescriptorSet storage_buffer_write(VkDescriptorSet set, uint32_t binding,
                                          const VkDescriptorBufferInfo* info);
VkWriteDescriptorSet uniform_buffer_write(VkDescriptorSet set, uint32_t binding,
                                          const VkDescriptorBufferInfo* info);
VkWriteDescriptorSet storage_image_write(VkDescriptorSet set, uint32_t binding,
                                         const VkDescriptorImageInfo* info);
// `scene` (one acceleration structure, VkWriteDescriptorSetAccelerationStructureKHR) must outlive
// the returned write, which points at it.
VkWriteDescriptorSet acceleration_structure_write(
    VkDescriptorSet set, uint32_t binding,
    const VkWriteDescriptorSetAccelerationStructureKHR* scene);
// The pNext of acceleration_structure_write: one acceleration structure, `*scene`.
VkWriteDescriptorSetAccelerationStructureKHR acceleration_structure_info(
    const VkAccelerationStructureKHR* scene);
// A storage image in VK_IMAGE_LAYOUT_GENERAL (every image of glpt's, gpu_image.hpp).
VkDescriptorImageInfo general_image_info(VkImageView view);

}  // namespace glpt::rt
