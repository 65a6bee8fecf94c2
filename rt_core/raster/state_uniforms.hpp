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
// RasterLight::spot.w: the cosine of the cutoff, -2 for a light that is not a spotlight.
float packed_spot_cosine(const rec::Light& l);
// GLPT_LIGHT_POSITIONAL and GLPT_LIGHT_SPOT bits of the enabled lights (GLPT_SC_LIGHT_MASK).
uint32_t light_kind_bits(const rec::LightingState& lighting);

}  // namespace glpt::rt
