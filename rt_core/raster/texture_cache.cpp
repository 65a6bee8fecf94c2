#include "rt_core/raster/texture_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "common/content_hash.hpp"
#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

constexpr uint64_t kEvictAfterUnusedFrames = 120;

VkFormat format_of(rec::TexelFormat format) {
  switch (format) {
    case rec::TexelFormat::kRgba16:
      return VK_FORMAT_R16G16B16A16_UNORM;
    case rec::TexelFormat::kRgba32f:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
    case rec::TexelFormat::kDepth32f:
      return VK_FORMAT_R32_SFLOAT;
    default:
      return VK_FORMAT_R8G8B8A8_UNORM;
  }
}

}  // namespace

size_t TextureCache::SamplerKeyHash::operator()(const SamplerSetup& key) const {
  // Field by field: the struct has padding.
  ContentHash h;
  const uint32_t enums[] = {key.mag_filter, key.min_filter, key.mipmap_mode,
                            key.address[0], key.address[1], key.address[2]};
  h.add_bytes(enums, sizeof enums);
  const float values[] = {key.min_lod,  key.max_lod,  key.lod_bias, key.border.r,
                          key.border.g, key.border.b, key.border.a, key.max_anisotropy};
  h.add_bytes(values, sizeof values);
  return static_cast<size_t>(h.value());
}

TextureCache::TextureCache(VulkanDevice& device) : device_(device) {
  const GpuImageInfo kinds[4] = {
      {VK_IMAGE_TYPE_1D, VK_IMAGE_VIEW_TYPE_1D, VK_FORMAT_R8G8B8A8_UNORM, {1, 1, 1}, 1, 1},
      {VK_IMAGE_TYPE_2D, VK_IMAGE_VIEW_TYPE_2D, VK_FORMAT_R8G8B8A8_UNORM, {1, 1, 1}, 1, 1},
      {VK_IMAGE_TYPE_3D, VK_IMAGE_VIEW_TYPE_3D, VK_FORMAT_R8G8B8A8_UNORM, {1, 1, 1}, 1, 1},
      {VK_IMAGE_TYPE_2D, VK_IMAGE_VIEW_TYPE_CUBE, VK_FORMAT_R8G8B8A8_UNORM, {1, 1, 1}, 1, 6},
  };
  for (int i = 0; i < 4; ++i) dummies_[i] = GpuImage::create(device_, kinds[i]);
  device_.submit_and_wait([&](VkCommandBuffer cmd) {
    for (const GpuImage& image : dummies_) {
      image.initial_barrier(cmd);
      const VkClearColorValue white{{1.0f, 1.0f, 1.0f, 1.0f}};
      const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, image.info().layers};
      vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_GENERAL, &white, 1, &range);
    }
  });
  auto info = make_info<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  info.magFilter = info.minFilter = VK_FILTER_NEAREST;
  VkSampler sampler = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateSampler(device_.handle(), &info, nullptr, &sampler));
  dummy_sampler_ = vk::Sampler(sampler, {device_.handle()});
}

namespace {

// Depth texels as gallivm samples them (lp_build_unsigned_norm_to_float) from the unorm value z
// Mesa stores: float(z) times the float nearest 1 / (2^n - 1) for its 16- and 24-bit formats;
// the top 23 bits of a 32-bit z as a mantissa, scaled by 2^23 / (2^23 - 1). The record holds
// z / (2^n - 1) (the value glGetTexImage returns), from which z is exact for up to 24 bits.
void depth_samples(const rec::TextureImage& image, std::vector<float>& out) {
  const uint32_t bits = image.internal_format == GL_DEPTH_COMPONENT16   ? 16
                        : image.internal_format == GL_DEPTH_COMPONENT32 ? 32
                                                                        : 24;
  const double max = bits == 32 ? 4294967295.0 : double((1u << bits) - 1);
  out.resize(image.texels.size() / 4);
  for (size_t i = 0; i < out.size(); ++i) {
    float stored;
    std::memcpy(&stored, image.texels.data() + i * 4, 4);
    const uint32_t z = static_cast<uint32_t>(std::min(std::nearbyint(double(stored) * max), max));
    if (bits <= 24) {
      out[i] = static_cast<float>(z) * static_cast<float>(1.0 / max);
    } else {
      const uint32_t mantissa_bits = (z >> 9) | 0x3F800000u;
      float m;
      std::memcpy(&m, &mantissa_bits, 4);
      out[i] = (m - 1.0f) * static_cast<float>(8388608.0 / 8388607.0);
    }
  }
}

int32_t base_level_of(const rec::TextureObjectSnapshot& t) {
  return std::clamp(t.sampler.base_level, 0, std::max(t.last_level, 0));
}

}  // namespace

