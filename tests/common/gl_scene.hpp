// Small GL 1.x scene pieces shared by the path-traced scene tests (tests/light_transport,
// tests/denoiser). Header-only; call with a current context.
#pragma once

#include <glm/glm.hpp>

#include "gl/gl_enums.h"
#include "gl_shim/gl_entry_decls.h"

namespace glpt::test {

// A quad with corners p0..p3 (counter-clockwise seen from where its normal points), its face
// normal given once.
inline void quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
  const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p3 - p0));
  glBegin(GL_QUADS);
  glNormal3f(n.x, n.y, n.z);
  for (const glm::vec3& p : {p0, p1, p2, p3}) glVertex3f(p.x, p.y, p.z);
  glEnd();
}

// A positional light of diffuse colour `color` at `position` (in the current modelview) with
// GL's inverse-square attenuation alone: a physical point (or sphere) light. Enables it.
inline void inverse_square_light(GLenum light, glm::vec3 position, glm::vec3 color) {
  const float p[] = {position.x, position.y, position.z, 1};
  const float c[] = {color.r, color.g, color.b, 1};
  const float black[] = {0, 0, 0, 1};
  glLightfv(light, GL_POSITION, p);
  glLightfv(light, GL_DIFFUSE, c);
  glLightfv(light, GL_SPECULAR, black);
  glLightfv(light, GL_AMBIENT, black);
  glLightf(light, GL_CONSTANT_ATTENUATION, 0.0f);
  glLightf(light, GL_QUADRATIC_ATTENUATION, 1.0f);
  glEnable(light);
}

}  // namespace glpt::test
