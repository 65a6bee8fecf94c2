#include "rt_core/vk/vk_device.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <vector>

#include "common/stopwatch.hpp"
#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"

namespace glpt::rt {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kInstallHint =
    "On Debian 12 install mesa-vulkan-drivers >= 24.1 from bookworm-backports (lavapipe with "
    "VK_KHR_ray_query), see scripts/setup.sh.";
}  // namespace

const char* vulkan_install_hint() { return kInstallHint; }

namespace {

// Raster mode: GL's rasterization rules on Vulkan (see docs/architecture.md, "raster parity").
constexpr const char* kRasterDeviceExtensions[] = {
    VK_EXT_PROVOKING_VERTEX_EXTENSION_NAME,     // GL's last-vertex convention
    VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME,   // Bresenham (GL's diamond-exit) lines, stipple
    VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME,   // GL's [-1, 1] clip-space depth
    VK_EXT_CUSTOM_BORDER_COLOR_EXTENSION_NAME,  // GL's texture border colour
};
// Path tracing. VK_KHR_deferred_host_operations is required by VK_KHR_acceleration_structure
// even though all builds run on the queue.
// Blend state set per draw (optional: without it each blend state is a pipeline of its own).
constexpr const char* kDynamicBlendDeviceExtensions[] = {
    VK_EXT_EXTENDED_DYNAMIC_STATE_2_EXTENSION_NAME,
    VK_EXT_EXTENDED_DYNAMIC_STATE_3_EXTENSION_NAME,
};
// Blending in the fragment shader (optional: else blending is the pipeline's).
constexpr const char* kOrderedFramebufferReadExtensions[] = {
    VK_EXT_RASTERIZATION_ORDER_ATTACHMENT_ACCESS_EXTENSION_NAME,
};
constexpr const char* kRayQueryDeviceExtensions[] = {
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
    VK_KHR_RAY_QUERY_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
};

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& layer) {
    return std::strcmp(layer.layerName, name) == 0;
  });
}

struct Candidate {
  VkPhysicalDevice device = VK_NULL_HANDLE;
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t queue_family = UINT32_MAX;
  std::vector<std::string> missing;            // for raster (and anything at all): empty = usable
  std::vector<std::string> missing_ray_query;  // empty: path tracing possible
  bool geometry_shader = false;
  bool storage_image_read = false, storage_image_write = false;  // ...WithoutFormat
  uint32_t api_version = 0;
  std::string driver;                 // driverName and driverInfo, where the driver reports them
  bool external_host_memory = false;  // VK_EXT_external_memory_host: zero-copy presenting
  bool smooth_lines = false, stippled_smooth_lines = false;
  bool precise_occlusion_queries = false;
  // VK_EXT_extended_dynamic_state3's blend enable, equation, write mask and logic op enable, and
  // _2's logic op: blend state set per draw.
  bool dynamic_blend = false;
  // rasterizationOrderColorAttachmentAccess and imagelessFramebuffer: blending in the shader.
  bool ordered_framebuffer_reads = false;
};

template <size_t N>
void require_extensions(const std::vector<VkExtensionProperties>& available,
                        const char* const (&wanted)[N], std::vector<std::string>& missing) {
  for (const char* name : wanted) {
    const bool found = std::any_of(available.begin(), available.end(), [&](const auto& e) {
      return std::strcmp(e.extensionName, name) == 0;
    });
    if (!found) missing.push_back(name);
  }
}

