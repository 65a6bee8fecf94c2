#include "rt_core/passes/temporal_aa_pass.hpp"

#include <algorithm>

#include "shared_types.h"
#include "temporal_aa_spv.h"  // generated from shaders/temporal_aa.comp at build time

namespace glpt::rt {
namespace {

constexpr VkDescriptorSetLayoutBinding kBindings[] = {
    compute_binding(GLPT_TAA_BINDING_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
    compute_binding(GLPT_TAA_BINDING_COLOUR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_TAA_BINDING_TILES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_TAA_BINDING_SURFACE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
};

}  // namespace

void TemporalAaPass::write_addresses(gpu::TemporalAaUniforms& uniforms) const {
  uniforms.buffers = glm::uvec4(glm::uvec2(uniforms.buffers), histories_[parity_].address_words());
  uniforms.histories = glm::uvec4(histories_[parity_ ^ 1u].address_words(), 0u, 0u);
}

bool TemporalAaPass::prepare(uint32_t width, uint32_t height, const void* owner) {
  if (!pipeline_)
    pipeline_ = std::make_unique<ComputePipeline>(
        device_, temporal_aa_spv, kBindings, static_cast<uint32_t>(sizeof(uint32_t)),
        VkExtent2D{GLPT_IMAGE_TILE_WIDTH, GLPT_IMAGE_TILE_HEIGHT});
  if (width != width_ || height != height_ || !histories_[0]) {
    history_valid_ = false;
    width_ = height_ = 0;
    // A vec4 a pixel (shared_types.h, GLPT_TAA_*); every pixel is written before a frame with
    // history reads it.
    const VkDeviceSize bytes =
        VkDeviceSize{std::max(width, 1u)} * std::max(height, 1u) * 4 * sizeof(float);
    for (GpuBuffer& buffer : histories_)
      buffer = GpuBuffer::create(device_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    width_ = width;
    height_ = height;
  }
  if (owner != owner_) history_valid_ = false;
  owner_ = owner;
  return history_valid_;
}

void TemporalAaPass::record(VkCommandBuffer cmd, const TemporalAaResources& resources,
                            uint32_t width, uint32_t height, bool write_back) {
  const uint32_t previous = parity_ ^ 1u;
  const VkDescriptorBufferInfo uniforms{resources.uniforms->handle(), 0,
                                        sizeof(gpu::TemporalAaUniforms)};
  const VkDescriptorImageInfo images[2] = {general_image_info(resources.colour),
                                           general_image_info(resources.surface)};
  const VkDescriptorBufferInfo tiles{resources.tiles->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorSet set = pipeline_->descriptor_set();
  const VkWriteDescriptorSet writes[] = {
      uniform_buffer_write(set, GLPT_TAA_BINDING_UNIFORMS, &uniforms),
      storage_image_write(set, GLPT_TAA_BINDING_COLOUR, &images[0]),
      storage_buffer_write(set, GLPT_TAA_BINDING_TILES, &tiles),
      storage_image_write(set, GLPT_TAA_BINDING_SURFACE, &images[1]),
  };
  pipeline_->update(device_.handle(), writes);
  const uint32_t resolve = GLPT_TAA_RESOLVE;
  pipeline_->dispatch(cmd, &resolve, sizeof resolve, width, height);
  if (write_back) {
    // The copy reads the history the resolve wrote, and writes pixels whose neighbourhoods the
    // resolve read.
    const VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                 VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT,
                                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &memory, 0, nullptr, 0,
                         nullptr);
    const uint32_t copy = GLPT_TAA_WRITE_BACK;
    pipeline_->dispatch(cmd, &copy, sizeof copy, width, height);
  }
  parity_ = previous;
  history_valid_ = true;
}

}  // namespace glpt::rt
