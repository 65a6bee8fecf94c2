#include "replay/window_view.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace glpt::replay {
namespace {

struct Keys {
  bool paused = false;
  bool step = false;
  bool quit = false;
};

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  Keys& keys = *static_cast<Keys*>(glfwGetWindowUserPointer(window));
  if (key == GLFW_KEY_SPACE && action == GLFW_PRESS) keys.paused = !keys.paused;
  if (key == GLFW_KEY_N || key == GLFW_KEY_RIGHT) {
    keys.paused = true;
    keys.step = true;
  }
  if (key == GLFW_KEY_Q || key == GLFW_KEY_ESCAPE) keys.quit = true;
}

bool check(VkResult result, const char* what, std::string* error) {
  if (result == VK_SUCCESS) return true;
  *error = std::string("--window: ") + what + " failed (VkResult " + std::to_string(result) + ")";
  return false;
}

}  // namespace

class WindowView::Impl {
 public:
  ~Impl() {
    if (device_ != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      destroy_swapchain();
      if (fence_) vkDestroyFence(device_, fence_, nullptr);
      if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
      if (staging_) vkDestroyBuffer(device_, staging_, nullptr);
      if (staging_memory_) vkFreeMemory(device_, staging_memory_, nullptr);
      vkDestroyDevice(device_, nullptr);
    }
    if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
    if (instance_) vkDestroyInstance(instance_, nullptr);
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
  }

