// GL lighting (GL 1.5 spec 2.14). The live state is Context::lighting, a rec::LightingState;
// this header holds what other parts of the front end call.
#pragma once

#include <glm/glm.hpp>

#include "rt_core/record/gl_state.hpp"

namespace glpt {

class Context;

// GL_COLOR_MATERIAL: while enabled, the tracked material components follow the current colour
// (GL 1.5 2.14.3). Called whenever the current colour changes, when GL_COLOR_MATERIAL becomes
// enabled and when glColorMaterial changes the tracked components.
void apply_color_material(Context& ctx);

// `m` (the material of `side`: 0 front, 1 back) with the components GL_COLOR_MATERIAL tracks
// replaced by `color`, if it is enabled for that side.
rec::Material with_color_material(rec::Material m, const rec::LightingState& l, int side,
                                  const glm::vec4& color);

}  // namespace glpt
