// GPU images of the record's textures, one per TextureObjectSnapshot::content_version (a texture
// whose content did not change is uploaded once), and samplers per GL sampler state. Entries not
// used for a while are dropped, and the least recently used ones beyond a memory budget.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "rt_core/raster/sampler_setup.hpp"
#include "rt_core/record/texture.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/gpu_image.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

class TextureCache {
 public:
  explicit TextureCache(VulkanDevice& device);

  // Makes sure every texture in `textures` has an image, uploading new ones with one submission.
  // The image holds the texture's levels base_level..last_level as its levels 0..n-1.
  // Returns the bytes of texels uploaded.
  size_t prepare(const std::vector<const rec::TextureObjectSnapshot*>& textures, uint64_t frame);
  // The image view of a prepared texture (null if it could not be made, e.g. zero size).
  VkImageView view(const rec::TextureObjectSnapshot& texture) const;
  // The sampler of `texture` on a unit with GL_TEXTURE_LOD_BIAS `unit_lod_bias`
  // (make_sampler_setup).
  VkSampler sampler(const rec::TextureObjectSnapshot& texture, float unit_lod_bias);
  // 1x1 white textures of each kind (1D, 2D, 3D, cube) for bindings nothing samples.
  VkImageView dummy_view(uint32_t kind) const { return dummies_[kind].view(); }
  VkSampler dummy_sampler() const { return dummy_sampler_.get(); }
  // Drops the images unused for many frames, then, while the images hold more than
  // kMemoryBudgetBytes, the least recently used ones that neither `frame` nor the execute before
  // it used (a frame presented later may still be drawing with those; a program that
  // makes a new texture at every frame or draw would otherwise fill the device's memory).
  void evict_unused(uint64_t frame);
  // Bytes of the texels of the cached images.
  size_t image_bytes() const;
  static constexpr size_t kMemoryBudgetBytes = size_t{512} << 20;

 private:
  struct Entry {
    GpuImage image;
    uint64_t last_used = 0;
    size_t bytes = 0;  // of its texels
  };
  struct SamplerKeyHash {
    size_t operator()(const SamplerSetup& key) const;
  };

  VulkanDevice& device_;
  std::unordered_map<uint64_t, Entry> entries_;
  std::unordered_map<SamplerSetup, vk::Sampler, SamplerKeyHash> samplers_;
  GpuImage dummies_[4];
  vk::Sampler dummy_sampler_;
  GpuBuffer staging_;
  std::vector<float> depth_scratch_;  // depth texels converted for upload
};

}  // namespace glpt::rt
