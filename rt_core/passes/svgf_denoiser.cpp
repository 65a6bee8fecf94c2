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
    compute_binding(GLPT_DN_BINDING_SCENE, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR),
    compute_binding(GLPT_DN_BINDING_INSTANCES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_TILES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
};

// The work slots and the two colour histories' (shared_types.h, the work slots).
constexpr uint32_t kWorkLayers = (GLPT_DN_SLOTS + GLPT_DN_HISTORY_SLOTS) * GLPT_DN_WORK_LAYERS;
constexpr VkDeviceSize kTexelBytes = 16;  // a layer's texel per pixel (uvec4, vec4)
static_assert(sizeof(gpu::DenoiseGuide) == 2 * kTexelBytes);

struct IterationConstants {
  uint32_t step, input_slot, output_slot, also_output;
};

}  // namespace
static_assert(GLPT_CHANNELS == 3);  // the passes filter three channels

bool SvgfDenoiser::fits(uint32_t width, uint32_t height) const {
  // The largest buffer, the work slots, within 2 GiB (one allocation; the shaders' 32-bit texel
  // indices reach 64 GiB).
  const VkDeviceSize work = VkDeviceSize{width} * height * kWorkLayers * kTexelBytes;
  return work <= VkDeviceSize{0x7fffffff};
}

void SvgfDenoiser::write_addresses(gpu::DenoiseUniforms& uniforms) const {
  const uint32_t current = parity_, previous = parity_ ^ 1u;
  auto pair = [](glm::uvec2 a, glm::uvec2 b) { return glm::uvec4(a, b); };
  uniforms.guides = pair(guides_[current].address_words(), guides_[previous].address_words());
  uniforms.histories =
      pair(histories_[current].address_words(), histories_[previous].address_words());
  uniforms.moments = pair(moments_[current].address_words(), moments_[previous].address_words());
  uniforms.buffers = pair(work_.address_words(), motion_.address_words());
}

glm::uvec2 SvgfDenoiser::motion_address() const { return motion_.address_words(); }