Candidate evaluate(VkPhysicalDevice device) {
  Candidate candidate;
  candidate.device = device;
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(device, &properties);
  candidate.name = properties.deviceName;
  candidate.type = properties.deviceType;
  candidate.api_version = properties.apiVersion;
  if (properties.apiVersion < VK_API_VERSION_1_3) candidate.missing.push_back("Vulkan 1.3");

  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  require_extensions(extensions, kRasterDeviceExtensions, candidate.missing);
  require_extensions(extensions, kRayQueryDeviceExtensions, candidate.missing_ray_query);
  candidate.external_host_memory =
      std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME) == 0;
      });
  std::vector<std::string> no_dynamic_blend;
  require_extensions(extensions, kDynamicBlendDeviceExtensions, no_dynamic_blend);
  std::vector<std::string> no_ordered_reads;
  require_extensions(extensions, kOrderedFramebufferReadExtensions, no_ordered_reads);
  if (!candidate.missing.empty()) return candidate;  // feature structs may not be understood

  auto dynamic3 = make_info<VkPhysicalDeviceExtendedDynamicState3FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_3_FEATURES_EXT);
  auto dynamic2 = make_info<VkPhysicalDeviceExtendedDynamicState2FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_2_FEATURES_EXT, &dynamic3);
  auto ray_query = make_info<VkPhysicalDeviceRayQueryFeaturesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR,
      no_dynamic_blend.empty() ? static_cast<void*>(&dynamic2) : nullptr);
  auto acceleration = make_info<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR, &ray_query);
  auto provoking = make_info<VkPhysicalDeviceProvokingVertexFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
      candidate.missing_ray_query.empty()
          ? static_cast<void*>(&acceleration)
          : (no_dynamic_blend.empty() ? static_cast<void*>(&dynamic2) : nullptr));
  auto lines = make_info<VkPhysicalDeviceLineRasterizationFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT, &provoking);
  auto depth_clip = make_info<VkPhysicalDeviceDepthClipControlFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT, &lines);
  auto border = make_info<VkPhysicalDeviceCustomBorderColorFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CUSTOM_BORDER_COLOR_FEATURES_EXT, &depth_clip);
  auto vulkan13 = make_info<VkPhysicalDeviceVulkan13Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &border);
  auto vulkan12 = make_info<VkPhysicalDeviceVulkan12Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &vulkan13);
  auto order = make_info<VkPhysicalDeviceRasterizationOrderAttachmentAccessFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RASTERIZATION_ORDER_ATTACHMENT_ACCESS_FEATURES_EXT,
      vulkan12.pNext);
  if (no_ordered_reads.empty()) vulkan12.pNext = &order;
  auto features =
      make_info<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &vulkan12);
  vkGetPhysicalDeviceFeatures2(device, &features);
  candidate.ordered_framebuffer_reads = no_ordered_reads.empty() &&
                                        order.rasterizationOrderColorAttachmentAccess &&
                                        vulkan12.imagelessFramebuffer;
  const VkPhysicalDeviceFeatures& core = features.features;
  auto need = [&](bool present, const char* what) {
    if (!present) candidate.missing.push_back(what);
  };
  need(vulkan12.bufferDeviceAddress, "bufferDeviceAddress");
  need(vulkan13.dynamicRendering, "dynamicRendering");
  need(vulkan13.synchronization2, "synchronization2");
  need(vulkan13.maintenance4, "maintenance4");
  need(core.fillModeNonSolid, "fillModeNonSolid");
  need(core.wideLines, "wideLines");
  need(core.largePoints, "largePoints");
  need(core.logicOp, "logicOp");
  need(core.shaderClipDistance, "shaderClipDistance");
  need(core.independentBlend, "independentBlend");
  need(provoking.provokingVertexLast, "provokingVertexLast");
  need(lines.bresenhamLines, "bresenhamLines");
  need(lines.stippledBresenhamLines, "stippledBresenhamLines");
  need(depth_clip.depthClipControl, "depthClipControl");
  need(border.customBorderColors, "customBorderColors");
  need(border.customBorderColorWithoutFormat, "customBorderColorWithoutFormat");
  // Geometry shaders draw GL's unfilled polygons with edge flags; they also need point sizes.
  candidate.geometry_shader = core.geometryShader && core.shaderTessellationAndGeometryPointSize;
  candidate.storage_image_read = core.shaderStorageImageReadWithoutFormat;
  candidate.storage_image_write = core.shaderStorageImageWriteWithoutFormat;
  // Smooth lines are only used where stippled smooth lines exist too (GL stipples either kind).
  candidate.smooth_lines = lines.smoothLines && lines.stippledSmoothLines;
  candidate.stippled_smooth_lines = lines.stippledSmoothLines;
  // GL's occlusion queries count samples; without this feature Vulkan may only count 0 or not 0.
  candidate.precise_occlusion_queries = core.occlusionQueryPrecise;
  candidate.dynamic_blend = no_dynamic_blend.empty() && dynamic2.extendedDynamicState2LogicOp &&
                            dynamic3.extendedDynamicState3ColorBlendEnable &&
                            dynamic3.extendedDynamicState3ColorBlendEquation &&
                            dynamic3.extendedDynamicState3ColorWriteMask &&
                            dynamic3.extendedDynamicState3LogicOpEnable;
  if (candidate.missing_ray_query.empty()) {
    if (!acceleration.accelerationStructure)
      candidate.missing_ray_query.push_back("accelerationStructure");
    if (!ray_query.rayQuery) candidate.missing_ray_query.push_back("rayQuery");
    // Path-traced mode's G-buffer pass (a geometry shader) and its trace pass, which reads and
    // writes the BGRA colour buffers as storage images.
    if (!candidate.geometry_shader) candidate.missing_ray_query.push_back("geometryShader");
    if (!core.shaderStorageImageReadWithoutFormat)
      candidate.missing_ray_query.push_back("shaderStorageImageReadWithoutFormat");
    if (!core.shaderStorageImageWriteWithoutFormat)
      candidate.missing_ray_query.push_back("shaderStorageImageWriteWithoutFormat");
    // Bounce and shadow rays sample the texture of whatever draw they hit.
    if (!vulkan12.shaderSampledImageArrayNonUniformIndexing)
      candidate.missing_ray_query.push_back("shaderSampledImageArrayNonUniformIndexing");
  }

  // The path tracer counts rays with subgroupAdd; the denoiser reads a subgroup's shared record
  // state once (subgroupAllEqual, subgroupBroadcastFirst).
  auto subgroup = make_info<VkPhysicalDeviceSubgroupProperties>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES);
  auto driver = make_info<VkPhysicalDeviceDriverProperties>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES, &subgroup);
  auto properties2 = make_info<VkPhysicalDeviceProperties2>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver);
  vkGetPhysicalDeviceProperties2(device, &properties2);
  candidate.driver = driver.driverName;
  if (driver.driverInfo[0] != '\0') candidate.driver += std::string(" ") + driver.driverInfo;
  if (!(subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) ||
      !(subgroup.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT) ||
      !(subgroup.supportedOperations & VK_SUBGROUP_FEATURE_VOTE_BIT) ||
      !(subgroup.supportedOperations & VK_SUBGROUP_FEATURE_BALLOT_BIT)) {
    candidate.missing_ray_query.push_back(
        "subgroup arithmetic, votes and ballots in compute shaders");
  }

  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  constexpr VkQueueFlags kWanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & kWanted) == kWanted) {
      candidate.queue_family = i;
      break;
    }
  }
  if (candidate.queue_family == UINT32_MAX)
    candidate.missing.push_back("a graphics and compute queue");
  return candidate;
}

