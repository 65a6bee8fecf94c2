// The texturing block of a state snapshot (rt_core/record/gl_state.hpp, TexturingState).
#pragma once

#include "rt_core/record/gl_state.hpp"

namespace glpt {

class Context;

// Fills `out` from the live texture state: per unit the enabled target with a complete texture
// (0: texturing off), an immutable snapshot of that texture, the environment, texgen and the
// texture matrix. Cheap when nothing changed: unchanged textures keep their snapshot pointer.
void snapshot_texturing(const Context& ctx, rec::TexturingState& out);

}  // namespace glpt
