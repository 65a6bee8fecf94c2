#include "gl_shim/geometry/triangulate.hpp"

#include "gl/gl_enums.h"

namespace glpt {

bool is_valid_primitive_mode(GLenum mode) { return mode <= GL_POLYGON; }

bool triangulate(GLenum mode, uint32_t n, std::vector<TriangleIndices>& out) {
  switch (mode) {
    case GL_POINTS:
    case GL_LINES:
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      return true;
    case GL_TRIANGLES:
      for (uint32_t i = 0; i + 2 < n; i += 3) out.push_back({{i, i + 1, i + 2}, i + 2});
      return true;
    case GL_TRIANGLE_STRIP:
      // Odd triangles swap their first two vertices so every triangle keeps the strip's winding.
      for (uint32_t i = 0; i + 2 < n; ++i) {
        if (i % 2 == 0)
          out.push_back({{i, i + 1, i + 2}, i + 2});
        else
          out.push_back({{i + 1, i, i + 2}, i + 2});
      }
      return true;
    case GL_TRIANGLE_FAN:
      for (uint32_t i = 1; i + 1 < n; ++i) out.push_back({{0, i, i + 1}, i + 1});
      return true;
    case GL_QUADS:
      for (uint32_t i = 0; i + 3 < n; i += 4) {
        out.push_back({{i, i + 1, i + 2}, i + 3});
        out.push_back({{i, i + 2, i + 3}, i + 3});
      }
      return true;
    case GL_QUAD_STRIP:
      // Quad k is the polygon v(2k), v(2k+1), v(2k+3), v(2k+2).
      for (uint32_t i = 0; i + 3 < n; i += 2) {
        out.push_back({{i, i + 1, i + 3}, i + 3});
        out.push_back({{i, i + 3, i + 2}, i + 3});
      }
      return true;
    case GL_POLYGON:
      // GL's provoking vertex of a polygon is its first vertex.
      for (uint32_t i = 1; i + 1 < n; ++i) out.push_back({{0, i, i + 1}, 0});
      return true;
    default:
      return false;
  }
}

}  // namespace glpt