size_t TextureCache::prepare(const std::vector<const rec::TextureObjectSnapshot*>& textures,
                             uint64_t frame) {
  struct Upload {
    const rec::TextureObjectSnapshot* texture;
    GpuImage* image;
  };
  std::vector<Upload> uploads;
  size_t staging_bytes = 0;
  for (const rec::TextureObjectSnapshot* t : textures) {
    auto it = entries_.find(t->content_version);
    if (it != entries_.end()) {
      it->second.last_used = frame;
      continue;
    }
    const int32_t base_level = base_level_of(*t);
    if (t->faces.empty() || t->faces[0].size() <= static_cast<size_t>(base_level) ||
        !t->faces[0][base_level])
      continue;
    const rec::TextureImage& base = *t->faces[0][base_level];
    if (base.width == 0 || base.height == 0 || base.depth == 0) continue;
    GpuImageInfo info;
    const bool cube = t->target == GL_TEXTURE_CUBE_MAP;
    info.type = t->target == GL_TEXTURE_1D   ? VK_IMAGE_TYPE_1D
                : t->target == GL_TEXTURE_3D ? VK_IMAGE_TYPE_3D
                                             : VK_IMAGE_TYPE_2D;
    info.view_type = t->target == GL_TEXTURE_1D   ? VK_IMAGE_VIEW_TYPE_1D
                     : t->target == GL_TEXTURE_3D ? VK_IMAGE_VIEW_TYPE_3D
                     : cube                       ? VK_IMAGE_VIEW_TYPE_CUBE
                                                  : VK_IMAGE_VIEW_TYPE_2D;
    info.format = format_of(t->texel_format);
    info.extent = {base.width, base.height, base.depth};
    info.mip_levels = static_cast<uint32_t>(std::max(t->last_level - base_level + 1, 1));
    info.layers = cube ? 6 : 1;
    Entry& entry = entries_[t->content_version];
    entry.image = GpuImage::create(device_, info);
    entry.last_used = frame;
    uploads.push_back({t, &entry.image});
    entry.bytes = 0;
    for (const auto& face : t->faces)
      for (const auto& level : face)
        if (level) {
          entry.bytes += level->texels.size();
          staging_bytes += (level->texels.size() + 15) & ~size_t{15};
        }
  }
  if (uploads.empty()) return 0;
  ensure_capacity(device_, staging_, staging_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::vector<VkBufferImageCopy> copies;
  size_t offset = 0;
  device_.submit_and_wait([&](VkCommandBuffer cmd) {
    for (const Upload& u : uploads) {
      const int32_t base_level = base_level_of(*u.texture);
      u.image->initial_barrier(cmd);
      copies.clear();
      const uint32_t levels = u.image->info().mip_levels;
      for (size_t f = 0; f < u.texture->faces.size() && f < u.image->info().layers; ++f) {
        const auto& face = u.texture->faces[f];
        for (uint32_t l = 0; l < levels && base_level + l < face.size(); ++l) {
          const rec::TextureImage* img = face[base_level + l].get();
          if (img == nullptr || img->texels.empty()) continue;
          if (u.texture->texel_format == rec::TexelFormat::kDepth32f) {
            depth_samples(*img, depth_scratch_);
            staging_.write(depth_scratch_.data(), depth_scratch_.size() * 4, offset);
          } else {
            staging_.write(img->texels.data(), img->texels.size(), offset);
          }
          VkBufferImageCopy copy{};
          copy.bufferOffset = offset;
          copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, static_cast<uint32_t>(f), 1};
          copy.imageExtent = {img->width, img->height, img->depth};
          copies.push_back(copy);
          offset += (img->texels.size() + 15) & ~size_t{15};
        }
      }
      if (!copies.empty())
        vkCmdCopyBufferToImage(cmd, staging_.handle(), u.image->handle(), VK_IMAGE_LAYOUT_GENERAL,
                               static_cast<uint32_t>(copies.size()), copies.data());
    }
  });
  return staging_bytes;
}

