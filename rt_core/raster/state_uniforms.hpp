// A state snapshot -> the uniform data the fixed-function raster shaders read (RasterState in
// shaders/raster_types.h), computed once per snapshot of a record.
#pragma once

#include <glm/glm.hpp>

#include "raster_types.h"
#include "rt_core/record/frame_record.hpp"

namespace glpt::rt {

void pack_state_uniforms(const rec::StateSnapshot& state, gpu::RasterState& out);
// One material as the shaders read it (also per vertex: RasterPushConstants::materials).
gpu::RasterMaterial pack_material(const rec::Material& m);

}  // namespace glpt::rt
