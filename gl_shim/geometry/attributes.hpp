// The canonical vertex-attribute setters behind every glVertex*/glNormal*/glColor*/glTexCoord*
// variant (generated in gl_attribute_families.cpp, which converts the arguments).
#pragma once

#include <glm/glm.hpp>
#include <limits>
#include <type_traits>

#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

void attribute_vertex(Context& ctx, glm::vec4 position);
void attribute_normal(Context& ctx, glm::vec3 normal);
void attribute_color(Context& ctx, glm::vec4 color);
void attribute_tex_coord(Context& ctx, glm::vec4 coord);
void attribute_multi_tex_coord(Context& ctx, GLenum texture_unit, glm::vec4 coord);

// glMaterial between glBegin and glEnd (allowed by GL 1.5 2.6.3): from then on every vertex of the
// primitive records its own material. Does nothing outside glBegin/glEnd.
void material_changed_inside_begin_end(Context& ctx);

// GL 1.5 spec table 2.9: integer colours and normals map to [0,1] (unsigned) or [-1,1] (signed).
template <typename T>
float normalized_component(T v) {
  if constexpr (std::is_floating_point_v<T>) {
    return static_cast<float>(v);
  } else if constexpr (std::is_unsigned_v<T>) {
    return static_cast<float>(static_cast<double>(v) / std::numeric_limits<T>::max());
  } else {
    constexpr double kRange = 2.0 * std::numeric_limits<T>::max() + 1.0;  // 2^b - 1
    return static_cast<float>((2.0 * static_cast<double>(v) + 1.0) / kRange);
  }
}

template <typename T>
float float_component(T v) {
  return static_cast<float>(v);
}

}  // namespace glpt
