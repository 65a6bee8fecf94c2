// The path tracer: renders a TraceScene (scene/trace_scene.hpp) with Vulkan ray queries.
//
// Not thread-safe: one PathTracer is used by one thread at a time (the GL context's). No exception
// leaves this API; failures come back as nullptr / false with a message.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rt_core/frame_stats.hpp"
#include "rt_core/render_settings.hpp"
#include "rt_core/scene/trace_scene.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

class PathTracer {
 public:
  // nullptr + a message in *error when `device` has no ray queries (or creation failed).
  static std::unique_ptr<PathTracer> create(std::shared_ptr<VulkanDevice> device,
                                            const RenderSettings& settings, std::string* error);
  // The same on a device of its own (tests and benchmarks of the tracer alone).
  // GLPT_VK_DEVICE=substring selects the device by name.
  static std::unique_ptr<PathTracer> create(const RenderSettings& settings, std::string* error);
  ~PathTracer();
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  // Renders `frame` into `rgba` (resized to width*height*4, RGBA8, rows bottom-to-top like
  // glReadPixels). Returns false (and a message in *error) on a Vulkan failure; never throws.
  bool render(const TraceScene& frame, std::vector<uint8_t>& rgba, FrameStats& stats,
              std::string* error);
  const std::string& device_name() const;

 private:
  class Impl;
  explicit PathTracer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace glpt::rt