std::string join(const std::vector<std::string>& parts, const char* separator) {
  std::string joined;
  for (const std::string& part : parts) {
    if (!joined.empty()) joined += separator;
    joined += part;
  }
  return joined;
}

// Ranking: usable at all first; then, without a name filter, ray queries, then a CPU device
// (glpt targets lavapipe, and a machine with both should not silently switch to a GPU with a
// different look or different bugs).
const Candidate& choose(const std::vector<Candidate>& candidates, const std::string& name_filter) {
  std::vector<std::string> reasons;
  const Candidate* best = nullptr;
  auto rank = [&](const Candidate& c) {
    int r = c.missing_ray_query.empty() ? 2 : 0;
    if (name_filter.empty() && c.type == VK_PHYSICAL_DEVICE_TYPE_CPU) r += 1;
    return r;
  };
  for (const Candidate& candidate : candidates) {
    if (!name_filter.empty() && candidate.name.find(name_filter) == std::string::npos) continue;
    if (!candidate.missing.empty()) {
      reasons.push_back(candidate.name + " lacks " + join(candidate.missing, ", "));
      continue;
    }
    if (best == nullptr || rank(candidate) > rank(*best)) best = &candidate;
  }
  if (best != nullptr) return *best;

  std::string message;
  if (!name_filter.empty() && reasons.empty()) {
    std::vector<std::string> names;
    for (const Candidate& candidate : candidates) names.push_back(candidate.name);
    message = "GLPT_VK_DEVICE=\"" + name_filter + "\" matches no Vulkan device (devices: " +
              (names.empty() ? std::string("none") : join(names, ", ")) + ").";
  } else {
    message = "no usable Vulkan device (" +
              (reasons.empty() ? std::string("no Vulkan devices found") : join(reasons, "; ")) +
              "). " + kInstallHint + " (" + kDoctorHint + ")";
  }
  throw DeviceUnavailable("glpt: " + message);
}

std::string version_text(uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
         std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

const char* device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    default:
      return "other";
  }
}

// GLPT_VK_NO_RAY_QUERY: every device is judged as lacking ray queries.
void hide_ray_queries(std::vector<Candidate>& candidates) {
  for (Candidate& c : candidates)
    c.missing_ray_query.push_back("ray queries: hidden by GLPT_VK_NO_RAY_QUERY");
}

}  // namespace

DeviceOptions DeviceOptions::from_environment(bool validation) {
  DeviceOptions options;
  options.validation = validation;
  if (const char* filter = std::getenv("GLPT_VK_DEVICE")) options.name_filter = filter;
  if (const char* hide = std::getenv("GLPT_VK_NO_RAY_QUERY"); hide && *hide && *hide != '0')
    options.hide_ray_query = true;
  if (const char* sync = std::getenv("GLPT_VK_SYNC"); sync && *sync && *sync != '0')
    options.sync_submissions = true;
  if (const char* hide = std::getenv("GLPT_VK_NO_DYNAMIC_BLEND"); hide && *hide && *hide != '0')
    options.hide_dynamic_blend = true;
  if (const char* hide = std::getenv("GLPT_VK_NO_SHADER_BLEND"); hide && *hide && *hide != '0')
    options.hide_framebuffer_reads = true;
  if (const char* log = std::getenv("GLPT_VALIDATION_LOG")) options.validation_log = log;
  return options;
}

DeviceSurvey survey_devices(const DeviceOptions& options) {
  DeviceSurvey survey;
  uint32_t loader_version = VK_API_VERSION_1_0;
  if (vkEnumerateInstanceVersion(&loader_version) == VK_SUCCESS)
    survey.loader_version = version_text(loader_version);
  survey.validation_layer = has_layer(kValidationLayer);

  auto application = make_info<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  application.pApplicationName = "glpt doctor";
  application.apiVersion = VK_API_VERSION_1_3;
  auto instance_info = make_info<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  instance_info.pApplicationInfo = &application;
  VkInstance raw_instance = VK_NULL_HANDLE;
  if (const VkResult result = vkCreateInstance(&instance_info, nullptr, &raw_instance);
      result != VK_SUCCESS) {
    survey.instance_error = "cannot create a Vulkan instance (" + vk_result_name(result) + ")";
    return survey;
  }
  const vk::Instance instance(raw_instance, {});

  uint32_t count = 0;
  std::vector<VkPhysicalDevice> physical_devices;
  if (vkEnumeratePhysicalDevices(raw_instance, &count, nullptr) == VK_SUCCESS) {
    physical_devices.resize(count);
    if (vkEnumeratePhysicalDevices(raw_instance, &count, physical_devices.data()) != VK_SUCCESS)
      physical_devices.clear();
    physical_devices.resize(std::min<size_t>(count, physical_devices.size()));
  }
  std::vector<Candidate> candidates;
  for (VkPhysicalDevice device : physical_devices) candidates.push_back(evaluate(device));
  if (options.hide_ray_query) hide_ray_queries(candidates);
  const Candidate* chosen = nullptr;
  try {
    chosen = &choose(candidates, options.name_filter);
  } catch (const DeviceUnavailable& e) {
    survey.choice_error = e.what();
  }
  for (const Candidate& c : candidates) {
    DeviceSurvey::Device& device = survey.devices.emplace_back();
    device.name = c.name;
    device.type = device_type_name(c.type);
    device.driver = c.driver;
    device.api_version = version_text(c.api_version);
    device.missing = c.missing;
    device.missing_ray_query = c.missing_ray_query;
    device.geometry_shader = c.geometry_shader;
    device.storage_image_read = c.storage_image_read;
    device.storage_image_write = c.storage_image_write;
    device.chosen = &c == chosen;
  }
  return survey;
}

