#include "rt_core/passes/tonemap_pass.hpp"

#include <cstdint>

#include "shared_types.h"
#include "tonemap_spv.h"  // generated from shaders/tonemap.comp at build time

namespace glpt::rt {
namespace {

constexpr VkDescriptorSetLayoutBinding kBindings[] = {
    {GLPT_TM_BINDING_ACCUMULATION, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
     VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    {GLPT_TM_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
     nullptr},
    {GLPT_TM_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
     nullptr},
};

}  // namespace

TonemapPass::TonemapPass(const VulkanDevice& device)
    : device_(device), pipeline_(device, tonemap_spv, kBindings) {}

void TonemapPass::record(VkCommandBuffer cmd, const TonemapResources& resources, uint32_t width,
                         uint32_t height) const {
  const VkDescriptorSet set = pipeline_.descriptor_set();
  const VkDescriptorBufferInfo accumulation{resources.accumulation->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo output{resources.output->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo frame{resources.frame->handle(), 0, sizeof(gpu::FrameUniforms)};
  const VkWriteDescriptorSet writes[] = {
      storage_buffer_write(set, GLPT_TM_BINDING_ACCUMULATION, &accumulation),
      storage_buffer_write(set, GLPT_TM_BINDING_OUTPUT, &output),
      uniform_buffer_write(set, GLPT_TM_BINDING_FRAME, &frame),
  };
  pipeline_.update_and_dispatch(device_.handle(), cmd, writes, width, height);
}

}  // namespace glpt::rt
