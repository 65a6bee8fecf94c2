// The CPU ceiling of bench/ray_ceiling: Embree 3 over the same triangles (one geometry per
// instance, its transform applied, its mask as the geometry mask), rtcIntersect1 for closest-hit
// rays and rtcOccluded1 for shadow rays, on `threads` std::threads.
#pragma once

#include <string>
#include <vector>

#include "rays.hpp"

namespace ray_ceiling {

class EmbreeTracer {
 public:
  explicit EmbreeTracer(unsigned threads);
  ~EmbreeTracer();
  EmbreeTracer(const EmbreeTracer&) = delete;
  EmbreeTracer& operator=(const EmbreeTracer&) = delete;

  std::string description() const;
  bool masks_supported() const;
  double build(const AccelInput& input);  // ms of rtcCommitScene
  // Hits use the Vulkan side's numbering: instance = geometry = AccelInput instance, primitive =
  // its primitive. Shadow rays that hit report t = their tmax (Embree does not say where).
  std::vector<double> trace(const std::vector<Ray>& rays, int repetitions, std::vector<Hit>& hits);

 private:
  void* device_ = nullptr;  // RTCDevice
  void* scene_ = nullptr;   // RTCScene
  unsigned threads_;
};

}  // namespace ray_ceiling
