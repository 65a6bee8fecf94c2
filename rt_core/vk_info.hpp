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

}  // namespace glpt::rt
