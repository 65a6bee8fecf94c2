#include "rt_core/passes/temporal_aa_pass.hpp"

#include <algorithm>

#include "shared_types.h"
#include "temporal_aa_spv.h"  // generated from shaders/temporal_aa.comp at build time

namespace glpt::rt {
namespace {

constexpr VkDescriptorSetLayoutBinding kBindings[] = {
    compute_binding(GLPT_TAA_BINDING_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
    compute_binding(GLPT_TAA_BINDING_COLOUR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_TAA_BINDING_HISTORY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_TAA_BINDING_HISTORY_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_TAA_BINDING_MOTION, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_TAA_BINDING_TILES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_TAA_BINDING_SURFACE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
};

}  // namespace

bool TemporalAaPass::prepare(uint32_t width, uint32_t height, const void* owner) {
  if (!pipeline_)
    pipeline_ = std::make_unique<ComputePipeline>(
        device_, temporal_aa_spv, kBindings, static_cast<uint32_t>(sizeof(uint32_t)),
        VkExtent2D{GLPT_IMAGE_TILE_WIDTH, GLPT_IMAGE_TILE_HEIGHT});
  if (width != width_ || height != height_ || !histories_[0]) {
    history_valid_ = false;
    width_ = height_ = 0;
    GpuImageInfo info;
    info.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    info.extent = {std::max(width, 1u), std::max(height, 1u), 1};
    info.usage = VK_IMAGE_USAGE_STORAGE_BIT;
    for (GpuImage& image : histories_) image = GpuImage::create(device_, info);
    images_need_layout_ = true;
    width_ = width;
    height_ = height;
  }
  if (owner != owner_) history_valid_ = false;
  owner_ = owner;
  return history_valid_;
}

void TemporalAaPass::record(VkCommandBuffer cmd, const TemporalAaResources& resources,
                            uint32_t width, uint32_t height, bool write_back) {
  if (images_need_layout_) {
    for (GpuImage& image : histories_) image.initial_barrier(cmd);
    images_need_layout_ = false;
  }
  const uint32_t current = parity_, previous = parity_ ^ 1u;
  const VkDescriptorBufferInfo uniforms{resources.uniforms->handle(), 0,
                                        sizeof(gpu::TemporalAaUniforms)};
  const VkDescriptorImageInfo images[5] = {
      general_image_info(resources.colour), general_image_info(histories_[current].view()),
      general_image_info(histories_[previous].view()), general_image_info(resources.motion),
      general_image_info(resources.surface)};
  const VkDescriptorBufferInfo tiles{resources.tiles->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorSet set = pipeline_->descriptor_set();
  const VkWriteDescriptorSet writes[] = {
      uniform_buffer_write(set, GLPT_TAA_BINDING_UNIFORMS, &uniforms),
      storage_image_write(set, GLPT_TAA_BINDING_COLOUR, &images[0]),
      storage_image_write(set, GLPT_TAA_BINDING_HISTORY, &images[1]),
      storage_image_write(set, GLPT_TAA_BINDING_HISTORY_PREVIOUS, &images[2]),
      storage_image_write(set, GLPT_TAA_BINDING_MOTION, &images[3]),
      storage_buffer_write(set, GLPT_TAA_BINDING_TILES, &tiles),
      storage_image_write(set, GLPT_TAA_BINDING_SURFACE, &images[4]),
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
