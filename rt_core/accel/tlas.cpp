#include "rt_core/accel/tlas.hpp"

#include <algorithm>

#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {

VkAccelerationStructureGeometryKHR Tlas::instances_geometry() const {
  auto geometry = make_info<VkAccelerationStructureGeometryKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
  geometry.geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry.geometry.instances.arrayOfPointers = VK_FALSE;
  geometry.geometry.instances.data.deviceAddress = instance_buffer_.address();
  return geometry;
}

void Tlas::reserve(uint32_t instance_count) {
  if (structure_ && instance_count <= capacity_) return;
  // Grow geometrically so a scene that adds objects over time re-creates rarely.
  const uint32_t capacity = std::max({instance_count, capacity_ * 2, 16u});
  structure_.reset();
  instance_buffer_ =
      GpuBuffer::create(device_, capacity * sizeof(VkAccelerationStructureInstanceKHR),
                        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR);

  VkAccelerationStructureGeometryKHR geometry = instances_geometry();
  auto info = acceleration_build_info(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, &geometry);
  auto sizes = make_info<VkAccelerationStructureBuildSizesInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
  const auto& as = device_.as_functions();
  // Sized for `capacity` instances: later builds with fewer instances fit into it.
  as.get_build_sizes(device_.handle(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info,
                     &capacity, &sizes);
  storage_ = GpuBuffer::create(device_, sizes.accelerationStructureSize,
                               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR);
  scratch_size_ = sizes.buildScratchSize + device_.scratch_alignment();
  scratch_ = GpuBuffer::create(device_, scratch_size_, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

  auto create_info = make_info<VkAccelerationStructureCreateInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR);
  create_info.buffer = storage_.handle();
  create_info.size = sizes.accelerationStructureSize;
  create_info.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  VkAccelerationStructureKHR structure = VK_NULL_HANDLE;
  GLPT_VK_CHECK(as.create(device_.handle(), &create_info, nullptr, &structure));
  structure_ = vk::AccelerationStructure(structure, {device_.handle(), as.destroy});
  capacity_ = capacity;
}

VulkanDevice::Ticket Tlas::build(std::span<const VkAccelerationStructureInstanceKHR> instances) {
  device_.wait(last_build_);
  const auto count = static_cast<uint32_t>(instances.size());
  reserve(count);
  instance_buffer_.write(instances.data(), instances.size_bytes());

  VkAccelerationStructureGeometryKHR geometry = instances_geometry();
  auto info = acceleration_build_info(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, &geometry);
  info.dstAccelerationStructure = structure_.get();
  const VkDeviceSize alignment = device_.scratch_alignment();
  info.scratchData.deviceAddress = (scratch_.address() + alignment - 1) / alignment * alignment;
  const VkAccelerationStructureBuildRangeInfoKHR range{count, 0, 0, 0};
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
  last_build_ = device_.submit(
      [&](VkCommandBuffer cmd) { device_.as_functions().cmd_build(cmd, 1, &info, &ranges); });
  return last_build_;
}

}  // namespace glpt::rt
