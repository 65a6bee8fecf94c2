// The Vulkan instance, the chosen physical device, the logical device (raster features always,
// ray queries when the device has them), and one graphics+compute queue with a reusable command
// buffer for "record, submit, wait" work. One per process, shared by every GL context.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "common/device_survey.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

// True once the process is exiting: exit() has run the handlers registered after the Vulkan
// driver was loaded, and the driver's own (lavapipe's LLVM: its global state is torn down by
// static destructors registered when it was loaded) may run next or already have. A program
// whose exit handler releases or destroys its GL context (piglit's teardown, through
// glXMakeCurrent) must then not render or compile: LLVM used after its teardown hangs in code
// generation or crashes. Set by a handler VulkanDevice::create registers.
bool process_exiting();

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
  // Wait for every submission right away (GLPT_VK_SYNC=1), as glpt did before the passes of a
  // frame overlapped: what that overlap gains is measured against it, and a synchronization
  // problem shows by going away with it.
  bool sync_submissions = false;
  // Treat the device as lacking dynamic blend state (GLPT_VK_NO_DYNAMIC_BLEND=1): every blend,
  // colour mask and logic op state its own pipeline, as on devices without
  // VK_EXT_extended_dynamic_state3 (for A/B measurements and to test that path).
  bool hide_dynamic_blend = false;
  // Treat the device as lacking ordered reads of colour attachments (GLPT_VK_NO_SHADER_BLEND=1):
  // blending and logic ops in the pipeline's blend state, not in the fragment shader.
  bool hide_framebuffer_reads = false;
  // Also append every validation message, one line each, to this file (GLPT_VALIDATION_LOG):
  // `scripts/test.sh --validation` collects the messages of every process of the test suite
  // there, including programs whose stderr a test swallows or compares.
  std::string validation_log;
  // Time every submission with a pair of timestamp queries (RenderSettings::device_timing).
  bool timestamps = true;
  bool operator==(const DeviceOptions&) const = default;
  // GLPT_VK_DEVICE, GLPT_VK_NO_RAY_QUERY and GLPT_VK_SYNC, as every renderer reads them.
  static DeviceOptions from_environment(bool validation);
};

