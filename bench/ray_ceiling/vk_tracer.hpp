// The raw ray-query side of bench/ray_ceiling: a headless Vulkan device (lavapipe preferred),
// BLASes and a TLAS built from an AccelInput (PREFER_FAST_TRACE, opaque, culling off, like
// glpt's), and trace.comp dispatched over a ray buffer. Adapted from the rqprobe feasibility
// probe (shared/reference/rqprobe).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rays.hpp"

namespace ray_ceiling {

class VkTracer {
 public:
  VkTracer();  // throws std::runtime_error when no device with ray queries is found
  ~VkTracer();
  VkTracer(const VkTracer&) = delete;
  VkTracer& operator=(const VkTracer&) = delete;

  std::string device_description() const;
  // (Re)builds every BLAS and the TLAS; returns the build's wall time in ms.
  double build(const AccelInput& input);
  // Traces `rays` once per repetition (one dispatch each); returns each dispatch's wall time of
  // vkQueueSubmit + vkWaitForFences in ms, and the last dispatch's hits.
  std::vector<double> trace(const std::vector<Ray>& rays, int repetitions, std::vector<Hit>& hits);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ray_ceiling
