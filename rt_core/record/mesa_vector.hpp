// Mesa's vector macros (src/mesa/main/macros.h: DOT3, DOT4, NORMALIZE_3FV) with their order of
// float operations, which the front end's CPU lighting and texture generation and the tracer's
// texture generation follow bit for bit.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

namespace glpt::rec {

inline float dot3(const glm::vec3& a, const glm::vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline float dot4(const glm::vec4& a, const glm::vec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}
// Scaled by the reciprocal of the length; a zero vector stays zero.
inline glm::vec3 normalize3(glm::vec3 v) {
  float len = dot3(v, v);
  if (len != 0.0f) {
    len = 1.0f / std::sqrt(len);
    v *= len;
  }
  return v;
}

}  // namespace glpt::rec
