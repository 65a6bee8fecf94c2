// GL lighting state (GL 1.5 spec 2.14): lights, materials, light model, colour material.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "gl_shim/gl_types.h"
#include "rt_core/frame.hpp"

namespace glpt {

inline constexpr int kMaxLights = 8;

struct LightingState {
  std::array<rt::Light, kMaxLights> lights;  // positions/directions already in eye space
  std::array<bool, kMaxLights> light_enabled{};
  rt::Material front, back;  // lit/color_source are filled in when a vertex is captured
  glm::vec4 model_ambient{0.2f, 0.2f, 0.2f, 1.0f};
  bool two_side = false;
  bool local_viewer = false;
  GLenum color_material_face = 0x0408;  // GL_FRONT_AND_BACK
  GLenum color_material_mode = 0x1602;  // GL_AMBIENT_AND_DIFFUSE
  GLenum shade_model = 0x1D01;          // GL_SMOOTH
  // Bumped on any change that affects how vertices are shaded, so the capture code re-interns
  // the material only when something changed.
  uint64_t material_version = 0;

  LightingState();
};

}  // namespace glpt
