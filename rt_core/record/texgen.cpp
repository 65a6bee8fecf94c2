#include "rt_core/record/texgen.hpp"

#include <cmath>

#include "gl/gl_enums.h"
#include "rt_core/record/mesa_vector.hpp"

namespace glpt::rec {

glm::vec4 generate_tex_coord(uint8_t mask, const std::array<TexGen, 4>& texgen,
                             const glm::vec4& object, const glm::vec4& eye, const glm::vec3& normal,
                             glm::vec4 tc) {
  const glm::vec3 u = normalize3(glm::vec3(eye));
  const float two_nu = 2.0f * dot3(normal, u);
  const glm::vec3 r(u.x - normal.x * two_nu, u.y - normal.y * two_nu, u.z - normal.z * two_nu);
  const float m = r.x * r.x + r.y * r.y + (r.z + 1.0f) * (r.z + 1.0f);
  const float m_inverse = m > 0.0f ? 0.5f * (1.0f / std::sqrt(m)) : 0.0f;
  for (int c = 0; c < 4; ++c) {
    if (!(mask & (1u << c))) continue;
    const TexGen& g = texgen[c];
    switch (g.mode) {
      case GL_OBJECT_LINEAR:
        tc[c] = dot4(object, g.object_plane);
        break;
      case GL_EYE_LINEAR:
        tc[c] = dot4(eye, g.eye_plane);
        break;
      case GL_SPHERE_MAP:
        if (c < 2) tc[c] = r[c] * m_inverse + 0.5f;
        break;
      case GL_REFLECTION_MAP:
        if (c < 3) tc[c] = r[c];
        break;
      case GL_NORMAL_MAP:
        if (c < 3) tc[c] = normal[c];
        break;
      default:
        break;
    }
  }
  return tc;
}

}  // namespace glpt::rec
