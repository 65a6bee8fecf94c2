// Derives the path tracer's scene (TraceScene) from a frame record: which draws are traced, their
// triangles (decomposed as GL assembles them), materials resolved from the state snapshots, the
// camera and the lights.
//
// Interim policy, until draw classification lands: the "main camera" is the projection and
// viewport under which the most triangles are drawn; triangle draws under it are traced; the
// lights are those of the first lit traced draw. Everything else (points, lines, draws under other
// projections) is left to the raster pipelines (`overlay` lists them, in record order).
#pragma once

#include <cstddef>
#include <vector>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/scene/trace_scene.hpp"

namespace glpt::rt {

struct SceneBuild {
  TraceScene scene;
  std::vector<size_t> traced;   // indices of the traced Draw commands
  std::vector<size_t> overlay;  // indices of commands the tracer does not take
};

void build_trace_scene(const rec::FrameRecord& record, uint32_t width, uint32_t height,
                       SceneBuild& out);

}  // namespace glpt::rt