namespace {

// One line per message: the process (pid and command), the level, the message's id and text.
// One write() on an O_APPEND descriptor, so lines of concurrent test processes do not interleave.
void append_validation_log(const std::string& path, const char* level,
                           const VkDebugUtilsMessengerCallbackDataEXT* data) {
  std::string program = "?";
  if (FILE* cmdline = std::fopen("/proc/self/cmdline", "rb")) {
    char buffer[256] = {};
    const size_t n = std::fread(buffer, 1, sizeof buffer - 1, cmdline);
    std::fclose(cmdline);
    if (n > 0) program = buffer;  // argv[0]
  }
  std::string line = std::to_string(::getpid()) + " " + program + " [" + level + "] " +
                     (data->pMessageIdName ? data->pMessageIdName : "-") + ": " +
                     (data->pMessage ? data->pMessage : "");
  for (char& c : line)
    if (c == '\n') c = ' ';
  line += '\n';
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return;  // the message is on stderr still
  const ssize_t written = ::write(fd, line.data(), line.size());
  (void)written;  // nothing more to do if the disk is full: stderr has the message
  ::close(fd);
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanDevice::on_validation_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user_data) {
  auto* self = static_cast<VulkanDevice*>(user_data);
  ++self->validation_messages_;
  const char* level =
      (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
  std::fprintf(stderr, "glpt: [vulkan validation %s] %s\n", level, data->pMessage);
  // The loader's own messages (a missing driver: what faults.no-vulkan arranges on purpose) are
  // about the installation, not about glpt's use of Vulkan: stderr only.
  const bool from_loader =
      data->pMessageIdName != nullptr && std::strcmp(data->pMessageIdName, "Loader Message") == 0;
  // No exception may leave the callback (it unwinds through the layer's C code): an allocation
  // that fails here (faults.c_abi fails every allocation in turn) loses the log line only.
  if (!self->validation_log_.empty() && !from_loader) {
    try {
      append_validation_log(self->validation_log_, level, data);
    } catch (...) {
    }
  }
  return VK_FALSE;
}

namespace {
std::atomic<uint64_t> g_devices_created{0};  // a statistic, for tests and GLPT_STATS
}  // namespace

uint64_t VulkanDevice::devices_created() { return g_devices_created.load(); }

namespace {

std::atomic<bool>& exiting_flag() {
  static std::atomic<bool> exiting{false};  // process-wide by nature, like exit() itself
  return exiting;
}

void mark_process_exiting() { exiting_flag().store(true, std::memory_order_release); }

}  // namespace

bool process_exiting() { return exiting_flag().load(std::memory_order_acquire); }

std::unique_ptr<VulkanDevice> VulkanDevice::create(const DeviceOptions& options) {
  std::unique_ptr<VulkanDevice> self(new VulkanDevice());
  ++g_devices_created;
  self->validation_log_ = options.validation_log;

  // ---- instance
  bool validation = options.validation && has_layer(kValidationLayer);
  if (options.validation && !validation) {
    std::fprintf(stderr,
                 "glpt: GLPT_VALIDATION=1 but %s is not installed (apt-get install "
                 "vulkan-validationlayers); continuing without it\n",
                 kValidationLayer);
  }
  auto application = make_info<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  application.pApplicationName = "glpt";
  application.pEngineName = "glpt";
  application.apiVersion = VK_API_VERSION_1_3;

  auto messenger_info = make_info<VkDebugUtilsMessengerCreateInfoEXT>(
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  // Performance hints are left out: they mostly ask for optimal image layouts, and glpt keeps
  // every image in GENERAL on purpose (gpu_image.hpp).
  messenger_info.messageType =
      VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger_info.pfnUserCallback = &VulkanDevice::on_validation_message;
  messenger_info.pUserData = self.get();

  // Synchronization validation too: every stage is a separate submission, and a missing barrier
  // between them would go unnoticed on lavapipe, which runs submissions strictly in order.
  const VkValidationFeatureEnableEXT validation_features_enabled[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  auto validation_features = make_info<VkValidationFeaturesEXT>(
      VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &messenger_info);
  validation_features.enabledValidationFeatureCount = 1;
  validation_features.pEnabledValidationFeatures = validation_features_enabled;

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (validation) {
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);  // provided by the layer
  }
  auto instance_info = make_info<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  // The chained messenger also reports problems inside vkCreateInstance / vkDestroyInstance.
  instance_info.pNext = validation ? &validation_features : nullptr;
  instance_info.pApplicationInfo = &application;
  instance_info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  instance_info.ppEnabledLayerNames = layers.data();
  instance_info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  instance_info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&instance_info, nullptr, &instance);
  if (result != VK_SUCCESS) {
    throw DeviceUnavailable("glpt: no usable Vulkan device: cannot create a Vulkan instance (" +
                            vk_result_name(result) + "), is a Vulkan driver installed? " +
                            kInstallHint + " (" + kDoctorHint + ")");
  }
  self->instance_ = vk::Instance(instance, {});

  if (validation) {
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (create_messenger != nullptr && destroy_messenger != nullptr) {
      VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
      GLPT_VK_CHECK(create_messenger(instance, &messenger_info, nullptr, &messenger));
      self->messenger_ = vk::DebugMessenger(messenger, {instance, destroy_messenger});
    }
  }

  // ---- physical device
  uint32_t count = 0;
  GLPT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> physical_devices(count);
  GLPT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, physical_devices.data()));
  std::vector<Candidate> candidates;
  for (VkPhysicalDevice device : physical_devices) candidates.push_back(evaluate(device));
  if (options.hide_ray_query) hide_ray_queries(candidates);
  const Candidate& chosen = choose(candidates, options.name_filter);
  self->physical_device_ = chosen.device;
  self->sync_submissions_ = options.sync_submissions;
  self->name_ = chosen.name;

