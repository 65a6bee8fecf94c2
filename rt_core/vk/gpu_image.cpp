#include "rt_core/vk/gpu_image.hpp"

#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {

GpuImage GpuImage::create(const VulkanDevice& device, const GpuImageInfo& info) {
  GpuImage result;
  result.info_ = info;
  auto image_info = make_info<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  image_info.flags =
      info.view_type == VK_IMAGE_VIEW_TYPE_CUBE ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  image_info.imageType = info.type;
  image_info.format = info.format;
  image_info.extent = info.extent;
  image_info.mipLevels = info.mip_levels;
  image_info.arrayLayers = info.layers;
  image_info.samples = VK_SAMPLE_COUNT_1_BIT;
  image_info.tiling = info.host_readable ? VK_IMAGE_TILING_LINEAR : VK_IMAGE_TILING_OPTIMAL;
  image_info.usage = info.usage;
  image_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  image_info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateImage(device.handle(), &image_info, nullptr, &image));
  result.image_ = vk::Image(image, {device.handle()});

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device.handle(), image, &requirements);
  auto allocate_info = make_info<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  allocate_info.allocationSize = requirements.size;
  allocate_info.memoryTypeIndex =
      info.host_readable
          ? device.memory_type(
                requirements.memoryTypeBits,
                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                VK_MEMORY_PROPERTY_HOST_CACHED_BIT)
          : device.memory_type(requirements.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkAllocateMemory(device.handle(), &allocate_info, nullptr, &memory));
  result.memory_ = vk::DeviceMemory(memory, {device.handle()});
  GLPT_VK_CHECK(vkBindImageMemory(device.handle(), image, memory, 0));
  if (info.host_readable) {
    const VkImageSubresource subresource{info.aspect, 0, 0};
    VkSubresourceLayout layout{};
    vkGetImageSubresourceLayout(device.handle(), image, &subresource, &layout);
    void* mapped = nullptr;
    GLPT_VK_CHECK(vkMapMemory(device.handle(), memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    result.pixels_ = static_cast<const uint8_t*>(mapped) + layout.offset;
    result.row_pitch_ = static_cast<size_t>(layout.rowPitch);
  }

  auto view_info = make_info<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view_info.image = image;
  view_info.viewType = info.view_type;
  view_info.format = info.format;
  view_info.components = info.swizzle;
  view_info.subresourceRange = {info.aspect, 0, info.mip_levels, 0, info.layers};
  VkImageView view = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateImageView(device.handle(), &view_info, nullptr, &view));
  result.view_ = vk::ImageView(view, {device.handle()});
  return result;
}

bool GpuImage::linear_supported(const VulkanDevice& device, VkFormat format,
                                VkImageUsageFlags usage) {
  VkImageFormatProperties properties{};
  return vkGetPhysicalDeviceImageFormatProperties(device.physical_device(), format,
                                                  VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_LINEAR, usage,
                                                  0, &properties) == VK_SUCCESS;
}

void GpuImage::initial_barrier(VkCommandBuffer cmd) const {
  auto barrier = make_info<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
  barrier.srcAccessMask = 0;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = handle();
  barrier.subresourceRange = {info_.aspect, 0, info_.mip_levels, 0, info_.layers};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace glpt::rt
