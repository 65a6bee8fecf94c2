// The top-level acceleration structure: one instance per TraceScene::Instance, built whenever the
// instance list changes. When only the instances' transforms, masks or indices changed (the same
// count referring to the same BLASes in the same order: objects moved, the camera moved) it is
// updated in place instead (VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR), except every
// kMaxUpdates-th time, when it is rebuilt so tracing does not degrade with repeated updates.
// Buffers and the AS object are kept and only re-created when the instance count outgrows them.
#pragma once

#include <span>
#include <vector>

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
  // `updated` (may be null) says whether it was an update rather than a build.
  VulkanDevice::Ticket build(std::span<const VkAccelerationStructureInstanceKHR> instances,
                             bool* updated = nullptr);

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
  static constexpr uint32_t kMaxUpdates = 32;
  std::vector<uint64_t> built_references_;  // the BLAS of each instance the structure holds
  uint32_t updates_since_build_ = 0;
};

}  // namespace glpt::rt
