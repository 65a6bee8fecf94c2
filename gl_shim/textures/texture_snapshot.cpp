// Interim: texture objects are not implemented yet, so no unit samples a texture; environment,
// texgen and texture matrices are snapshot already.
#include "gl_shim/textures/texture_snapshot.hpp"

#include "gl_shim/context.hpp"

namespace glpt {

void snapshot_texturing(const Context& ctx, rec::TexturingState& out) {
  for (int i = 0; i < rec::kMaxTextureUnits; ++i) {
    const TextureUnit& live = ctx.textures.units[i];
    rec::TextureUnitState& unit = out.units[i];
    unit.target = 0;
    unit.texture.reset();
    unit.env = live.env;
    unit.texgen_mask = live.texgen_mask;
    unit.texgen = live.texgen;
    unit.matrix = ctx.matrices.texture[i].top();
  }
}

}  // namespace glpt
