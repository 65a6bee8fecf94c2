// Move-only owners for Vulkan handles. Every Vulkan object rt_core creates lives in one of these,
// so destruction happens in exactly one place (the deleter) and in reverse declaration order of
// the owning class's members, with no destroy calls scattered around.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

namespace glpt::rt::vk {

// Vulkan objects alive in this process (every owner below counts its handle): a statistic for
// GLPT_STATS (vk_objects=) and the soak (bench/soak.sh), where a count that grows frame after
// frame is a leak. Relaxed: only the count matters, not its order with anything else.
inline std::atomic<int64_t>& live_object_count() {
  static std::atomic<int64_t> count{0};
  return count;
}

// The same count per kind of handle, so that a count that grows says what grows (the soak's
// report names it). The kinds are the handle types the owners below are instantiated with.
using ObjectKinds =
    std::tuple<VkInstance, VkDevice, VkDebugUtilsMessengerEXT, VkAccelerationStructureKHR, VkBuffer,
               VkDeviceMemory, VkCommandPool, VkDescriptorPool, VkDescriptorSetLayout, VkFence,
               VkPipeline, VkPipelineLayout, VkShaderModule, VkImage, VkImageView, VkSampler,
               VkPipelineCache, VkQueryPool, VkRenderPass, VkFramebuffer, VkSemaphore>;
template <typename Handle, std::size_t index = 0>
constexpr std::size_t kind_index() {
  if constexpr (index == std::tuple_size_v<ObjectKinds>)
    return index;
  else if constexpr (std::is_same_v<Handle, std::tuple_element_t<index, ObjectKinds>>)
    return index;
  else
    return kind_index<Handle, index + 1>();
}
inline constexpr std::array<const char*, std::tuple_size_v<ObjectKinds>> kObjectKindNames = {
    "instance",
    "device",
    "debug_messenger",
    "acceleration_structure",
    "buffer",
    "memory",
    "command_pool",
    "descriptor_pool",
    "descriptor_set_layout",
    "fence",
    "pipeline",
    "pipeline_layout",
    "shader_module",
    "image",
    "image_view",
    "sampler",
    "pipeline_cache",
    "query_pool",
    "render_pass",
    "framebuffer",
    "semaphore"};
inline std::array<std::atomic<int64_t>, kObjectKindNames.size()>& live_object_counts_by_kind() {
  static std::array<std::atomic<int64_t>, kObjectKindNames.size()> counts{};
  return counts;
}
template <typename Handle>
std::atomic<int64_t>& live_count_of() {
  constexpr std::size_t index = kind_index<Handle>();
  static_assert(index < kObjectKindNames.size(), "a Vulkan handle type without a kind name");
  return live_object_counts_by_kind()[index];
}
// "buffer:12,memory:12,...": the kinds with objects alive, for GLPT_STATS (vk_by_kind=).
inline std::string live_object_counts_text() {
  std::string text;
  for (std::size_t kind = 0; kind < kObjectKindNames.size(); ++kind) {
    int64_t alive = live_object_counts_by_kind()[kind].load(std::memory_order_relaxed);
    if (alive == 0) continue;
    if (!text.empty()) text += ',';
    text += kObjectKindNames[kind];
    text += ':';
    text += std::to_string(alive);
  }
  return text.empty() ? std::string("none") : text;
}

template <typename Handle, typename Deleter>
class Unique {
 public:
  Unique() = default;
  Unique(Handle handle, Deleter deleter) : handle_(handle), deleter_(deleter) {
    if (handle_ != Handle{VK_NULL_HANDLE}) {
      live_object_count().fetch_add(1, std::memory_order_relaxed);
      live_count_of<Handle>().fetch_add(1, std::memory_order_relaxed);
    }
  }
  Unique(const Unique&) = delete;
  Unique& operator=(const Unique&) = delete;
  Unique(Unique&& other) noexcept
      : handle_(std::exchange(other.handle_, Handle{VK_NULL_HANDLE})), deleter_(other.deleter_) {}
  Unique& operator=(Unique&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, Handle{VK_NULL_HANDLE});
      deleter_ = other.deleter_;
    }
    return *this;
  }
  ~Unique() { reset(); }

  void reset() noexcept {
    if (handle_ != Handle{VK_NULL_HANDLE}) {
      deleter_(handle_);
      live_object_count().fetch_sub(1, std::memory_order_relaxed);
      live_count_of<Handle>().fetch_sub(1, std::memory_order_relaxed);
    }
    handle_ = Handle{VK_NULL_HANDLE};
  }
  Handle get() const { return handle_; }
  const Handle* address() const { return &handle_; }  // for APIs taking arrays of handles
  explicit operator bool() const { return handle_ != Handle{VK_NULL_HANDLE}; }

 private:
  Handle handle_{VK_NULL_HANDLE};
  Deleter deleter_{};
};

