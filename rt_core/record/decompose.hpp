// GL primitives -> points, lines and triangles, as GL assembles them (GL 1.5 2.6.1).
//
// The order follows Mesa's (draw_decompose / llvmpipe setup with GL's last-vertex convention):
// every triangle is emitted with its provoking vertex last, so a rasterizer set to "provoking
// vertex last" flat-shades as GL does, and quads and polygons split along the same diagonals as
// Mesa's, which keeps interpolation and edge ties identical.
//   triangle strip  i even (i, i+1, i+2), i odd (i+1, i, i+2)
//   triangle fan    (0, i+1, i+2)
//   quads           (0, 1, 3), (1, 2, 3)        provoking: the 4th vertex
//   quad strip      (2i+2, 2i, 2i+3), (2i, 2i+1, 2i+3)
//   polygon         (i+1, i+2, 0)               provoking: the first vertex
#pragma once

#include <cstdint>
#include <vector>

#include "rt_core/record/frame_record.hpp"

namespace glpt::rec {

struct DecomposedTriangle {
  uint32_t v[3];  // vertex numbers (indices already resolved); v[2] is the provoking vertex
  // Bit k: the edge v[k] -> v[(k+1)%3] is a boundary edge (drawn in GL_LINE / GL_POINT polygon
  // mode): the structural edges of the GL primitive AND the edge flag of the vertex it starts at
  // (edge flags apply to independent triangles, quads and polygons only, GL 1.5 2.6.2).
  uint8_t boundary_edges;
};

struct DecomposedLine {
  uint32_t v[2];  // v[1] is the provoking vertex
  bool reset_stipple;  // GL restarts the line stipple here (each GL_LINES segment, each strip)
};

struct Decomposed {
  std::vector<uint32_t> points;
  std::vector<DecomposedLine> lines;
  std::vector<DecomposedTriangle> triangles;
  void clear() {
    points.clear();
    lines.clear();
    triangles.clear();
  }
};

// Appends the primitives of `vertices` to `out`. Incomplete trailing primitives are dropped as GL
// drops them; out-of-range indices drop the primitive they belong to.
void decompose(const VertexData& vertices, Decomposed& out);

// The basic primitive class a GL mode rasterizes as (before polygon mode).
enum class PrimitiveClass : uint8_t { kPoints, kLines, kTriangles };
PrimitiveClass primitive_class(uint32_t mode);

}  // namespace glpt::rec
