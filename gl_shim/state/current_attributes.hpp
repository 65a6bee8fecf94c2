// The current vertex attributes (GL 1.5 spec 2.7): what glColor/glNormal/glTexCoord set.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "gl_shim/state/matrix_stack.hpp"

namespace glpt {

struct CurrentAttributes {
  glm::vec4 color{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  std::array<glm::vec4, kMaxTextureUnits> tex_coord{glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1),
                                                    glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 0, 1)};
  bool edge_flag = true;
};

}  // namespace glpt
