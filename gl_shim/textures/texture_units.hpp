// Per-texture-unit GL state that lives outside texture objects (GL 1.5 3.8.15, 2.11.4, 3.8.13):
// which targets are enabled, texture coordinate generation, the texture environment, and what is
// bound to each target. Texture objects themselves are shared by the share group (TextureStore).
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "gl_shim/textures/texture_object.hpp"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

struct TextureUnit {
  // Bits: GL_TEXTURE_1D, _2D, _3D, _CUBE_MAP, _RECTANGLE_ARB enabled (kTarget* below).
  uint8_t enabled_targets = 0;
  uint8_t texgen_mask = 0;  // bits 0..3: GL_TEXTURE_GEN_S, T, R, Q
  std::array<rec::TexGen, 4> texgen = rec::TextureUnitState::default_texgen();
  rec::TexEnv env;
  // What GL_TEXTURE_1D, _2D, _3D, _CUBE_MAP, _RECTANGLE_ARB (TextureSlot order) are bound to;
  // null: texture 0.
  std::array<std::shared_ptr<TextureObject>, kSlotCount> bound{};
};

inline constexpr uint8_t kTarget1D = 1, kTarget2D = 2, kTarget3D = 4, kTargetCubeMap = 8,
                         kTargetRect = 16;
// enabled_targets bit i is TextureSlot i.
static_assert(kTarget1D == 1 << kSlot1D && kTarget2D == 1 << kSlot2D && kTarget3D == 1 << kSlot3D &&
              kTargetCubeMap == 1 << kSlotCube && kTargetRect == 1 << kSlotRect);

struct TextureUnits {
  std::array<TextureUnit, rec::kMaxTextureUnits> units{};
  uint32_t active = 0;         // glActiveTexture - GL_TEXTURE0
  uint32_t client_active = 0;  // glClientActiveTexture - GL_TEXTURE0
  // Texture objects of the share group (Context's constructor shares it with share_list).
  std::shared_ptr<TextureStore> store = std::make_shared<TextureStore>();
  // GL_PROXY_TEXTURE_1D/2D/3D/CUBE_MAP/RECTANGLE_ARB: per context, images without texels.
  std::array<std::shared_ptr<TextureObject>, kSlotCount> proxies = make_proxies();

  TextureUnit& active_unit() { return units[active]; }
  const TextureUnit& active_unit() const { return units[active]; }
  // The object bound to `slot` of `unit` (texture 0 of the target when nothing is).
  TextureObject& bound(const TextureUnit& unit, int slot) const {
    const std::shared_ptr<TextureObject>& b = unit.bound[size_t(slot)];
    return b ? *b : *store->defaults[size_t(slot)];
  }

  static std::array<std::shared_ptr<TextureObject>, kSlotCount> make_proxies() {
    std::array<std::shared_ptr<TextureObject>, kSlotCount> p;
    for (int s = 0; s < kSlotCount; ++s)
      p[size_t(s)] = std::make_shared<TextureObject>(0, slot_target(s));
    return p;
  }
};

}  // namespace glpt
