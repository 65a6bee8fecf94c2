// A state snapshot -> the uniform data the fixed-function raster shaders read (RasterState in
// shaders/raster_types.h), computed once per snapshot of a record.
#pragma once

#include <glm/glm.hpp>

#include "raster_types.h"
#include "rt_core/record/frame_record.hpp"

namespace glpt::rt {

// projection * modelview with Mesa's float arithmetic and operation order (matmul4: each element
// a0j*b... summed left to right), so clip coordinates match Mesa's to the bit.
glm::mat4 multiply_like_mesa(const glm::mat4& a, const glm::mat4& b);

void pack_state_uniforms(const rec::StateSnapshot& state, gpu::RasterState& out);

}  // namespace glpt::rt
