// Primitive assembly (GL 1.5 spec 2.6.1): turns a glBegin/glEnd vertex sequence into triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "gl_shim/gl_types.h"

namespace glpt {

struct TriangleIndices {
  uint32_t v[3];
  // The vertex whose colour/normal GL uses for the whole primitive under GL_FLAT (spec table 2.9).
  uint32_t provoking;
};

// Appends the triangles of a primitive of `vertex_count` vertices to `out`. Points and lines
// produce nothing (they have no area to trace); incomplete trailing primitives are dropped as
// GL drops them. Returns false for a mode that is not a GL primitive.
bool triangulate(GLenum mode, uint32_t vertex_count, std::vector<TriangleIndices>& out);

bool is_valid_primitive_mode(GLenum mode);

}  // namespace glpt
