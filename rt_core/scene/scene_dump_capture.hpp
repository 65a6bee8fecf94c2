// GLPT_DUMP_SCENE=FILE: the path tracer writes the world of one traced frame to FILE
// (scene_dump.hpp has the format): GLPT_DUMP_SCENE_FRAME=N picks the Nth trace that adds samples
// (1-based, default 3: past the first frames' pipeline compiles and BLAS builds). Nothing is
// captured, and nothing costs more than a flag test, when GLPT_DUMP_SCENE is unset.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>

#include "rt_core/accel/blas_cache.hpp"
#include "rt_core/frame_stats.hpp"
#include "rt_core/scene/scene_dump.hpp"
#include "rt_core/scene/trace_scene.hpp"
#include "shared_types.h"

namespace glpt::rt {

class SceneDumpCapture {
 public:
  // Reads GLPT_DUMP_SCENE and GLPT_DUMP_SCENE_FRAME.
  SceneDumpCapture();

  // Called once per trace that adds samples: whether this is the one to capture.
  bool wanted() {
    if (path_.empty() || done_) return false;
    return ++traces_ == target_;
  }
  // Takes the frame's world as the TLAS gets it: `instances` in TLAS order with their final
  // masks, each instance's BLAS found in `blases` through the geometries of `scene`.
  void capture(const TraceScene& scene,
               std::span<const VkAccelerationStructureInstanceKHR> instances,
               const BlasCache& blases, std::span<const gpu::GpuLight> lights,
               const gpu::FrameUniforms& uniforms, uint64_t frame_number);
  // After the frame completed: adds the trace pass's rays and device time and writes the file
  // (one line on stderr either way).
  void finish(const FrameStats& stats);

 private:
  std::string path_;
  uint64_t target_ = 3;
  uint64_t traces_ = 0;
  bool captured_ = false;
  bool done_ = false;
  SceneDump dump_;
};

}  // namespace glpt::rt