  auto as_properties = make_info<VkPhysicalDeviceAccelerationStructurePropertiesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR);
  auto properties = make_info<VkPhysicalDeviceProperties2>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
      chosen.missing_ray_query.empty() ? &as_properties : nullptr);
  vkGetPhysicalDeviceProperties2(chosen.device, &properties);
  self->limits_ = properties.properties.limits;
  self->properties_ = properties.properties;
  self->scratch_alignment_ =
      std::max<VkDeviceSize>(as_properties.minAccelerationStructureScratchOffsetAlignment, 1);
  vkGetPhysicalDeviceMemoryProperties(chosen.device, &self->memory_properties_);

  // ---- logical device: enable exactly what the shaders, pipelines and builders use
  self->ray_query_ = chosen.missing_ray_query.empty();
  self->ray_query_missing_ = join(chosen.missing_ray_query, ", ");
  self->geometry_shader_ = chosen.geometry_shader;
  const bool dynamic_blend = chosen.dynamic_blend && !options.hide_dynamic_blend;
  auto dynamic3 = make_info<VkPhysicalDeviceExtendedDynamicState3FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_3_FEATURES_EXT);
  dynamic3.extendedDynamicState3ColorBlendEnable = VK_TRUE;
  dynamic3.extendedDynamicState3ColorBlendEquation = VK_TRUE;
  dynamic3.extendedDynamicState3ColorWriteMask = VK_TRUE;
  dynamic3.extendedDynamicState3LogicOpEnable = VK_TRUE;
  auto dynamic2 = make_info<VkPhysicalDeviceExtendedDynamicState2FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_2_FEATURES_EXT, &dynamic3);
  dynamic2.extendedDynamicState2LogicOp = VK_TRUE;
  void* const dynamic_chain = dynamic_blend ? static_cast<void*>(&dynamic2) : nullptr;
  auto ray_query = make_info<VkPhysicalDeviceRayQueryFeaturesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR, dynamic_chain);
  ray_query.rayQuery = VK_TRUE;
  auto acceleration = make_info<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR, &ray_query);
  acceleration.accelerationStructure = VK_TRUE;
  auto provoking = make_info<VkPhysicalDeviceProvokingVertexFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
      self->ray_query_ ? static_cast<void*>(&acceleration) : dynamic_chain);
  provoking.provokingVertexLast = VK_TRUE;
  auto lines = make_info<VkPhysicalDeviceLineRasterizationFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT, &provoking);
  lines.bresenhamLines = VK_TRUE;
  lines.stippledBresenhamLines = VK_TRUE;
  // GL_LINE_SMOOTH draws Vulkan's smooth lines where the device has them (else Bresenham).
  lines.smoothLines = chosen.smooth_lines;
  lines.stippledSmoothLines = chosen.smooth_lines && chosen.stippled_smooth_lines;
  self->smooth_lines_ = chosen.smooth_lines;
  auto depth_clip = make_info<VkPhysicalDeviceDepthClipControlFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT, &lines);
  depth_clip.depthClipControl = VK_TRUE;
  auto border = make_info<VkPhysicalDeviceCustomBorderColorFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CUSTOM_BORDER_COLOR_FEATURES_EXT, &depth_clip);
  border.customBorderColors = VK_TRUE;
  border.customBorderColorWithoutFormat = VK_TRUE;
  auto vulkan13 = make_info<VkPhysicalDeviceVulkan13Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &border);
  vulkan13.dynamicRendering = VK_TRUE;
  vulkan13.synchronization2 = VK_TRUE;
  // SPIR-V 1.6 (Vulkan 1.3) states compute workgroup sizes with LocalSizeId, which needs this.
  vulkan13.maintenance4 = VK_TRUE;
  auto vulkan12 = make_info<VkPhysicalDeviceVulkan12Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &vulkan13);
  vulkan12.bufferDeviceAddress = VK_TRUE;
  vulkan12.timelineSemaphore = VK_TRUE;  // core in 1.2, required: tickets are its values
  const bool ordered_reads = chosen.ordered_framebuffer_reads && !options.hide_framebuffer_reads;
  auto order = make_info<VkPhysicalDeviceRasterizationOrderAttachmentAccessFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RASTERIZATION_ORDER_ATTACHMENT_ACCESS_FEATURES_EXT,
      vulkan12.pNext);
  order.rasterizationOrderColorAttachmentAccess = VK_TRUE;
  if (ordered_reads) {
    vulkan12.pNext = &order;
    vulkan12.imagelessFramebuffer = VK_TRUE;
  }
  self->ordered_framebuffer_reads_ = ordered_reads;
  auto features =
      make_info<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &vulkan12);
  features.features.fillModeNonSolid = VK_TRUE;
  features.features.wideLines = VK_TRUE;
  features.features.largePoints = VK_TRUE;
  features.features.logicOp = VK_TRUE;
  features.features.shaderClipDistance = VK_TRUE;
  features.features.independentBlend = VK_TRUE;
  features.features.occlusionQueryPrecise = chosen.precise_occlusion_queries ? VK_TRUE : VK_FALSE;
  self->precise_occlusion_queries_ = chosen.precise_occlusion_queries;
  features.features.geometryShader = chosen.geometry_shader ? VK_TRUE : VK_FALSE;
  features.features.shaderTessellationAndGeometryPointSize = features.features.geometryShader;
  const VkBool32 path_traced = chosen.missing_ray_query.empty() ? VK_TRUE : VK_FALSE;
  features.features.shaderStorageImageReadWithoutFormat = path_traced;
  features.features.shaderStorageImageWriteWithoutFormat = path_traced;
  vulkan12.shaderSampledImageArrayNonUniformIndexing = path_traced;

  std::vector<const char*> device_extensions(std::begin(kRasterDeviceExtensions),
                                             std::end(kRasterDeviceExtensions));
  if (chosen.external_host_memory) {
    device_extensions.push_back(VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME);
    self->external_host_memory_ = true;
    auto host_properties = make_info<VkPhysicalDeviceExternalMemoryHostPropertiesEXT>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTERNAL_MEMORY_HOST_PROPERTIES_EXT);
    auto properties2 = make_info<VkPhysicalDeviceProperties2>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &host_properties);
    vkGetPhysicalDeviceProperties2(chosen.device, &properties2);
    self->host_pointer_alignment_ = host_properties.minImportedHostPointerAlignment;
  }
  if (self->ray_query_) {
    device_extensions.insert(device_extensions.end(), std::begin(kRayQueryDeviceExtensions),
                             std::end(kRayQueryDeviceExtensions));
  }
  if (dynamic_blend) {
    device_extensions.insert(device_extensions.end(), std::begin(kDynamicBlendDeviceExtensions),
                             std::end(kDynamicBlendDeviceExtensions));
  }
  if (ordered_reads) {
    device_extensions.insert(device_extensions.end(), std::begin(kOrderedFramebufferReadExtensions),
                             std::end(kOrderedFramebufferReadExtensions));
  }

  float priority = 1.0f;
  auto queue_info = make_info<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue_info.queueFamilyIndex = chosen.queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  auto device_info = make_info<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  device_info.pNext = &features;  // pEnabledFeatures stays null when features are chained
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  device_info.enabledExtensionCount = static_cast<uint32_t>(device_extensions.size());
  device_info.ppEnabledExtensionNames = device_extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateDevice(chosen.device, &device_info, nullptr, &device));
  self->device_ = vk::Device(device, {});
  self->queue_family_ = chosen.queue_family;
  vkGetDeviceQueue(device, chosen.queue_family, 0, &self->queue_);

  auto load = [&](const char* name) {
    PFN_vkVoidFunction function = vkGetDeviceProcAddr(device, name);
    if (function == nullptr)
      throw VulkanError(std::string("vkGetDeviceProcAddr(") + name + ") failed");
    return function;
  };
  if (dynamic_blend) {
    auto& blend = self->dynamic_blend_;
    blend.set_enable =
        reinterpret_cast<PFN_vkCmdSetColorBlendEnableEXT>(load("vkCmdSetColorBlendEnableEXT"));
    blend.set_equation =
        reinterpret_cast<PFN_vkCmdSetColorBlendEquationEXT>(load("vkCmdSetColorBlendEquationEXT"));
    blend.set_write_mask =
        reinterpret_cast<PFN_vkCmdSetColorWriteMaskEXT>(load("vkCmdSetColorWriteMaskEXT"));
    blend.set_logic_op_enable =
        reinterpret_cast<PFN_vkCmdSetLogicOpEnableEXT>(load("vkCmdSetLogicOpEnableEXT"));
    blend.set_logic_op = reinterpret_cast<PFN_vkCmdSetLogicOpEXT>(load("vkCmdSetLogicOpEXT"));
  }
  if (self->ray_query_) {
    auto& as = self->as_functions_;
    as.create = reinterpret_cast<PFN_vkCreateAccelerationStructureKHR>(
        load("vkCreateAccelerationStructureKHR"));
    as.destroy = reinterpret_cast<PFN_vkDestroyAccelerationStructureKHR>(
        load("vkDestroyAccelerationStructureKHR"));
    as.get_build_sizes = reinterpret_cast<PFN_vkGetAccelerationStructureBuildSizesKHR>(
        load("vkGetAccelerationStructureBuildSizesKHR"));
    as.cmd_build = reinterpret_cast<PFN_vkCmdBuildAccelerationStructuresKHR>(
        load("vkCmdBuildAccelerationStructuresKHR"));
    as.get_device_address = reinterpret_cast<PFN_vkGetAccelerationStructureDeviceAddressKHR>(
        load("vkGetAccelerationStructureDeviceAddressKHR"));
  }

  // ---- the submission ring: a command buffer and fence per slot, two timestamps per slot
  auto pool_info = make_info<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool_info.flags =
      VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT | VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_info.queueFamilyIndex = chosen.queue_family;
  VkCommandPool pool = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateCommandPool(device, &pool_info, nullptr, &pool));
  self->command_pool_ = vk::CommandPool(pool, {device});

  auto allocate_info =
      make_info<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  allocate_info.commandPool = pool;
  allocate_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate_info.commandBufferCount = 1;
  auto fence_info = make_info<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  for (SubmissionSlot& slot : self->slots_) {
    GLPT_VK_CHECK(vkAllocateCommandBuffers(device, &allocate_info, &slot.cmd));
    VkFence fence = VK_NULL_HANDLE;
    GLPT_VK_CHECK(vkCreateFence(device, &fence_info, nullptr, &fence));
    slot.fence = vk::Fence(fence, {device});
  }
  // Signalled with each ticket: a thread waits for a ticket without holding the submission lock
  // (a fence is reset when its slot completes, so only the lock holder may wait on one).
  auto timeline_type =
      make_info<VkSemaphoreTypeCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO);
  timeline_type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
  timeline_type.initialValue = 0;
  auto semaphore_info =
      make_info<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, &timeline_type);
  VkSemaphore timeline = VK_NULL_HANDLE;
  GLPT_VK_CHECK(vkCreateSemaphore(device, &semaphore_info, nullptr, &timeline));
  self->timeline_ = vk::Semaphore(timeline, {device});

  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(self->physical_device_, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(self->physical_device_, &family_count, families.data());
  const uint32_t valid_bits =
      chosen.queue_family < family_count ? families[chosen.queue_family].timestampValidBits : 0;
  if (options.timestamps && valid_bits > 0 && self->limits_.timestampPeriod > 0.0f) {
    auto query_info = make_info<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    query_info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    query_info.queryCount = 2 * kSubmissionSlots;
    VkQueryPool queries = VK_NULL_HANDLE;
    GLPT_VK_CHECK(vkCreateQueryPool(device, &query_info, nullptr, &queries));
    self->timestamps_ = vk::QueryPool(queries, {device});
    self->timestamp_period_ns_ = self->limits_.timestampPeriod;
    self->timestamp_mask_ = valid_bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << valid_bits) - 1;
  }
  // Registered after the driver (and LLVM) loaded, so it runs before their teardown at exit.
  static std::once_flag exit_handler;
  std::call_once(exit_handler, [] { std::atexit(mark_process_exiting); });
  return self;
}

