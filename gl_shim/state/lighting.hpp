// GL lighting (GL 1.5 spec 2.14). The live state is Context::lighting, a rec::LightingState;
// this header holds what other parts of the front end call.
#pragma once

namespace glpt {

class Context;

// GL_COLOR_MATERIAL: while enabled, the tracked material components follow the current colour
// (GL 1.5 2.14.3). Called whenever the current colour changes, when GL_COLOR_MATERIAL becomes
// enabled and when glColorMaterial changes the tracked components.
void apply_color_material(Context& ctx);

}  // namespace glpt
