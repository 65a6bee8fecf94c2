// The texturing state a draw records (rec::TexturingState), taken from the live state at every
// draw; cheap when nothing changed (texture snapshots are cached by their objects).
#pragma once

#include "rt_core/record/gl_state.hpp"

namespace glpt {

class Context;

// For each unit: the highest-priority enabled target whose bound texture is complete (cube map >
// 3D > 2D > 1D; an incomplete one is skipped, as Mesa does; 0 when none: texturing is off), its
// immutable snapshot, the environment, texgen and the texture matrix. (Texture objects, shared
// with the share group, cache their completeness and snapshot as they are asked.)
void snapshot_texturing(const Context& ctx, rec::TexturingState& out);

}  // namespace glpt
