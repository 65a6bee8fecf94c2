#include "rt_core/vk/vk_error.hpp"

namespace glpt::rt {

std::string vk_result_name(VkResult result) {
  switch (result) {
#define GLPT_RESULT_CASE(name) \
  case name:                   \
    return #name;
    GLPT_RESULT_CASE(VK_SUCCESS)
    GLPT_RESULT_CASE(VK_NOT_READY)
    GLPT_RESULT_CASE(VK_TIMEOUT)
    GLPT_RESULT_CASE(VK_INCOMPLETE)
    GLPT_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    GLPT_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    GLPT_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    GLPT_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    GLPT_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    GLPT_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    GLPT_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    GLPT_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    GLPT_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    GLPT_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    GLPT_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    GLPT_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    GLPT_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    GLPT_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    GLPT_RESULT_CASE(VK_ERROR_UNKNOWN)
#undef GLPT_RESULT_CASE
    default:
      return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
  }
}

void check_vk(VkResult result, const char* what) {
  if (result != VK_SUCCESS)
    throw VulkanError(std::string(what) + " failed: " + vk_result_name(result));
}

}  // namespace glpt::rt