VkImageView TextureCache::view(const rec::TextureObjectSnapshot& texture) const {
  auto it = entries_.find(texture.content_version);
  return it == entries_.end() ? VK_NULL_HANDLE : it->second.image.view();
}

VkSampler TextureCache::sampler(const rec::TextureObjectSnapshot& texture, float unit_lod_bias) {
  SamplerSetup key = make_sampler_setup(texture, unit_lod_bias);
  key.shader = {};  // the shader's part does not make a different sampler
  // Nor does anisotropy: raster_ff.frag filters anisotropic units itself from texel fetches,
  // and gallivm samples explicit lods (the path tracer's) isotropically.
  key.max_anisotropy = 0.0f;
  auto it = samplers_.find(key);
  if (it != samplers_.end()) return it->second.get();
  auto border = make_info<VkSamplerCustomBorderColorCreateInfoEXT>(
      VK_STRUCTURE_TYPE_SAMPLER_CUSTOM_BORDER_COLOR_CREATE_INFO_EXT);
  std::memcpy(border.customBorderColor.float32, &key.border, sizeof(float) * 4);
  border.format = VK_FORMAT_UNDEFINED;
  auto info = make_info<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO, &border);
  info.magFilter = key.mag_filter;
  info.minFilter = key.min_filter;
  info.mipmapMode = key.mipmap_mode;
  info.addressModeU = key.address[0];
  info.addressModeV = key.address[1];
  info.addressModeW = key.address[2];
  info.mipLodBias = key.lod_bias;
  info.minLod = key.min_lod;
  info.maxLod = key.max_lod;
  info.borderColor = VK_BORDER_COLOR_FLOAT_CUSTOM_EXT;
  VkSampler sampler = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateSampler(device_.handle(), &info, nullptr, &sampler));
  return samplers_.emplace(key, vk::Sampler(sampler, {device_.handle()})).first->second.get();
}

void TextureCache::evict_unused(uint64_t frame) {
  std::erase_if(entries_, [&](const auto& kv) {
    return frame > kv.second.last_used + kEvictAfterUnusedFrames;
  });
  size_t bytes = image_bytes();
  if (bytes <= kMemoryBudgetBytes) return;
  std::vector<std::pair<uint64_t, uint64_t>> by_age;  // (last used, content version)
  for (const auto& [version, entry] : entries_)
    // Not those of this execute or the one before: a frame presented later may still sample
    // the previous execute's (FrameEnd::present_later).
    if (entry.last_used + 1 < frame) by_age.emplace_back(entry.last_used, version);
  std::sort(by_age.begin(), by_age.end());
  for (const auto& [last_used, version] : by_age) {
    if (bytes <= kMemoryBudgetBytes) break;
    auto it = entries_.find(version);
    bytes -= it->second.bytes;
    entries_.erase(it);
  }
}

size_t TextureCache::image_bytes() const {
  size_t bytes = 0;
  for (const auto& kv : entries_) bytes += kv.second.bytes;
  return bytes;
}

}  // namespace glpt::rt