// Objects destroyed with vkDestroyX(device, handle, allocator) from the loader's exports.
template <typename Handle, auto Destroy>
struct DeviceChildDeleter {
  VkDevice device = VK_NULL_HANDLE;
  void operator()(Handle handle) const { Destroy(device, handle, nullptr); }
};

template <typename Handle, auto Destroy>
using DeviceChild = Unique<Handle, DeviceChildDeleter<Handle, Destroy>>;

struct InstanceDeleter {
  void operator()(VkInstance instance) const { vkDestroyInstance(instance, nullptr); }
};
struct DeviceDeleter {
  void operator()(VkDevice device) const { vkDestroyDevice(device, nullptr); }
};
// Extension objects: their destroy entry point is looked up at run time.
struct DebugMessengerDeleter {
  VkInstance instance = VK_NULL_HANDLE;
  PFN_vkDestroyDebugUtilsMessengerEXT destroy = nullptr;
  void operator()(VkDebugUtilsMessengerEXT messenger) const {
    destroy(instance, messenger, nullptr);
  }
};
struct AccelerationStructureDeleter {
  VkDevice device = VK_NULL_HANDLE;
  PFN_vkDestroyAccelerationStructureKHR destroy = nullptr;
  void operator()(VkAccelerationStructureKHR structure) const {
    destroy(device, structure, nullptr);
  }
};

using Instance = Unique<VkInstance, InstanceDeleter>;
using Device = Unique<VkDevice, DeviceDeleter>;
using DebugMessenger = Unique<VkDebugUtilsMessengerEXT, DebugMessengerDeleter>;
using AccelerationStructure = Unique<VkAccelerationStructureKHR, AccelerationStructureDeleter>;
using Buffer = DeviceChild<VkBuffer, &vkDestroyBuffer>;
// vkFreeMemory also unmaps a mapped allocation, so no separate unmap is needed.
using DeviceMemory = DeviceChild<VkDeviceMemory, &vkFreeMemory>;
// Command buffers and descriptor sets are freed with their pools.
using CommandPool = DeviceChild<VkCommandPool, &vkDestroyCommandPool>;
using DescriptorPool = DeviceChild<VkDescriptorPool, &vkDestroyDescriptorPool>;
using DescriptorSetLayout = DeviceChild<VkDescriptorSetLayout, &vkDestroyDescriptorSetLayout>;
using Fence = DeviceChild<VkFence, &vkDestroyFence>;
using Pipeline = DeviceChild<VkPipeline, &vkDestroyPipeline>;
using PipelineLayout = DeviceChild<VkPipelineLayout, &vkDestroyPipelineLayout>;
using ShaderModule = DeviceChild<VkShaderModule, &vkDestroyShaderModule>;
using Image = DeviceChild<VkImage, &vkDestroyImage>;
using ImageView = DeviceChild<VkImageView, &vkDestroyImageView>;
using Sampler = DeviceChild<VkSampler, &vkDestroySampler>;
using PipelineCache = DeviceChild<VkPipelineCache, &vkDestroyPipelineCache>;
using QueryPool = DeviceChild<VkQueryPool, &vkDestroyQueryPool>;
using RenderPass = DeviceChild<VkRenderPass, &vkDestroyRenderPass>;
using Framebuffer = DeviceChild<VkFramebuffer, &vkDestroyFramebuffer>;
using Semaphore = DeviceChild<VkSemaphore, &vkDestroySemaphore>;

}  // namespace glpt::rt::vk
