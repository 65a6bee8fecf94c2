// Vulkan error reporting inside rt_core. Internal code throws VulkanError; the public API
// (renderer.cpp) catches everything, because the library is called through a C ABI.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace glpt::rt {

class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "VK_ERROR_DEVICE_LOST" etc.; the numeric value for codes it does not know.
std::string vk_result_name(VkResult result);

// Throws VulkanError("<what> failed: <result>") unless `result` is VK_SUCCESS.
void check_vk(VkResult result, const char* what);

}  // namespace glpt::rt

// Names the failing call in the message: GLPT_VK_CHECK(vkCreateFence(...)).
#define GLPT_VK_CHECK(call) ::glpt::rt::check_vk((call), #call)
