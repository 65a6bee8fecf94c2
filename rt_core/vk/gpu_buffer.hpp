// A VkBuffer with its own memory allocation, persistently mapped and with a device address.
//
// All buffers live in host-visible, host-coherent memory: on lavapipe that is the only kind of
// memory (so uploads and readbacks are plain memcpy, no staging copies), and on a GPU it still
// works, through the BAR or system memory. Device-local is preferred where the driver offers it
// together with host visibility.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstring>
#include <glm/vec2.hpp>
#include <utility>

#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

class GpuBuffer {
 public:
  GpuBuffer() = default;
  GpuBuffer(GpuBuffer&&) noexcept = default;
  // Releases the old buffer before its memory (the defaulted operator would free memory first).
  GpuBuffer& operator=(GpuBuffer&& other) noexcept {
    if (this != &other) {
      buffer_ = std::move(other.buffer_);
      memory_ = std::move(other.memory_);
      size_ = std::exchange(other.size_, 0);
      address_ = std::exchange(other.address_, 0);
      mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
  }
  // `usage` gets SHADER_DEVICE_ADDRESS added. Throws VulkanError.
  static GpuBuffer create(const VulkanDevice& device, VkDeviceSize size, VkBufferUsageFlags usage);
  // A buffer over existing host memory (VK_EXT_external_memory_host): `pointer` and `size` must
  // be aligned to device.host_pointer_alignment(); the memory must outlive the buffer. An empty
  // buffer when the device cannot import it. Throws VulkanError on other failures.
  static GpuBuffer import_host(const VulkanDevice& device, void* pointer, VkDeviceSize size,
                               VkBufferUsageFlags usage);

  VkBuffer handle() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  VkDeviceAddress address() const { return address_; }
  // The device address as a shader takes it from a uniform (GL_EXT_buffer_reference_uvec2): low
  // word, high word.
  glm::uvec2 address_words() const {
    return {static_cast<uint32_t>(address_), static_cast<uint32_t>(address_ >> 32)};
  }
  void* mapped() const { return mapped_; }
  template <typename T>
  T* as() const {
    return static_cast<T*>(mapped_);
  }
  void write(const void* source, size_t bytes, size_t offset = 0) const {
    if (bytes != 0) std::memcpy(static_cast<std::byte*>(mapped_) + offset, source, bytes);
  }
  explicit operator bool() const { return static_cast<bool>(buffer_); }

 private:
  // The buffer is destroyed before the memory it is bound to.
  vk::DeviceMemory memory_;
  vk::Buffer buffer_;
  VkDeviceSize size_ = 0;
  VkDeviceAddress address_ = 0;
  void* mapped_ = nullptr;
};

// Makes `buffer` hold at least `size` bytes, re-creating it (with 50 % headroom, so slowly
// growing scenes do not re-create it every frame) when it is too small. The contents are not
// kept. Returns true when the buffer was re-created.
bool ensure_capacity(const VulkanDevice& device, GpuBuffer& buffer, VkDeviceSize size,
                     VkBufferUsageFlags usage);

}  // namespace glpt::rt