// Every Vulkan device as glpt judges it, without creating one: what `glpt doctor` reports. The
// judgement is VulkanDevice::create's own (the same requirements and the same ranking), so the
// doctor cannot disagree with what a renderer would do.
DeviceSurvey survey_devices(const DeviceOptions& options);

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
  // A fragment shader may read the colour attachment it writes as an input attachment, in
  // rasterization order (VK_EXT_rasterization_order_attachment_access), in render passes with
  // imageless framebuffers: blending and logic ops in the shader (raster_framebuffer_ops.h).
  bool has_ordered_framebuffer_reads() const { return ordered_framebuffer_reads_; }
  // Blend enable, equations and factors, colour write masks and the logic op set per draw
  // (VK_EXT_extended_dynamic_state3 and _2's logic op): one pipeline serves every blend state.
  // Null where the device lacks them.
  struct DynamicBlendFunctions {
    PFN_vkCmdSetColorBlendEnableEXT set_enable = nullptr;
    PFN_vkCmdSetColorBlendEquationEXT set_equation = nullptr;
    PFN_vkCmdSetColorWriteMaskEXT set_write_mask = nullptr;
    PFN_vkCmdSetLogicOpEnableEXT set_logic_op_enable = nullptr;
    PFN_vkCmdSetLogicOpEXT set_logic_op = nullptr;
  };
  const DynamicBlendFunctions* dynamic_blend() const {
    return dynamic_blend_.set_enable != nullptr ? &dynamic_blend_ : nullptr;
  }
  // occlusionQueryPrecise: occlusion queries count samples (else only zero / not zero).
  bool has_precise_occlusion_queries() const { return precise_occlusion_queries_; }
  // Host memory (an X shared-memory segment) can be imported as a buffer, with this alignment.
  bool has_external_host_memory() const { return external_host_memory_; }
  VkDeviceSize host_pointer_alignment() const { return host_pointer_alignment_; }
  const AccelerationStructureFunctions& as_functions() const { return as_functions_; }
  const std::string& name() const { return name_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }
  // Vendor, device and driver ids and the pipeline cache UUID: what a pipeline cache is valid for.
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  VkDeviceSize scratch_alignment() const { return scratch_alignment_; }

  // A memory type in `type_bits` with all `required` flags, preferring one that also has
  // `preferred`. Throws VulkanError if none.
  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                       VkMemoryPropertyFlags preferred) const;

  // Submissions: tickets in submission order (0: none). `submit` records commands with `record`
  // into a command buffer of its own and submits them without waiting, so the passes of one
  // frame follow each other on the device while the host prepares the next; `wait` blocks until
  // a ticket and every earlier one have completed (it holds no lock while it blocks). Each
  // submission starts with a full memory barrier, so earlier submissions' work and host writes made
  // before it are visible, and ends with one that makes its results visible to the host once
  // waited. A caller that writes host memory a pending submission reads, or reads what it writes,
  // waits for it first. Thread-safe: contexts current on different threads share the device, and
  // submissions are serialized (the queue is one).
  using Ticket = uint64_t;
  Ticket submit(const std::function<void(VkCommandBuffer)>& record);
  void wait(Ticket ticket);
  void wait_all() { wait(last_ticket()); }
  Ticket last_ticket() const;
  // Every ticket up to the one returned has completed (asks the fences of the later ones, without
  // waiting).
  Ticket completed_ticket();
  // The device time of a completed ticket's commands in milliseconds (timestamps; where the
  // queue has none, submit to completion as the host saw it), once: the value is handed over
  // and forgotten. 0 for a ticket not waited for, unknown or already taken.
  double take_device_ms(Ticket ticket);
  // submit, then wait; returns the ticket's device milliseconds.
  double submit_and_wait(const std::function<void(VkCommandBuffer)>& record);
  // How many times the host has waited for the device (waits for tickets not yet known to be
  // complete, and submissions that had to wait for a free slot): what FrameStats::host_waits
  // counts per frame.
  uint64_t host_waits() const { return host_waits_; }

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
  std::string validation_log_;  // DeviceOptions::validation_log; set before the instance
  // Declaration order is destruction order in reverse: everything device-level goes before the
  // device, the device before the messenger and instance.
  vk::Instance instance_;
  vk::DebugMessenger messenger_;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  vk::Device device_;
  // Guards the submission ring, the ticket counters, the finished times and queue_.
  mutable std::mutex submit_mutex_;
  vk::CommandPool command_pool_;
  // Submissions in flight: slot t % kSubmissionSlots holds ticket t until it is waited for (a new
  // submission waits for the slot's previous ticket, kSubmissionSlots tickets back).
  static constexpr size_t kSubmissionSlots = 16;
  struct SubmissionSlot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // freed with command_pool_
    vk::Fence fence;
    Ticket ticket = 0;  // pending while nonzero
    double submitted_at_ms = 0;
  };
  std::array<SubmissionSlot, kSubmissionSlots> slots_;
  vk::Semaphore timeline_;    // timeline semaphore: value t once ticket t has completed
  vk::QueryPool timestamps_;  // two per slot (start, end); null where the queue has none
  double timestamp_period_ns_ = 0;
  uint64_t timestamp_mask_ = 0;
  Ticket last_ticket_ = 0;
  std::atomic<uint64_t> host_waits_ = 0;
  bool sync_submissions_ = false;
  DynamicBlendFunctions dynamic_blend_;
  Ticket completed_ticket_ = 0;           // every ticket up to it has completed
  std::map<Ticket, double> finished_ms_;  // device times not yet taken (the newest only)
  void complete_locked(SubmissionSlot& slot);
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  bool ray_query_ = false;
  std::string ray_query_missing_;
  bool geometry_shader_ = false;
  bool smooth_lines_ = false;
  bool ordered_framebuffer_reads_ = false;
  bool precise_occlusion_queries_ = false;
  bool external_host_memory_ = false;
  VkDeviceSize host_pointer_alignment_ = 4096;

  AccelerationStructureFunctions as_functions_;
  std::string name_;
  VkPhysicalDeviceLimits limits_{};
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  VkDeviceSize scratch_alignment_ = 1;
};

}  // namespace glpt::rt
