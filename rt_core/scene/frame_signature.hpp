// Everything a rendered image depends on, for deciding whether a frame may be accumulated onto
// the previous one: geometry identities, transforms, lights, projection, viewport, size, clear
// colour and ambient.
#pragma once

#include <cstdint>
#include <vector>

#include "rt_core/scene/trace_scene.hpp"

namespace glpt::rt {

class FrameSignature {
 public:
  FrameSignature() = default;  // equal to no frame's signature
  explicit FrameSignature(const TraceScene& frame);

  bool operator==(const FrameSignature& other) const = default;

 private:
  bool valid_ = false;
  // All values as raw bits: exact comparison, and NaNs compare equal to themselves instead of
  // restarting accumulation on every frame.
  std::vector<uint32_t> words_;
};

}  // namespace glpt::rt
