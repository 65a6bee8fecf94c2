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

GpuBuffer GpuBuffer::import_host(const VulkanDevice& device, void* pointer, VkDeviceSize size,
                                 VkBufferUsageFlags usage) {
  GpuBuffer result;
  const VkDeviceSize alignment = device.host_pointer_alignment();
  if (!device.has_external_host_memory() || pointer == nullptr || size == 0 ||
      reinterpret_cast<uintptr_t>(pointer) % alignment != 0 || size % alignment != 0)
    return result;
  auto get_properties = reinterpret_cast<PFN_vkGetMemoryHostPointerPropertiesEXT>(
      vkGetDeviceProcAddr(device.handle(), "vkGetMemoryHostPointerPropertiesEXT"));
  auto host_properties = make_info<VkMemoryHostPointerPropertiesEXT>(
      VK_STRUCTURE_TYPE_MEMORY_HOST_POINTER_PROPERTIES_EXT);
  if (get_properties == nullptr ||
      get_properties(device.handle(), VK_EXTERNAL_MEMORY_HANDLE_TYPE_HOST_ALLOCATION_BIT_EXT,
                     pointer, &host_properties) != VK_SUCCESS)
    return result;

  auto external = make_info<VkExternalMemoryBufferCreateInfo>(
      VK_STRUCTURE_TYPE_EXTERNAL_MEMORY_BUFFER_CREATE_INFO);
  external.handleTypes = VK_EXTERNAL_MEMORY_HANDLE_TYPE_HOST_ALLOCATION_BIT_EXT;
  auto buffer_info = make_info<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, &external);
  buffer_info.size = size;
  buffer_info.usage = usage;
  buffer_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateBuffer(device.handle(), &buffer_info, nullptr, &buffer));
  result.buffer_ = vk::Buffer(buffer, {device.handle()});
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device.handle(), buffer, &requirements);

  auto import = make_info<VkImportMemoryHostPointerInfoEXT>(
      VK_STRUCTURE_TYPE_IMPORT_MEMORY_HOST_POINTER_INFO_EXT);
  import.handleType = VK_EXTERNAL_MEMORY_HANDLE_TYPE_HOST_ALLOCATION_BIT_EXT;
  import.pHostPointer = pointer;
  auto allocate_info =
      make_info<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, &import);
  allocate_info.allocationSize = size;
  allocate_info.memoryTypeIndex =
      device.memory_type(requirements.memoryTypeBits & host_properties.memoryTypeBits,
                         VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, 0);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  if (vkAllocateMemory(device.handle(), &allocate_info, nullptr, &memory) != VK_SUCCESS)
    return GpuBuffer();
  result.memory_ = vk::DeviceMemory(memory, {device.handle()});
  GLPT_VK_CHECK(vkBindBufferMemory(device.handle(), buffer, memory, 0));
  result.size_ = size;
  result.mapped_ = pointer;
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
