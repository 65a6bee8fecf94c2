#include "rt_core/passes/path_trace_pass.hpp"

#include <cstdint>
#include <span>

#include "gbuffer_layout.h"
#include "path_trace_spv.h"  // generated from shaders/path_trace.comp at build time
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

constexpr VkDescriptorSetLayoutBinding kBindings[] = {
    compute_binding(GLPT_PT_BINDING_SCENE, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR),
    compute_binding(GLPT_PT_BINDING_INSTANCES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_PT_BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_PT_BINDING_EMITTERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_PT_BINDING_CLIP_PLANES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_PT_BINDING_COUNTERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_PT_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
    compute_binding(GLPT_PT_BINDING_STATES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_PT_BINDING_GBUFFER + 0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_PT_BINDING_GBUFFER + 1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_PT_BINDING_GBUFFER + 2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_PT_BINDING_GBUFFER + 3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_PT_BINDING_TEXTURES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    GLPT_TRACE_TEXTURES),
    compute_binding(GLPT_PT_BINDING_TEXTURES_1D, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    GLPT_TRACE_TEXTURES_OTHER),
    compute_binding(GLPT_PT_BINDING_TEXTURES_3D, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    GLPT_TRACE_TEXTURES_OTHER),
    compute_binding(GLPT_PT_BINDING_TEXTURES_CUBE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                    GLPT_TRACE_TEXTURES_OTHER),
    compute_binding(GLPT_PT_BINDING_DENOISE_TILES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_PT_BINDING_BLUE_NOISE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
};
static_assert(GLPT_GBUFFER_ATTACHMENTS == 4 && GLPT_CHANNELS == 3);

}  // namespace

PathTracePass::PathTracePass(const VulkanDevice& device)
    : device_(device), pipeline_(device, path_trace_spv, kBindings, sizeof(uint32_t)) {}

void PathTracePass::record(VkCommandBuffer cmd, const PathTraceResources& resources, uint32_t width,
                           uint32_t height, uint32_t grid_width, uint32_t grid_height) const {
  const VkDescriptorSet set = pipeline_.descriptor_set();
  const auto scene_info = acceleration_structure_info(&resources.scene);
  const VkWriteDescriptorSet scene_write =
      acceleration_structure_write(set, GLPT_PT_BINDING_SCENE, &scene_info);

  auto whole = [](const GpuBuffer* buffer) {
    return VkDescriptorBufferInfo{buffer->handle(), 0, VK_WHOLE_SIZE};
  };
  const VkDescriptorBufferInfo instances = whole(resources.instances);
  const VkDescriptorBufferInfo lights = whole(resources.lights);
  const VkDescriptorBufferInfo emitters = whole(resources.emitters);
  const VkDescriptorBufferInfo clip_planes = whole(resources.clip_planes);
  const VkDescriptorBufferInfo states = whole(resources.states);
  const VkDescriptorBufferInfo counters = whole(resources.counters);
  const VkDescriptorBufferInfo denoise_tiles = whole(resources.denoise_tiles);
  const VkDescriptorBufferInfo blue_noise = whole(resources.blue_noise);
  const VkDescriptorBufferInfo frame{resources.frame->handle(), 0, sizeof(gpu::FrameUniforms)};
  VkDescriptorImageInfo images[GLPT_GBUFFER_ATTACHMENTS];
  for (uint32_t i = 0; i < GLPT_GBUFFER_ATTACHMENTS; ++i)
    images[i] = general_image_info(resources.gbuffer[i]);
  auto texture_write = [set](uint32_t binding, std::span<const VkDescriptorImageInfo> table) {
    auto write = make_info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstSet = set;
    write.dstBinding = binding;
    write.descriptorCount = static_cast<uint32_t>(table.size());
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = table.data();
    return write;
  };
  const VkWriteDescriptorSet writes[] = {
      scene_write,
      storage_buffer_write(set, GLPT_PT_BINDING_INSTANCES, &instances),
      storage_buffer_write(set, GLPT_PT_BINDING_LIGHTS, &lights),
      storage_buffer_write(set, GLPT_PT_BINDING_EMITTERS, &emitters),
      storage_buffer_write(set, GLPT_PT_BINDING_CLIP_PLANES, &clip_planes),
      storage_buffer_write(set, GLPT_PT_BINDING_STATES, &states),
      storage_buffer_write(set, GLPT_PT_BINDING_COUNTERS, &counters),
      storage_buffer_write(set, GLPT_PT_BINDING_DENOISE_TILES, &denoise_tiles),
      storage_buffer_write(set, GLPT_PT_BINDING_BLUE_NOISE, &blue_noise),
      uniform_buffer_write(set, GLPT_PT_BINDING_FRAME, &frame),
      storage_image_write(set, GLPT_PT_BINDING_GBUFFER + 0, &images[0]),
      storage_image_write(set, GLPT_PT_BINDING_GBUFFER + 1, &images[1]),
      storage_image_write(set, GLPT_PT_BINDING_GBUFFER + 2, &images[2]),
      storage_image_write(set, GLPT_PT_BINDING_GBUFFER + 3, &images[3]),
      texture_write(GLPT_PT_BINDING_TEXTURES, resources.textures),
      texture_write(GLPT_PT_BINDING_TEXTURES_1D, resources.textures_1d),
      texture_write(GLPT_PT_BINDING_TEXTURES_3D, resources.textures_3d),
      texture_write(GLPT_PT_BINDING_TEXTURES_CUBE, resources.textures_cube),
  };
  pipeline_.update(device_.handle(), writes);
  if (grid_width >= width && grid_height >= height) {
    const uint32_t pass = GLPT_TRACE_PASS_ALL;
    pipeline_.dispatch(cmd, &pass, sizeof pass, width, height);
    return;
  }
  const uint32_t grid_pass = GLPT_TRACE_PASS_GRID;
  pipeline_.dispatch(cmd, &grid_pass, sizeof grid_pass, grid_width, grid_height);
  // The fill pass reads the channels the grid pass wrote.
  VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr, VK_ACCESS_SHADER_WRITE_BIT,
                         VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &memory, 0, nullptr, 0, nullptr);
  const uint32_t fill_pass = GLPT_TRACE_PASS_FILL;
  pipeline_.dispatch(cmd, &fill_pass, sizeof fill_pass, width, height);
}

}  // namespace glpt::rt
