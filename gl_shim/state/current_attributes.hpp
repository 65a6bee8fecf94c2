// The current vertex attributes (GL 1.5 spec 2.7): what glColor/glNormal/glTexCoord set.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "rt_core/record/gl_state.hpp"

namespace glpt {

struct CurrentAttributes {
  glm::vec4 color{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 secondary_color{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  float fog_coord = 0.0f;
  std::array<glm::vec4, rec::kMaxTextureUnits> tex_coord = [] {
    std::array<glm::vec4, rec::kMaxTextureUnits> t{};
    t.fill(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    return t;
  }();
  bool edge_flag = true;
  // glIndex: colour-index mode is not supported; the value is kept for GL_CURRENT_INDEX.
  float index = 1.0f;
};

}  // namespace glpt
