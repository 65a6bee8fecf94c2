// What the contexts of one share group (GLX share_list, EGL share_context) render with: one
// rt::Renderer, so the GPU copies of their shared textures, their pipelines and the acceleration
// structures of their shared display lists are made once for all of them. The Vulkan device under
// it is the process's (rt::VulkanDevice::shared), whatever the group.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "rt_core/renderer.hpp"

namespace glpt {

class RenderGroup {
 public:
  // The group's renderer, created by the first context that needs it; nullptr and a message in
  // *error (and in *notice, e.g. no ray queries, only for the call that created it) if not.
  // Thread-safe: contexts of the group may be current on several threads.
  std::shared_ptr<rt::Renderer> renderer(std::string* error, std::string* notice);

 private:
  std::mutex mutex_;
  std::shared_ptr<rt::Renderer> renderer_;
};

}  // namespace glpt
