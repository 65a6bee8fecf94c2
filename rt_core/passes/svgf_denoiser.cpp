#include "rt_core/passes/svgf_denoiser.hpp"

#include <algorithm>

#include "shared_types.h"
#include "svgf_atrous_spv.h"    // generated from shaders/svgf_atrous.comp at build time
#include "svgf_temporal_spv.h"  // generated from shaders/svgf_temporal.comp

namespace glpt::rt {
namespace {

constexpr VkDescriptorSetLayoutBinding kBindings[] = {
    compute_binding(GLPT_DN_BINDING_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER),
    compute_binding(GLPT_DN_BINDING_STATES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_POSITION, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_SURFACE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_CHANNELS + 0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_CHANNELS + 1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_CHANNELS + 2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_GUIDE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_GUIDE_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_HISTORY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_HISTORY_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_WORK, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
};
static_assert(GLPT_CHANNELS == 3);

struct IterationConstants {
  uint32_t step, input_slot, output_slot, feedback;
};

}  // namespace

bool SvgfDenoiser::fits(uint32_t width, uint32_t height) const {
  const VkDeviceSize work = VkDeviceSize{width} * height * GLPT_DN_SLOTS * 3 * sizeof(gpu::vec4);
  // The device's own limit where it allows more than 2 GiB. Below that, bindings beyond
  // maxStorageBufferRange (lavapipe: 128 MiB) are kept as they were: they work up to 2 GiB.
  const VkDeviceSize limit = std::max<VkDeviceSize>(
      device_.properties().limits.maxStorageBufferRange, VkDeviceSize{0x7fffffff});
  return work <= limit;
}

bool SvgfDenoiser::prepare(uint32_t width, uint32_t height, const void* owner) {
  if (!temporal_) {
    temporal_ = std::make_unique<ComputePipeline>(device_, svgf_temporal_spv, kBindings);
    atrous_ = std::make_unique<ComputePipeline>(device_, svgf_atrous_spv, kBindings,
                                                static_cast<uint32_t>(sizeof(IterationConstants)));
  }
  const VkDeviceSize pixels = VkDeviceSize{width} * height;
  const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  if (width != width_ || height != height_ || !work_) {
    history_valid_ = false;
    width_ = height_ = 0;
    for (int i = 0; i < 2; ++i) {
      guides_[i] = GpuBuffer::create(
          device_, std::max<VkDeviceSize>(pixels, 1) * sizeof(gpu::DenoiseGuide), usage);
      histories_[i] = GpuBuffer::create(
          device_, std::max<VkDeviceSize>(pixels, 1) * sizeof(gpu::DenoiseHistory), usage);
    }
    work_ = GpuBuffer::create(
        device_, std::max<VkDeviceSize>(pixels, 1) * GLPT_DN_SLOTS * 3 * sizeof(gpu::vec4), usage);
    width_ = width;
    height_ = height;
  }
  if (owner != owner_) history_valid_ = false;
  owner_ = owner;
  return history_valid_;
}

void SvgfDenoiser::record(VkCommandBuffer cmd, const DenoiseResources& resources,
                          uint32_t iterations) {
  const uint32_t current = parity_, previous = parity_ ^ 1u;
  const VkDescriptorBufferInfo uniforms{resources.uniforms->handle(), 0,
                                        sizeof(gpu::DenoiseUniforms)};
  const VkDescriptorBufferInfo states{resources.states->handle(), 0, VK_WHOLE_SIZE};
  auto whole = [](const GpuBuffer& buffer) {
    return VkDescriptorBufferInfo{buffer.handle(), 0, VK_WHOLE_SIZE};
  };
  const VkDescriptorBufferInfo guide = whole(guides_[current]);
  const VkDescriptorBufferInfo previous_guide = whole(guides_[previous]);
  const VkDescriptorBufferInfo history = whole(histories_[current]);
  const VkDescriptorBufferInfo previous_history = whole(histories_[previous]);
  const VkDescriptorBufferInfo work = whole(work_);
  const VkDescriptorImageInfo images[5] = {
      general_image_info(resources.position), general_image_info(resources.surface),
      general_image_info(resources.channels[0]), general_image_info(resources.channels[1]),
      general_image_info(resources.channels[2])};
  for (const ComputePipeline* pipeline : {temporal_.get(), atrous_.get()}) {
    const VkDescriptorSet set = pipeline->descriptor_set();
    const VkWriteDescriptorSet writes[] = {
        uniform_buffer_write(set, GLPT_DN_BINDING_UNIFORMS, &uniforms),
        storage_buffer_write(set, GLPT_DN_BINDING_STATES, &states),
        storage_image_write(set, GLPT_DN_BINDING_POSITION, &images[0]),
        storage_image_write(set, GLPT_DN_BINDING_SURFACE, &images[1]),
        storage_image_write(set, GLPT_DN_BINDING_CHANNELS + 0, &images[2]),
        storage_image_write(set, GLPT_DN_BINDING_CHANNELS + 1, &images[3]),
        storage_image_write(set, GLPT_DN_BINDING_CHANNELS + 2, &images[4]),
        storage_buffer_write(set, GLPT_DN_BINDING_GUIDE, &guide),
        storage_buffer_write(set, GLPT_DN_BINDING_GUIDE_PREVIOUS, &previous_guide),
        storage_buffer_write(set, GLPT_DN_BINDING_HISTORY, &history),
        storage_buffer_write(set, GLPT_DN_BINDING_HISTORY_PREVIOUS, &previous_history),
        storage_buffer_write(set, GLPT_DN_BINDING_WORK, &work),
    };
    pipeline->update(device_.handle(), writes);
  }
  // Each pass reads what the one before wrote.
  auto barrier = [&] {
    const VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                 VK_ACCESS_SHADER_WRITE_BIT,
                                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &memory, 0, nullptr, 0,
                         nullptr);
  };
  temporal_->dispatch(cmd, nullptr, 0, width_, height_);
  for (uint32_t i = 0; i < iterations; ++i) {
    barrier();
    const IterationConstants constants{1u << i, i == 0 ? 0u : 1u + (i - 1) % 2, 1u + i % 2,
                                       i == 0 ? 1u : 0u};
    atrous_->dispatch(cmd, &constants, sizeof constants, width_, height_);
  }
  barrier();
  parity_ = previous;
  history_valid_ = true;
}

}  // namespace glpt::rt