VulkanDevice::~VulkanDevice() {
  // Nothing may be in flight when the members below start destroying objects.
  if (device_) vkDeviceWaitIdle(device_.get());
}

uint32_t VulkanDevice::memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
  uint32_t fallback = UINT32_MAX;
  for (uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i) {
    VkMemoryPropertyFlags flags = memory_properties_.memoryTypes[i].propertyFlags;
    if (!(type_bits & (1u << i)) || (flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback == UINT32_MAX) fallback = i;
  }
  if (fallback == UINT32_MAX) throw VulkanError("no Vulkan memory type with the required flags");
  return fallback;
}

std::shared_ptr<VulkanDevice> VulkanDevice::shared(const DeviceOptions& options) {
  // Process-wide by nature (the issue is "one device per process"): weak references, so the
  // device goes when its last renderer does. A forked child never reuses its parent's device,
  // whose lavapipe threads exist only in the parent (gl_shim/process_owner.hpp).
  struct Entry {
    DeviceOptions options;
    pid_t process;
    std::weak_ptr<VulkanDevice> device;
  };
  static std::mutex mutex;
  static std::vector<Entry> devices;
  std::lock_guard lock(mutex);
  std::erase_if(devices, [](const Entry& e) { return e.device.expired(); });
  for (const Entry& e : devices)
    if (e.options == options && e.process == ::getpid())
      if (std::shared_ptr<VulkanDevice> device = e.device.lock()) return device;
  std::shared_ptr<VulkanDevice> device = create(options);
  devices.push_back({options, ::getpid(), device});
  return device;
}

