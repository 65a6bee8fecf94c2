// Vertex-stage state that is neither a matrix nor lighting: normal rescaling and the user clip
// planes (GL 1.5 2.11.3, 2.12).
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "rt_core/record/gl_state.hpp"

namespace glpt {

struct TransformControls {
  bool normalize = false;       // GL_NORMALIZE
  bool rescale_normal = false;  // GL_RESCALE_NORMAL
  uint8_t clip_plane_mask = 0;  // bit i: GL_CLIP_PLANEi
  // Eye space: glClipPlane transforms the plane by the inverse of the modelview current then.
  std::array<glm::vec4, rec::kMaxClipPlanes> clip_planes{};
};

}  // namespace glpt
