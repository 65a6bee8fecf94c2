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
    compute_binding(GLPT_DN_BINDING_GUIDE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_GUIDE_META, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_GUIDE_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_GUIDE_META_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_HISTORY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_HISTORY_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_WORK, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_SCENE, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR),
    compute_binding(GLPT_DN_BINDING_INSTANCES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_MOMENTS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_MOMENTS_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
    compute_binding(GLPT_DN_BINDING_TILES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
    compute_binding(GLPT_DN_BINDING_MOTION, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE),
};
static_assert(GLPT_CHANNELS == 3);

// The work slots and the two colour histories' (shared_types.h, GLPT_DN_BINDING_WORK).
constexpr uint32_t kWorkLayers = (GLPT_DN_SLOTS + GLPT_DN_HISTORY_SLOTS) * GLPT_DN_WORK_LAYERS;

struct IterationConstants {
  uint32_t step, input_slot, output_slot, also_output;
};

}  // namespace

bool SvgfDenoiser::fits(uint32_t width, uint32_t height) const {
  // The largest image, the work slots, within 2 GiB (lavapipe addresses an image with 32-bit
  // offsets) and the device's image limits.
  const VkPhysicalDeviceLimits& limits = device_.properties().limits;
  const VkDeviceSize work = VkDeviceSize{width} * height * kWorkLayers * sizeof(gpu::uvec4);
  return work <= VkDeviceSize{0x7fffffff} && width <= limits.maxImageDimension2D &&
         height <= limits.maxImageDimension2D && kWorkLayers <= limits.maxImageArrayLayers;
}

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
    auto image = [&](VkFormat format, uint32_t layers,
                     VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT) {
      GpuImageInfo info;
      info.format = format;
      info.extent = {std::max(width, 1u), std::max(height, 1u), 1};
      info.usage = usage;
      info.view_type = layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
      info.layers = layers;
      return GpuImage::create(device_, info);
    };
    for (int i = 0; i < 2; ++i) {
      guide_eyes_[i] = image(VK_FORMAT_R32G32B32A32_SFLOAT, 1);
      // Cleared once (record_before_trace).
      guide_metas_[i] = image(VK_FORMAT_R32G32B32A32_UINT, 1,
                              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
      histories_[i] = image(VK_FORMAT_R32G32B32A32_UINT, GLPT_DN_HISTORY_LAYERS);
      moments_[i] = image(VK_FORMAT_R32G32B32A32_SFLOAT, GLPT_DN_MOMENT_LAYERS);
    }
    work_ = image(VK_FORMAT_R32G32B32A32_UINT, kWorkLayers);
    // Cleared once (record_before_trace): stamp 0 is no frame's.
    motion_ = image(VK_FORMAT_R32G32B32A32_UINT, 1,
                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    // The tile list (GLPT_DN_BINDING_TILES): a header, a flag and a list entry per tile.
    const VkDeviceSize tiles =
        VkDeviceSize{(std::max(width, 1u) + GLPT_IMAGE_TILE_WIDTH - 1) / GLPT_IMAGE_TILE_WIDTH} *
        ((std::max(height, 1u) + GLPT_IMAGE_TILE_HEIGHT - 1) / GLPT_IMAGE_TILE_HEIGHT);
    tiles_ =
        GpuBuffer::create(device_, (GLPT_DN_TILES_HEADER + 2 * tiles) * sizeof(uint32_t),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    tile_count_ = tiles;
    images_need_layout_ = true;  // to GENERAL in the next record()
    width_ = width;
    height_ = height;
  }
  if (owner != owner_) history_valid_ = false;
  owner_ = owner;
  return history_valid_;
}

void SvgfDenoiser::record_before_trace(VkCommandBuffer cmd) {
  if (images_need_layout_) {
    for (int i = 0; i < 2; ++i) {
      guide_eyes_[i].initial_barrier(cmd);
      guide_metas_[i].initial_barrier(cmd);
      histories_[i].initial_barrier(cmd);
      moments_[i].initial_barrier(cmd);
    }
    work_.initial_barrier(cmd);
    motion_.initial_barrier(cmd);
    // The passes read guides of tiles they skip: a new image's must say "no surface" (stamp 0).
    const VkClearColorValue zero{};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    for (const GpuImage& metas : guide_metas_)
      vkCmdClearColorImage(cmd, metas.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    vkCmdClearColorImage(cmd, motion_.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    images_need_layout_ = false;
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
  const uint32_t current = parity_, previous = parity_ ^ 1u;
  const VkDescriptorBufferInfo uniforms{resources.uniforms->handle(), 0,
                                        sizeof(gpu::DenoiseUniforms)};
  const VkDescriptorBufferInfo states{resources.states->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo instances{resources.instances->handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo tiles{tiles_.handle(), 0, VK_WHOLE_SIZE};
  const auto scene_info = acceleration_structure_info(&resources.scene);
  const VkDescriptorImageInfo images[15] = {general_image_info(resources.position),
                                            general_image_info(resources.surface),
                                            general_image_info(resources.channels[0]),
                                            general_image_info(resources.channels[1]),
                                            general_image_info(resources.channels[2]),
                                            general_image_info(guide_eyes_[current].view()),
                                            general_image_info(guide_metas_[current].view()),
                                            general_image_info(guide_eyes_[previous].view()),
                                            general_image_info(guide_metas_[previous].view()),
                                            general_image_info(histories_[current].view()),
                                            general_image_info(histories_[previous].view()),
                                            general_image_info(work_.view()),
                                            general_image_info(moments_[current].view()),
                                            general_image_info(moments_[previous].view()),
                                            general_image_info(motion_.view())};
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
        storage_image_write(set, GLPT_DN_BINDING_GUIDE, &images[5]),
        storage_image_write(set, GLPT_DN_BINDING_GUIDE_META, &images[6]),
        storage_image_write(set, GLPT_DN_BINDING_GUIDE_PREVIOUS, &images[7]),
        storage_image_write(set, GLPT_DN_BINDING_GUIDE_META_PREVIOUS, &images[8]),
        storage_image_write(set, GLPT_DN_BINDING_HISTORY, &images[9]),
        storage_image_write(set, GLPT_DN_BINDING_HISTORY_PREVIOUS, &images[10]),
        storage_image_write(set, GLPT_DN_BINDING_WORK, &images[11]),
        storage_image_write(set, GLPT_DN_BINDING_MOMENTS, &images[12]),
        storage_image_write(set, GLPT_DN_BINDING_MOMENTS_PREVIOUS, &images[13]),
        storage_buffer_write(set, GLPT_DN_BINDING_TILES, &tiles),
        storage_image_write(set, GLPT_DN_BINDING_MOTION, &images[14]),
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
