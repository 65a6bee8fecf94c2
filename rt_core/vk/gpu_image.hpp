// A VkImage with its own memory and one view, kept in VK_IMAGE_LAYOUT_GENERAL for its whole life:
// on lavapipe layouts are free, and GENERAL is valid for every use glpt makes (attachment,
// sampling, transfer), so no layout tracking is needed anywhere.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <utility>

#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

struct GpuImageInfo {
  VkImageType type = VK_IMAGE_TYPE_2D;
  VkImageViewType view_type = VK_IMAGE_VIEW_TYPE_2D;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkExtent3D extent{1, 1, 1};
  uint32_t mip_levels = 1;
  uint32_t layers = 1;  // 6 for cube maps
  VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  VkComponentMapping swizzle{};  // identity
  // Linear tiling in host-visible, coherent memory, mapped for the image's life (2D, one level,
  // one layer): the host reads its pixels in place (GpuImage::pixels). Only where the device
  // supports the format and usage so (linear_supported).
  bool host_readable = false;
};

class GpuImage {
 public:
  GpuImage() = default;
  GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }
  GpuImage& operator=(GpuImage&& other) noexcept {
    if (this != &other) {
      view_ = std::move(other.view_);
      image_ = std::move(other.image_);
      memory_ = std::move(other.memory_);
      info_ = other.info_;
      pixels_ = std::exchange(other.pixels_, nullptr);
      row_pitch_ = std::exchange(other.row_pitch_, 0);
    }
    return *this;
  }
  // Creates the image and its view; the caller transitions it to GENERAL (initial_barrier).
  // Throws VulkanError.
  static GpuImage create(const VulkanDevice& device, const GpuImageInfo& info);

  // Whether the device makes 2D images of `format` with `usage` in linear tiling.
  static bool linear_supported(const VulkanDevice& device, VkFormat format,
                               VkImageUsageFlags usage);

  VkImage handle() const { return image_.get(); }
  // A host_readable image's pixels (rows pixel_row_pitch() bytes apart); null otherwise.
  const uint8_t* pixels() const { return pixels_; }
  size_t pixel_row_pitch() const { return row_pitch_; }
  VkImageView view() const { return view_.get(); }
  const GpuImageInfo& info() const { return info_; }
  explicit operator bool() const { return static_cast<bool>(image_); }

  // UNDEFINED -> GENERAL for every subresource; record once after creation.
  void initial_barrier(VkCommandBuffer cmd) const;

 private:
  // Destroyed in reverse order: view, image, memory.
  vk::DeviceMemory memory_;
  vk::Image image_;
  vk::ImageView view_;
  GpuImageInfo info_;
  const uint8_t* pixels_ = nullptr;  // mapped (host_readable): unmapped when memory_ is freed
  size_t row_pitch_ = 0;
};

}  // namespace glpt::rt
