#include "rt_core/passes/composite_pass.hpp"

#include <cstdint>

#include "composite_spv.h"  // generated from shaders/composite.comp at build time
#include "gbuffer_layout.h"

namespace glpt::rt {
namespace {

constexpr VkDescriptorSetLayoutBinding kBindings[] = {
    compute_binding(GLPT_CO_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
    compute_binding(GLPT_CO_BINDING_STATES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_CO_BINDING_GBUFFER + 0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_CO_BINDING_GBUFFER + 1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_CO_BINDING_GBUFFER + 2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_CO_BINDING_GBUFFER + 3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_CO_BINDING_FRONT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_CO_BINDING_BACK, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_CO_BINDING_DENOISE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
};
static_assert(GLPT_GBUFFER_ATTACHMENTS == 4 && GLPT_CHANNELS == 3);

}  // namespace

CompositePass::CompositePass(const VulkanDevice& device)
    : device_(device),
      pipeline_(device, composite_spv, kBindings, 0,
                {GLPT_IMAGE_TILE_WIDTH, GLPT_IMAGE_TILE_HEIGHT}) {}

void CompositePass::record(VkCommandBuffer cmd, const CompositeResources& resources, uint32_t width,
                           uint32_t height) const {
  const VkDescriptorSet set = pipeline_.descriptor_set();
  const VkDescriptorBufferInfo frame{resources.frame->handle(), 0, sizeof(gpu::FrameUniforms)};
  const VkDescriptorBufferInfo states{resources.states->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo denoise{resources.denoise_uniforms->handle(), 0,
                                       sizeof(gpu::DenoiseUniforms)};
  VkDescriptorImageInfo images[GLPT_GBUFFER_ATTACHMENTS + 2];
  for (uint32_t i = 0; i < GLPT_GBUFFER_ATTACHMENTS; ++i)
    images[i] = general_image_info(resources.gbuffer[i]);
  images[GLPT_GBUFFER_ATTACHMENTS] = general_image_info(resources.front);
  images[GLPT_GBUFFER_ATTACHMENTS + 1] = general_image_info(resources.back);
  const VkWriteDescriptorSet writes[] = {
      uniform_buffer_write(set, GLPT_CO_BINDING_FRAME, &frame),
      storage_buffer_write(set, GLPT_CO_BINDING_STATES, &states),
      storage_image_write(set, GLPT_CO_BINDING_GBUFFER + 0, &images[0]),
      storage_image_write(set, GLPT_CO_BINDING_GBUFFER + 1, &images[1]),
      storage_image_write(set, GLPT_CO_BINDING_GBUFFER + 2, &images[2]),
      storage_image_write(set, GLPT_CO_BINDING_GBUFFER + 3, &images[3]),
      storage_image_write(set, GLPT_CO_BINDING_FRONT, &images[GLPT_GBUFFER_ATTACHMENTS]),
      storage_image_write(set, GLPT_CO_BINDING_BACK, &images[GLPT_GBUFFER_ATTACHMENTS + 1]),
      uniform_buffer_write(set, GLPT_CO_BINDING_DENOISE, &denoise),
  };
  pipeline_.update_and_dispatch(device_.handle(), cmd, writes, width, height);
}

}  // namespace glpt::rt