  bool init(std::string* error) {
    if (glfwInit() != GLFW_TRUE) {
      const char* description = nullptr;
      glfwGetError(&description);
      *error = std::string("--window: cannot open a window (") +
               (description ? description : "no display") + ")";
      return false;
    }
    if (glfwVulkanSupported() != GLFW_TRUE) {
      *error = "--window: no Vulkan loader for windows";
      return false;
    }
    uint32_t count = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&count);
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "glpt-replay";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pApplicationInfo = &app;
    info.enabledExtensionCount = count;
    info.ppEnabledExtensionNames = extensions;
    return check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance", error);
  }

  bool show(const FrameImage& image, uint64_t frame, std::string* error) {
    if (window_ == nullptr && !open(image.width, image.height, error)) return false;
    char title[96];
    std::snprintf(title, sizeof title, "glpt-replay: frame %llu",
                  static_cast<unsigned long long>(frame));
    glfwSetWindowTitle(window_, title);
    if (!present(image, error)) return false;
    keys_.step = false;
    glfwPollEvents();
    while (keys_.paused && !keys_.step && !quit_requested()) {
      glfwSetWindowTitle(window_, (std::string(title) + " (paused)").c_str());
      glfwWaitEvents();
    }
    return !quit_requested();
  }

  void pause() { keys_.paused = true; }

  bool quit_requested() const {
    return keys_.quit || (window_ != nullptr && glfwWindowShouldClose(window_));
  }

 private:
  bool open(uint32_t width, uint32_t height, std::string* error) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(static_cast<int>(width), static_cast<int>(height), "glpt-replay",
                               nullptr, nullptr);
    if (window_ == nullptr) {
      *error = "--window: glfwCreateWindow failed";
      return false;
    }
    glfwSetWindowUserPointer(window_, &keys_);
    glfwSetKeyCallback(window_, on_key);
    if (!check(glfwCreateWindowSurface(instance_, window_, nullptr, &surface_),
               "glfwCreateWindowSurface", error))
      return false;
    // The first device with a queue that can both copy and present to the window.
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance_, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance_, &count, devices.data());
    for (VkPhysicalDevice d : devices) {
      uint32_t families = 0;
      vkGetPhysicalDeviceQueueFamilyProperties(d, &families, nullptr);
      std::vector<VkQueueFamilyProperties> props(families);
      vkGetPhysicalDeviceQueueFamilyProperties(d, &families, props.data());
      for (uint32_t f = 0; f < families && physical_ == VK_NULL_HANDLE; ++f) {
        VkBool32 present = VK_FALSE;
        vkGetPhysicalDeviceSurfaceSupportKHR(d, f, surface_, &present);
        if (present && (props[f].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
          physical_ = d;
          family_ = f;
        }
      }
    }
    if (physical_ == VK_NULL_HANDLE) {
      *error = "--window: no Vulkan device can present to the window";
      return false;
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{};
    queue.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue.queueFamilyIndex = family_;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    const char* swapchain_extension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    VkDeviceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &swapchain_extension;
    if (!check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice", error))
      return false;
    vkGetDeviceQueue(device_, family_, 0, &queue_);
    VkCommandPoolCreateInfo pool{};
    pool.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = family_;
    if (!check(vkCreateCommandPool(device_, &pool, nullptr, &pool_), "vkCreateCommandPool", error))
      return false;
    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkFenceCreateInfo fence{};
    fence.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    return check(vkAllocateCommandBuffers(device_, &alloc, &commands_), "vkAllocateCommandBuffers",
                 error) &&
           check(vkCreateFence(device_, &fence, nullptr, &fence_), "vkCreateFence", error) &&
           create_swapchain(error);
  }

  bool create_swapchain(std::string* error) {
    VkSurfaceCapabilitiesKHR caps{};
    vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical_, surface_, &caps);
    uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(physical_, surface_, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(physical_, surface_, &count, formats.data());
    if (formats.empty()) {
      *error = "--window: the surface has no formats";
      return false;
    }
    format_ = formats[0];
    for (const VkSurfaceFormatKHR& f : formats)
      if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) format_ = f;
    extent_ = caps.currentExtent;
    if (extent_.width == UINT32_MAX) {
      int w = 0, h = 0;
      glfwGetFramebufferSize(window_, &w, &h);
      extent_ = {static_cast<uint32_t>(std::max(w, 1)), static_cast<uint32_t>(std::max(h, 1))};
    }
    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = surface_;
    info.minImageCount = caps.maxImageCount == 0
                             ? caps.minImageCount + 1
                             : std::min(caps.minImageCount + 1, caps.maxImageCount);
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    if (!check(vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR",
               error))
      return false;
    vkGetSwapchainImagesKHR(device_, swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(device_, swapchain_, &count, images_.data());
    return true;
  }

  void destroy_swapchain() {
    if (swapchain_) vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    images_.clear();
  }

  bool ensure_staging(size_t bytes, std::string* error) {
    if (bytes <= staging_size_) return true;
    if (staging_) vkDestroyBuffer(device_, staging_, nullptr);
    if (staging_memory_) vkFreeMemory(device_, staging_memory_, nullptr);
    staging_ = VK_NULL_HANDLE;
    staging_memory_ = VK_NULL_HANDLE;
    staging_size_ = 0;
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = bytes;
    info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    if (!check(vkCreateBuffer(device_, &info, nullptr, &staging_), "vkCreateBuffer", error))
      return false;
    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(device_, staging_, &req);
    VkPhysicalDeviceMemoryProperties props{};
    vkGetPhysicalDeviceMemoryProperties(physical_, &props);
    const VkMemoryPropertyFlags want =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkMemoryAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = UINT32_MAX;
    for (uint32_t i = 0; i < props.memoryTypeCount && alloc.memoryTypeIndex == UINT32_MAX; ++i)
      if ((req.memoryTypeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & want) == want)
        alloc.memoryTypeIndex = i;
    if (alloc.memoryTypeIndex == UINT32_MAX) {
      *error = "--window: no host-visible memory";
      return false;
    }
    if (!check(vkAllocateMemory(device_, &alloc, nullptr, &staging_memory_), "vkAllocateMemory",
               error) ||
        !check(vkBindBufferMemory(device_, staging_, staging_memory_, 0), "vkBindBufferMemory",
               error))
      return false;
    staging_size_ = bytes;
    return true;
  }

  bool present(const FrameImage& image, std::string* error) {
    for (int attempt = 0; attempt < 2; ++attempt) {
      uint32_t index = 0;
      VkResult r =
          vkAcquireNextImageKHR(device_, swapchain_, UINT64_MAX, VK_NULL_HANDLE, fence_, &index);
      if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        if (!recreate(error)) return false;
        continue;
      }
      if (r != VK_SUBOPTIMAL_KHR && !check(r, "vkAcquireNextImageKHR", error)) return false;
      vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
      vkResetFences(device_, 1, &fence_);
      if (!copy_to(image, images_[index], error)) return false;
      VkPresentInfoKHR info{};
      info.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
      info.swapchainCount = 1;
      info.pSwapchains = &swapchain_;
      info.pImageIndices = &index;
      r = vkQueuePresentKHR(queue_, &info);
      if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return recreate(error);
      return check(r, "vkQueuePresentKHR", error);
    }
    return true;
  }

  bool recreate(std::string* error) {
    vkDeviceWaitIdle(device_);
    destroy_swapchain();
    return create_swapchain(error);
  }

  // The frame (RGBA, rows bottom to top) into the swapchain image's top-left corner, upright,
  // in its byte order; the rest of the window black.
  bool copy_to(const FrameImage& image, VkImage target, std::string* error) {
    const uint32_t w = std::min(image.width, extent_.width);
    const uint32_t h = std::min(image.height, extent_.height);
    if (!ensure_staging(std::max<size_t>(size_t{w} * h * 4, 4), error)) return false;
    uint8_t* mapped = nullptr;
    if (!check(vkMapMemory(device_, staging_memory_, 0, VK_WHOLE_SIZE, 0,
                           reinterpret_cast<void**>(&mapped)),
               "vkMapMemory", error))
      return false;
    const bool bgra =
        format_.format == VK_FORMAT_B8G8R8A8_UNORM || format_.format == VK_FORMAT_B8G8R8A8_SRGB;
    for (uint32_t y = 0; y < h; ++y) {
      const uint8_t* src = image.rgba.data() + size_t{image.height - 1 - y} * image.width * 4;
      uint8_t* dst = mapped + size_t{y} * w * 4;
      for (uint32_t x = 0; x < w; ++x, src += 4, dst += 4) {
        dst[0] = bgra ? src[2] : src[0];
        dst[1] = src[1];
        dst[2] = bgra ? src[0] : src[2];
        dst[3] = 255;
      }
    }
    vkUnmapMemory(device_, staging_memory_);

    vkResetCommandBuffer(commands_, 0);
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(commands_, &begin);
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = target;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &barrier);
    const VkClearColorValue black{};
    vkCmdClearColorImage(commands_, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1,
                         &barrier.subresourceRange);
    VkMemoryBarrier clear_then_copy{};
    clear_then_copy.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    clear_then_copy.srcAccessMask = clear_then_copy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         0, 1, &clear_then_copy, 0, nullptr, 0, nullptr);
    if (w > 0 && h > 0) {
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {w, h, 1};
      vkCmdCopyBufferToImage(commands_, staging_, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                             &region);
    }
    barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = 0;
    vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0, nullptr, 1,
                         &barrier);
    vkEndCommandBuffer(commands_);
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands_;
    if (!check(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit", error)) return false;
    vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
    vkResetFences(device_, 1, &fence_);
    return true;
  }

  Keys keys_;
  GLFWwindow* window_ = nullptr;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  uint32_t family_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkSurfaceFormatKHR format_{};
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  VkBuffer staging_ = VK_NULL_HANDLE;
  VkDeviceMemory staging_memory_ = VK_NULL_HANDLE;
  size_t staging_size_ = 0;
};

std::unique_ptr<WindowView> WindowView::create(std::string* error) {
  auto impl = std::make_unique<Impl>();
  if (!impl->init(error)) return nullptr;
  return std::unique_ptr<WindowView>(new WindowView(std::move(impl)));
}

WindowView::WindowView(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
WindowView::~WindowView() = default;

bool WindowView::show(const FrameImage& image, uint64_t frame, std::string* error) {
  return impl_->show(image, frame, error);
}

bool WindowView::quit_requested() const { return impl_->quit_requested(); }
void WindowView::pause() { impl_->pause(); }

}  // namespace glpt::replay