namespace {

double now_ms() {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

VulkanDevice::Ticket VulkanDevice::submit(const std::function<void(VkCommandBuffer)>& record) {
  std::lock_guard lock(submit_mutex_);
  const Ticket ticket = last_ticket_ + 1;
  const size_t index = ticket % kSubmissionSlots;
  SubmissionSlot& slot = slots_[index];
  if (slot.ticket != 0) {
    ++host_waits_;
    // The slot's previous ticket, and so every ticket before it, must be complete first.
    for (Ticket t = completed_ticket_ + 1; t <= slot.ticket; ++t)
      complete_locked(slots_[t % kSubmissionSlots]);
  }
  VkCommandBuffer cmd = slot.cmd;
  GLPT_VK_CHECK(vkResetCommandBuffer(cmd, 0));
  auto begin = make_info<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GLPT_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  const auto first_query = static_cast<uint32_t>(2 * index);
  if (timestamps_) {
    vkCmdResetQueryPool(cmd, timestamps_.get(), first_query, 2);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_.get(), first_query);
  }

  // Submissions are few and large (a pass, a BLAS batch, the TLAS), so one global barrier each
  // way costs nothing and keeps every cross-submission hazard covered.
  auto before = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  before.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                       VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
  record(cmd);
  auto after = make_info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  after.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       VK_PIPELINE_STAGE_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &after, 0, nullptr, 0, nullptr);
  if (timestamps_)
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_.get(),
                        first_query + 1);
  GLPT_VK_CHECK(vkEndCommandBuffer(cmd));

  auto timeline_info =
      make_info<VkTimelineSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO);
  timeline_info.signalSemaphoreValueCount = 1;
  timeline_info.pSignalSemaphoreValues = &ticket;
  auto submit_info = make_info<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO, &timeline_info);
  submit_info.commandBufferCount = 1;
  submit_info.pCommandBuffers = &cmd;
  const VkSemaphore timeline = timeline_.get();
  submit_info.signalSemaphoreCount = 1;
  submit_info.pSignalSemaphores = &timeline;
  GLPT_VK_CHECK(vkQueueSubmit(queue_, 1, &submit_info, slot.fence.get()));
  slot.ticket = ticket;
  slot.submitted_at_ms = now_ms();
  last_ticket_ = ticket;
  if (sync_submissions_) {
    ++host_waits_;
    for (Ticket t = completed_ticket_ + 1; t <= ticket; ++t)
      complete_locked(slots_[t % kSubmissionSlots]);
  }
  return ticket;
}

