// The top-level acceleration structure: one instance per TraceScene::Instance, rebuilt (never
// updated) whenever the instance list changes. Buffers and the AS object are kept and only
// re-created when the instance count outgrows them.
#pragma once

#include <span>

#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

class Tlas {
 public:
  explicit Tlas(VulkanDevice& device) : device_(device) {}

  // Submits the build of the TLAS from `instances` (any count, including 0) without waiting
  // (submissions after it see the result); waits for the previous build first, whose buffers
  // this one refills. Returns the build's ticket. Throws VulkanError.
  VulkanDevice::Ticket build(std::span<const VkAccelerationStructureInstanceKHR> instances);

  VkAccelerationStructureKHR handle() const { return structure_.get(); }

 private:
  void reserve(uint32_t instance_count);
  VkAccelerationStructureGeometryKHR instances_geometry() const;

  VulkanDevice& device_;
  GpuBuffer instance_buffer_;
  GpuBuffer scratch_;
  GpuBuffer storage_;
  vk::AccelerationStructure structure_;  // declared after storage_: destroyed before it
  uint32_t capacity_ = 0;
  VulkanDevice::Ticket last_build_ = 0;
  VkDeviceSize scratch_size_ = 0;
};

}  // namespace glpt::rt
