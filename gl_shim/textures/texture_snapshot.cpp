#include "gl_shim/textures/texture_snapshot.hpp"

#include "gl_shim/context.hpp"

namespace glpt {

void snapshot_texturing(const Context& ctx, rec::TexturingState& out) {
  for (size_t u = 0; u < out.units.size(); ++u) {
    const TextureUnit& unit = ctx.textures.units[u];
    rec::TextureUnitState& s = out.units[u];
    s.target = 0;
    s.texture.reset();
    for (const TextureSlot slot : kSlotsByPriority) {
      if ((unit.enabled_targets & (1u << slot)) == 0) continue;
      TextureObject& object = ctx.textures.bound(unit, slot);
      if (!object.complete()) continue;  // Mesa falls back to the next enabled target
      s.target = slot_target(slot);
      s.texture = object.snapshot();
      break;
    }
    s.env = unit.env;
    s.texgen_mask = unit.texgen_mask;
    s.texgen = unit.texgen;
    s.matrix = ctx.matrices.texture[u].top();
  }
}

}  // namespace glpt