void VulkanDevice::complete_locked(SubmissionSlot& slot) {
  if (slot.ticket == 0) return;
  VkFence fence = slot.fence.get();
  GLPT_VK_CHECK(vkWaitForFences(handle(), 1, &fence, VK_TRUE, UINT64_MAX));
  double device_ms = now_ms() - slot.submitted_at_ms;
  if (timestamps_) {
    uint64_t stamps[2] = {0, 0};
    const auto first_query = static_cast<uint32_t>(2 * (&slot - slots_.data()));
    if (vkGetQueryPoolResults(handle(), timestamps_.get(), first_query, 2, sizeof stamps, stamps,
                              sizeof(uint64_t), VK_QUERY_RESULT_64_BIT) == VK_SUCCESS)
      device_ms = double((stamps[1] - stamps[0]) & timestamp_mask_) * timestamp_period_ns_ * 1e-6;
  }
  GLPT_VK_CHECK(vkResetFences(handle(), 1, &fence));
  // The slot is free and its ticket complete before anything that can throw: a failure below
  // must not leave a reset fence that a later wait would block on for ever.
  const Ticket ticket = slot.ticket;
  slot.ticket = 0;
  completed_ticket_ = std::max(completed_ticket_, ticket);
  try {
    finished_ms_[ticket] = device_ms;
    // Times nobody takes (submissions whose callers do not report them) are kept for a while.
    while (finished_ms_.size() > 4 * kSubmissionSlots) finished_ms_.erase(finished_ms_.begin());
  } catch (const std::bad_alloc&) {
    // Out of memory: the ticket's time is not reported; nothing else depends on it.
  }
}

void VulkanDevice::wait(Ticket ticket) {
  {
    std::lock_guard lock(submit_mutex_);
    ticket = std::min(ticket, last_ticket_);
    if (ticket <= completed_ticket_) return;
    ++host_waits_;
  }
  // Blocks without the lock: other threads submit meanwhile (a presenting thread waits for a
  // frame while the program's thread records the next).
  auto wait_info = make_info<VkSemaphoreWaitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO);
  const VkSemaphore timeline = timeline_.get();
  wait_info.semaphoreCount = 1;
  wait_info.pSemaphores = &timeline;
  wait_info.pValues = &ticket;
  GLPT_VK_CHECK(vkWaitSemaphores(handle(), &wait_info, UINT64_MAX));
  std::lock_guard lock(submit_mutex_);
  // In ticket order: a fence covers its own submission only. Their submissions have finished,
  // so these waits end at once.
  for (Ticket t = completed_ticket_ + 1; t <= ticket; ++t)
    complete_locked(slots_[t % kSubmissionSlots]);
}

VulkanDevice::Ticket VulkanDevice::completed_ticket() {
  std::lock_guard lock(submit_mutex_);
  for (Ticket t = completed_ticket_ + 1; t <= last_ticket_; ++t) {
    SubmissionSlot& slot = slots_[t % kSubmissionSlots];
    if (vkGetFenceStatus(handle(), slot.fence.get()) != VK_SUCCESS) break;
    complete_locked(slot);  // signalled: does not block
  }
  return completed_ticket_;
}

VulkanDevice::Ticket VulkanDevice::last_ticket() const {
  std::lock_guard lock(submit_mutex_);
  return last_ticket_;
}

double VulkanDevice::take_device_ms(Ticket ticket) {
  std::lock_guard lock(submit_mutex_);
  auto found = finished_ms_.find(ticket);
  if (found == finished_ms_.end()) return 0.0;
  const double ms = found->second;
  finished_ms_.erase(found);
  return ms;
}

double VulkanDevice::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  const Ticket ticket = submit(record);
  wait(ticket);
  return take_device_ms(ticket);
}

}  // namespace glpt::rt
