// Public entry point of the path tracer: renders a Frame (see frame.hpp) with Vulkan ray queries.
//
// Not thread-safe: one Renderer is used by one thread at a time (the GL context's). No exception
// leaves this API; failures come back as nullptr / false with a message.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rt_core/frame.hpp"
#include "rt_core/render_settings.hpp"

namespace glpt::rt {

struct FrameStats {
  // Wall-clock milliseconds per stage (host work, or submit + wait of the GPU work).
  double upload_ms = 0, blas_ms = 0, tlas_ms = 0, trace_ms = 0, readback_ms = 0;
  uint32_t blas_builds = 0, blas_reused = 0;
  // `rays`: rays actually traced this frame (primary + shadow + bounce), counted on the GPU.
  uint64_t triangles = 0, rays = 0;
  // Samples per pixel in the image now shown.
  uint32_t accumulated_samples = 0;
};

class Renderer {
 public:
  // nullptr + one clear message in *error when no Vulkan device with VK_KHR_ray_query and
  // VK_KHR_acceleration_structure exists (it names what is missing and how to install it).
  // GLPT_VK_DEVICE=substring selects the device by name.
  static std::unique_ptr<Renderer> create(const RenderSettings& settings, std::string* error);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders `frame` into `rgba` (resized to width*height*4, RGBA8, rows bottom-to-top like
  // glReadPixels). Returns false (and a message in *error) on a Vulkan failure; never throws.
  bool render(const Frame& frame, std::vector<uint8_t>& rgba, FrameStats& stats,
              std::string* error);
  const std::string& device_name() const;

 private:
  class Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace glpt::rt
