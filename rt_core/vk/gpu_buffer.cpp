#include "rt_core/vk/gpu_buffer.hpp"

#include <algorithm>

#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {

GpuBuffer GpuBuffer::create(const VulkanDevice& device, VkDeviceSize size,
                            VkBufferUsageFlags usage) {
  GpuBuffer result;
  // Zero-sized buffers are invalid; tiny ones keep every binding valid for empty scenes.
  result.size_ = std::max<VkDeviceSize>(size, 16);

  auto buffer_info = make_info<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  buffer_info.size = result.size_;
  buffer_info.usage = usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  buffer_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateBuffer(device.handle(), &buffer_info, nullptr, &buffer));
  result.buffer_ = vk::Buffer(buffer, {device.handle()});

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device.handle(), buffer, &requirements);
  // Device addresses need this flag on the allocation as well as the usage bit on the buffer.
  auto flags_info =
      make_info<VkMemoryAllocateFlagsInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO);
  flags_info.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  auto allocate_info =
      make_info<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, &flags_info);
  allocate_info.allocationSize = requirements.size;
  allocate_info.memoryTypeIndex =
      device.memory_type(requirements.memoryTypeBits,
                         VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                         VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkAllocateMemory(device.handle(), &allocate_info, nullptr, &memory));
  result.memory_ = vk::DeviceMemory(memory, {device.handle()});
  GLPT_VK_CHECK(vkBindBufferMemory(device.handle(), buffer, memory, 0));
  GLPT_VK_CHECK(vkMapMemory(device.handle(), memory, 0, VK_WHOLE_SIZE, 0, &result.mapped_));

  auto address_info =
      make_info<VkBufferDeviceAddressInfo>(VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO);
  address_info.buffer = buffer;
  result.address_ = vkGetBufferDeviceAddress(device.handle(), &address_info);
  return result;
}

bool ensure_capacity(const VulkanDevice& device, GpuBuffer& buffer, VkDeviceSize size,
                     VkBufferUsageFlags usage) {
  if (buffer && buffer.size() >= size) return false;
  buffer = GpuBuffer();  // free the old allocation before making the new one
  buffer = GpuBuffer::create(device, size + size / 2, usage);
  return true;
}

}  // namespace glpt::rt
