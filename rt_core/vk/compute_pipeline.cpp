#include "rt_core/vk/compute_pipeline.hpp"

#include <map>
#include <vector>

#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"
#include "shared_types.h"

namespace glpt::rt {

ComputePipeline::ComputePipeline(const VulkanDevice& device, std::span<const uint32_t> spirv,
                                 std::span<const VkDescriptorSetLayoutBinding> bindings,
                                 uint32_t push_constant_bytes, VkExtent2D tile)
    : tile_(tile) {
  VkDevice vk_device = device.handle();

  auto set_layout_info = make_info<VkDescriptorSetLayoutCreateInfo>(
      VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_layout_info.bindingCount = static_cast<uint32_t>(bindings.size());
  set_layout_info.pBindings = bindings.data();
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateDescriptorSetLayout(vk_device, &set_layout_info, nullptr, &set_layout));
  set_layout_ = vk::DescriptorSetLayout(set_layout, {vk_device});

  auto layout_info =
      make_info<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  const VkPushConstantRange push_range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_bytes};
  if (push_constant_bytes > 0) {
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push_range;
  }
  VkPipelineLayout layout = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreatePipelineLayout(vk_device, &layout_info, nullptr, &layout));
  layout_ = vk::PipelineLayout(layout, {vk_device});

  auto module_info =
      make_info<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  module_info.codeSize = spirv.size_bytes();
  module_info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateShaderModule(vk_device, &module_info, nullptr, &module));
  vk::ShaderModule module_owner(module, {vk_device});  // only needed until the pipeline exists

  auto pipeline_info =
      make_info<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  pipeline_info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipeline_info.stage.module = module;
  pipeline_info.stage.pName = "main";
  // The workgroup size (GLPT_SPEC_TILE_WIDTH/HEIGHT in the shader).
  const uint32_t tile_size[2] = {tile_.width, tile_.height};
  const VkSpecializationMapEntry entries[2] = {{GLPT_SPEC_TILE_WIDTH, 0, 4},
                                               {GLPT_SPEC_TILE_HEIGHT, 4, 4}};
  const VkSpecializationInfo specialization{2, entries, sizeof tile_size, tile_size};
  pipeline_info.stage.pSpecializationInfo = &specialization;
  pipeline_info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  GLPT_VK_CHECK(
      vkCreateComputePipelines(vk_device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline));
  pipeline_ = vk::Pipeline(pipeline, {vk_device});

  std::map<VkDescriptorType, uint32_t> counts;
  for (const auto& binding : bindings) counts[binding.descriptorType] += binding.descriptorCount;
  std::vector<VkDescriptorPoolSize> pool_sizes;
  for (const auto& [type, count] : counts) pool_sizes.push_back({type, count});
  auto pool_info =
      make_info<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = static_cast<uint32_t>(pool_sizes.size());
  pool_info.pPoolSizes = pool_sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateDescriptorPool(vk_device, &pool_info, nullptr, &pool));
  pool_ = vk::DescriptorPool(pool, {vk_device});

  auto set_info =
      make_info<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  set_info.descriptorPool = pool;
  set_info.descriptorSetCount = 1;
  set_info.pSetLayouts = &set_layout;
  GLPT_VK_CHECK(vkAllocateDescriptorSets(vk_device, &set_info, &descriptor_set_));
}

void ComputePipeline::update_and_dispatch(VkDevice device, VkCommandBuffer cmd,
                                          std::span<const VkWriteDescriptorSet> writes,
                                          uint32_t width, uint32_t height) const {
  vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1,
                          &descriptor_set_, 0, nullptr);
  vkCmdDispatch(cmd, (width + tile_.width - 1) / tile_.width,
                (height + tile_.height - 1) / tile_.height, 1);
}

void ComputePipeline::update(VkDevice device, std::span<const VkWriteDescriptorSet> writes) const {
  vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

void ComputePipeline::bind(VkCommandBuffer cmd, const void* push_constants,
                           uint32_t push_bytes) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1,
                          &descriptor_set_, 0, nullptr);
  if (push_bytes > 0)
    vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes,
                       push_constants);
}

void ComputePipeline::dispatch(VkCommandBuffer cmd, const void* push_constants, uint32_t push_bytes,
                               uint32_t width, uint32_t height) const {
  bind(cmd, push_constants, push_bytes);
  vkCmdDispatch(cmd, (width + tile_.width - 1) / tile_.width,
                (height + tile_.height - 1) / tile_.height, 1);
}

void ComputePipeline::dispatch_indirect(VkCommandBuffer cmd, const void* push_constants,
                                        uint32_t push_bytes, VkBuffer buffer,
                                        VkDeviceSize offset) const {
  bind(cmd, push_constants, push_bytes);
  vkCmdDispatchIndirect(cmd, buffer, offset);
}

VkWriteDescriptorSet storage_buffer_write(VkDescriptorSet set, uint32_t binding,
                                          const VkDescriptorBufferInfo* info) {
  auto write = make_info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = info;
  return write;
}

VkWriteDescriptorSetAccelerationStructureKHR acceleration_structure_info(
    const VkAccelerationStructureKHR* scene) {
  auto info = make_info<VkWriteDescriptorSetAccelerationStructureKHR>(
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR);
  info.accelerationStructureCount = 1;
  info.pAccelerationStructures = scene;
  return info;
}

VkWriteDescriptorSet acceleration_structure_write(
    VkDescriptorSet set, uint32_t binding,
    const VkWriteDescriptorSetAccelerationStructureKHR* scene) {
  auto write = make_info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.pNext = scene;  // VkWriteDescriptorSet's pNext is const
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  return write;
}

VkWriteDescriptorSet storage_image_write(VkDescriptorSet set, uint32_t binding,
                                         const VkDescriptorImageInfo* info) {
  auto write = make_info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  write.pImageInfo = info;
  return write;
}

VkDescriptorImageInfo general_image_info(VkImageView view) {
  return {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
}

VkWriteDescriptorSet uniform_buffer_write(VkDescriptorSet set, uint32_t binding,
                                          const VkDescriptorBufferInfo* info) {
  VkWriteDescriptorSet write = storage_buffer_write(set, binding, info);
  write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  return write;
}

}  // namespace glpt::rt
