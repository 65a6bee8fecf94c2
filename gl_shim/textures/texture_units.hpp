// Per-texture-unit GL state that lives outside texture objects (GL 1.5 3.8.15, 2.11.4, 3.8.13):
// which targets are enabled, texture coordinate generation, and the texture environment.
#pragma once

#include <array>
#include <cstdint>

#include "rt_core/record/gl_state.hpp"

namespace glpt {

struct TextureUnit {
  // Bits: GL_TEXTURE_1D, _2D, _3D, _CUBE_MAP enabled (kTarget* below).
  uint8_t enabled_targets = 0;
  uint8_t texgen_mask = 0;  // bits 0..3: GL_TEXTURE_GEN_S, T, R, Q
  std::array<rec::TexGen, 4> texgen = rec::TextureUnitState::default_texgen();
  rec::TexEnv env;
};

inline constexpr uint8_t kTarget1D = 1, kTarget2D = 2, kTarget3D = 4, kTargetCubeMap = 8;

struct TextureUnits {
  std::array<TextureUnit, rec::kMaxTextureUnits> units{};
  uint32_t active = 0;         // glActiveTexture - GL_TEXTURE0
  uint32_t client_active = 0;  // glClientActiveTexture - GL_TEXTURE0
  TextureUnit& active_unit() { return units[active]; }
  const TextureUnit& active_unit() const { return units[active]; }
};

}  // namespace glpt