bool SvgfDenoiser::prepare(uint32_t width, uint32_t height, const void* owner) {
  if (!temporal_) {
    constexpr VkExtent2D tile{GLPT_IMAGE_TILE_WIDTH, GLPT_IMAGE_TILE_HEIGHT};
    temporal_ = std::make_unique<ComputePipeline>(device_, svgf_temporal_spv, kBindings, 0, tile);
    atrous_ =
        std::make_unique<ComputePipeline>(device_, svgf_atrous_spv, kBindings,
                                          static_cast<uint32_t>(sizeof(IterationConstants)), tile);
  }
  if (width != width_ || height != height_ || !work_) {
    history_valid_ = false;
    width_ = height_ = 0;
    const VkDeviceSize pixels = VkDeviceSize{std::max(width, 1u)} * std::max(height, 1u);
    auto buffer = [&](VkDeviceSize layers) {
      return GpuBuffer::create(
          device_, pixels * layers * kTexelBytes,
          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    };
    for (int i = 0; i < 2; ++i) {
      guides_[i] = buffer(2);  // cleared once (record_before_trace)
      histories_[i] = buffer(GLPT_DN_HISTORY_LAYERS);
      moments_[i] = buffer(GLPT_DN_MOMENT_LAYERS);
    }
    work_ = buffer(kWorkLayers);
    motion_ = buffer(1);  // cleared once (record_before_trace): stamp 0 is no frame's
    // The tile list (GLPT_DN_BINDING_TILES): a header, a flag and a list entry per tile.
    const VkDeviceSize tiles =
        VkDeviceSize{(std::max(width, 1u) + GLPT_IMAGE_TILE_WIDTH - 1) / GLPT_IMAGE_TILE_WIDTH} *
        ((std::max(height, 1u) + GLPT_IMAGE_TILE_HEIGHT - 1) / GLPT_IMAGE_TILE_HEIGHT);
    tiles_ =
        GpuBuffer::create(device_, (GLPT_DN_TILES_HEADER + 2 * tiles) * sizeof(uint32_t),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    tile_count_ = tiles;
    buffers_need_clear_ = true;
    width_ = width;
    height_ = height;
  }
  if (owner != owner_) history_valid_ = false;
  owner_ = owner;
  return history_valid_;
}

void SvgfDenoiser::record_before_trace(VkCommandBuffer cmd) {
  if (buffers_need_clear_) {
    // The passes read guides of tiles they skip: a new buffer's must say "no surface" (id 0,
    // stamp 0), and a new motion buffer no frame's stamp.
    for (const GpuBuffer& guides : guides_)
      vkCmdFillBuffer(cmd, guides.handle(), 0, VK_WHOLE_SIZE, 0u);
    vkCmdFillBuffer(cmd, motion_.handle(), 0, VK_WHOLE_SIZE, 0u);
    buffers_need_clear_ = false;
  }
  // An empty tile list: no tile, a dispatch of (0, 1, 1), no tile flagged.
  const uint32_t header[GLPT_DN_TILES_HEADER] = {0u, 1u, 1u, 0u};
  vkCmdUpdateBuffer(cmd, tiles_.handle(), 0, sizeof header, header);
  vkCmdFillBuffer(cmd, tiles_.handle(), sizeof header, tile_count_ * sizeof(uint32_t), 0u);
  const VkMemoryBarrier cleared{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                VK_ACCESS_TRANSFER_WRITE_BIT,
                                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                       1, &cleared, 0, nullptr, 0, nullptr);
}

void SvgfDenoiser::record(VkCommandBuffer cmd, const DenoiseResources& resources,
                          uint32_t iterations, bool specular) {
  const uint32_t previous = parity_ ^ 1u;
  const VkDescriptorBufferInfo uniforms{resources.uniforms->handle(), 0,
                                        sizeof(gpu::DenoiseUniforms)};
  const VkDescriptorBufferInfo states{resources.states->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo instances{resources.instances->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo tiles{tiles_.handle(), 0, VK_WHOLE_SIZE};
  const auto scene_info = acceleration_structure_info(&resources.scene);
  const VkDescriptorImageInfo images[2] = {general_image_info(resources.position),
                                           general_image_info(resources.surface)};
  for (const ComputePipeline* pipeline : {temporal_.get(), atrous_.get()}) {
    const VkDescriptorSet set = pipeline->descriptor_set();
    const VkWriteDescriptorSet writes[] = {
        uniform_buffer_write(set, GLPT_DN_BINDING_UNIFORMS, &uniforms),
        storage_buffer_write(set, GLPT_DN_BINDING_STATES, &states),
        storage_image_write(set, GLPT_DN_BINDING_POSITION, &images[0]),
        storage_image_write(set, GLPT_DN_BINDING_SURFACE, &images[1]),
        storage_buffer_write(set, GLPT_DN_BINDING_TILES, &tiles),
        storage_buffer_write(set, GLPT_DN_BINDING_INSTANCES, &instances),
        acceleration_structure_write(set, GLPT_DN_BINDING_SCENE, &scene_info),
    };
    pipeline->update(device_.handle(), writes);
  }
  // Each pass reads what the one before wrote (the a-trous dispatches' sizes too).
  auto barrier = [&] {
    const VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                 VK_ACCESS_SHADER_WRITE_BIT,
                                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                                     VK_ACCESS_INDIRECT_COMMAND_READ_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                         0, 1, &memory, 0, nullptr, 0, nullptr);
  };
  // The trace pass listed the tiles (record_before_trace, GLPT_OPTION_DENOISE_TILES).
  barrier();
  temporal_->dispatch_indirect(cmd, nullptr, 0, tiles_.handle(), 0);
  for (uint32_t i = 0; i < iterations; ++i) {
    barrier();
    // The first iteration's result is the colour history (the paper's feedback) and the
    // second iteration's input; a work slot gets it as well only where it is the last.
    const uint32_t input = i == 0 ? 0u : i == 1 ? history_slot() : 1u + (i - 1) % 2;
    const uint32_t output = i == 0 ? history_slot() : 1u + i % 2;
    const uint32_t also = i == 0 && iterations == 1 ? 1u : GLPT_DN_SLOT_NONE;
    const IterationConstants constants{1u << i, input, output, also};
    atrous_->dispatch_indirect(cmd, &constants, sizeof constants, tiles_.handle(), 0);
  }
  barrier();
  parity_ = previous;
  previous_stamp_ = stamp_;
  stamp_ = stamp_ % 0xFFFFFFu + 1u;  // 1 .. 2^24 - 1
  history_valid_ = true;
  history_has_specular_ = specular;
}

}  // namespace glpt::rt
