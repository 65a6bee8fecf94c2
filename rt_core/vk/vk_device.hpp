// The Vulkan instance, the chosen physical device, the logical device (raster features always,
// ray queries when the device has them), and one graphics+compute queue with a reusable command
// buffer for "record, submit, wait" work. One per process, shared by every GL context.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

// How to get a Vulkan driver with ray queries on Debian 12 (for messages).
const char* vulkan_install_hint();

// Thrown by VulkanDevice::create when no usable device exists; the message says what is missing
// and how to install it.
class DeviceUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DeviceOptions {
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation if installed
  // Pick the first suitable device whose name contains this (GLPT_VK_DEVICE); empty: prefer a
  // CPU device (lavapipe), then any suitable one.
  std::string name_filter;
  // Treat every device as lacking ray queries (GLPT_VK_NO_RAY_QUERY=1): exercises the fallback to
  // raster mode on a machine that has them.
  bool hide_ray_query = false;
  bool operator==(const DeviceOptions&) const = default;
};

// Entry points of VK_KHR_acceleration_structure: the loader does not export them, they come from
// vkGetDeviceProcAddr.
struct AccelerationStructureFunctions {
  PFN_vkCreateAccelerationStructureKHR create = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroy = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR get_build_sizes = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmd_build = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR get_device_address = nullptr;
};

class VulkanDevice {
 public:
  // A new device of its own (tests that want one). Throws DeviceUnavailable or VulkanError.
  static std::unique_ptr<VulkanDevice> create(const DeviceOptions& options);
  // The process's device for `options`: created on first use and shared by every renderer (every
  // GL context, whatever its share group) for as long as one holds it. One device means one set
  // of lavapipe threads and one queue, and a drawable's buffers can be used by any context.
  // Throws as create().
  static std::shared_ptr<VulkanDevice> shared(const DeviceOptions& options);
  // How many devices this process has created so far (what tests of "one device" count).
  static uint64_t devices_created();
  ~VulkanDevice();
  VulkanDevice(const VulkanDevice&) = delete;
  VulkanDevice& operator=(const VulkanDevice&) = delete;

  VkDevice handle() const { return device_.get(); }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  uint32_t queue_family() const { return queue_family_; }
  // Ray queries and acceleration structures (path-traced mode). Without them only raster mode
  // works; ray_query_missing() names what the device lacks.
  bool has_ray_query() const { return ray_query_; }
  const std::string& ray_query_missing() const { return ray_query_missing_; }
  bool has_geometry_shader() const { return geometry_shader_; }
  bool has_smooth_lines() const { return smooth_lines_; }
  // occlusionQueryPrecise: occlusion queries count samples (else only zero / not zero).
  bool has_precise_occlusion_queries() const { return precise_occlusion_queries_; }
  // Host memory (an X shared-memory segment) can be imported as a buffer, with this alignment.
  bool has_external_host_memory() const { return external_host_memory_; }
  VkDeviceSize host_pointer_alignment() const { return host_pointer_alignment_; }
  const AccelerationStructureFunctions& as_functions() const { return as_functions_; }
  const std::string& name() const { return name_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }
  VkDeviceSize scratch_alignment() const { return scratch_alignment_; }

  // A memory type in `type_bits` with all `required` flags, preferring one that also has
  // `preferred`. Throws VulkanError if none.
  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                       VkMemoryPropertyFlags preferred) const;

  // Records commands into the device's command buffer with `record`, submits them and waits for
  // completion. Each call starts with a full memory barrier, so work of earlier calls and host
  // writes are visible, and ends with one that makes results visible to the host. Returns the
  // wall-clock milliseconds of submit + wait. Thread-safe: contexts current on different threads
  // share the device, and calls are serialized (the queue and command buffer are one).
  double submit_and_wait(const std::function<void(VkCommandBuffer)>& record);

  // Number of messages the validation layer reported (0 without validation).
  uint64_t validation_messages() const { return validation_messages_; }

 private:
  VulkanDevice() = default;
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user_data);

  // Written by the validation callback, which can run until the instance is gone: declared
  // first so it outlives every Vulkan object below.
  std::atomic<uint64_t> validation_messages_ = 0;
  // Declaration order is destruction order in reverse: everything device-level goes before the
  // device, the device before the messenger and instance.
  vk::Instance instance_;
  vk::DebugMessenger messenger_;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  vk::Device device_;
  std::mutex submit_mutex_;  // guards command_buffer_, fence_ and queue_ (submit_and_wait)
  vk::CommandPool command_pool_;
  vk::Fence fence_;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  bool ray_query_ = false;
  std::string ray_query_missing_;
  bool geometry_shader_ = false;
  bool smooth_lines_ = false;
  bool precise_occlusion_queries_ = false;
  bool external_host_memory_ = false;
  VkDeviceSize host_pointer_alignment_ = 4096;
  VkCommandBuffer command_buffer_ = VK_NULL_HANDLE;  // freed with command_pool_

  AccelerationStructureFunctions as_functions_;
  std::string name_;
  VkPhysicalDeviceLimits limits_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  VkDeviceSize scratch_alignment_ = 1;
};

}  // namespace glpt::rt
