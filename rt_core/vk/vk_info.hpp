// Construction of Vulkan info structs.
#pragma once

#include <vulkan/vulkan.h>

namespace glpt::rt {

// A zero-initialized Vulkan struct with its sType (and optionally pNext) set: the idiom
// `VkFooInfo info{VK_STRUCTURE_TYPE_FOO_INFO}` trips -Wmissing-field-initializers.
template <typename T>
T make_info(VkStructureType type, void* next = nullptr) {
  T info{};
  info.sType = type;
  info.pNext = next;
  return info;
}

// Build info for one acceleration structure of one geometry. Always PREFER_FAST_TRACE: glpt
// builds a BLAS once and traces it for many frames.
inline VkAccelerationStructureBuildGeometryInfoKHR acceleration_build_info(
    VkAccelerationStructureTypeKHR type, const VkAccelerationStructureGeometryKHR* geometry) {
  auto info = make_info<VkAccelerationStructureBuildGeometryInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
  info.type = type;
  info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.geometryCount = 1;
  info.pGeometries = geometry;
  return info;
}

}  // namespace glpt::rt
