#include "rt_core/record/decompose.hpp"

namespace glpt::rec {
namespace {

constexpr uint8_t kEdge0 = 1, kEdge1 = 2, kEdge2 = 4, kAllEdges = 7;

// Emits the primitives of one range; `element(i)` maps the range's i-th element to a vertex.
template <typename Element>
void decompose_range(uint32_t mode, uint32_t n, const Element& element,
                     const std::vector<uint8_t>& edge_flags, Decomposed& out) {
  auto edge_flag = [&](uint32_t v) -> bool {
    return edge_flags.empty() || (edge_flags.size() == 1 ? edge_flags[0] : edge_flags[v]) != 0;
  };
  // Structural edges of the GL primitive AND the edge flags of the vertices they start at.
  auto triangle_with_flags = [&](uint32_t a, uint32_t b, uint32_t c, uint8_t structural) {
    uint8_t edges = structural;
    if ((edges & kEdge0) && !edge_flag(a)) edges &= ~kEdge0;
    if ((edges & kEdge1) && !edge_flag(b)) edges &= ~kEdge1;
    if ((edges & kEdge2) && !edge_flag(c)) edges &= ~kEdge2;
    out.triangles.push_back({{a, b, c}, edges});
  };
  auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    out.triangles.push_back({{a, b, c}, kAllEdges});
  };
  switch (mode) {
    case GL_POINTS:
      for (uint32_t i = 0; i < n; ++i) out.points.push_back(element(i));
      break;
    case GL_LINES:
      for (uint32_t i = 0; i + 1 < n; i += 2) out.lines.push_back({{element(i), element(i + 1)}, true});
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      if (n < 2) break;
      for (uint32_t i = 1; i < n; ++i) out.lines.push_back({{element(i - 1), element(i)}, i == 1});
      if (mode == GL_LINE_LOOP) out.lines.push_back({{element(n - 1), element(0)}, false});
      break;
    case GL_TRIANGLES:
      for (uint32_t i = 0; i + 2 < n; i += 3)
        triangle_with_flags(element(i), element(i + 1), element(i + 2), kAllEdges);
      break;
    case GL_TRIANGLE_STRIP:
      for (uint32_t i = 0; i + 2 < n; ++i) {
        if (i & 1)
          triangle(element(i + 1), element(i), element(i + 2));
        else
          triangle(element(i), element(i + 1), element(i + 2));
      }
      break;
    case GL_TRIANGLE_FAN:
      for (uint32_t i = 0; i + 2 < n; ++i) triangle(element(0), element(i + 1), element(i + 2));
      break;
    case GL_QUADS:
      for (uint32_t i = 0; i + 3 < n; i += 4) {
        const uint32_t a = element(i), b = element(i + 1), c = element(i + 2), d = element(i + 3);
        triangle_with_flags(a, b, d, kEdge0 | kEdge2);
        triangle_with_flags(b, c, d, kEdge0 | kEdge1);
      }
      break;
    case GL_QUAD_STRIP:
      // Quad k is the polygon v(2k), v(2k+1), v(2k+3), v(2k+2); GL ignores edge flags here.
      for (uint32_t i = 0; i + 3 < n; i += 2) {
        const uint32_t a = element(i), b = element(i + 1), c = element(i + 2), d = element(i + 3);
        out.triangles.push_back({{c, a, d}, kEdge0 | kEdge2});
        out.triangles.push_back({{a, b, d}, kEdge0 | kEdge1});
      }
      break;
    case GL_POLYGON:
      for (uint32_t i = 0; i + 2 < n; ++i) {
        uint8_t structural = kEdge0;
        if (i == 0) structural |= kEdge2;
        if (i + 3 == n) structural |= kEdge1;
        triangle_with_flags(element(i + 1), element(i + 2), element(0), structural);
      }
      break;
    default:
      break;
  }
}

}  // namespace

PrimitiveClass primitive_class(uint32_t mode) {
  switch (mode) {
    case GL_POINTS:
      return PrimitiveClass::kPoints;
    case GL_LINES:
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      return PrimitiveClass::kLines;
    default:
      return PrimitiveClass::kTriangles;
  }
}

void decompose(const VertexData& vertices, Decomposed& out) {
  const uint32_t vertex_count = vertices.vertex_count();
  const bool indexed = !vertices.indices.empty();
  const uint64_t element_count = indexed ? vertices.indices.size() : vertex_count;
  for (const PrimitiveRange& range : vertices.primitives) {
    if (range.count == 0 || uint64_t{range.first} + range.count > element_count) continue;
    if (!indexed) {
      decompose_range(
          vertices.mode, range.count, [&](uint32_t i) { return range.first + i; },
          vertices.edge_flag, out);
      continue;
    }
    // An index past the vertices drops the primitives that use it, not the whole draw.
    const size_t points = out.points.size(), lines = out.lines.size(),
                 triangles = out.triangles.size();
    bool bad_index = false;
    decompose_range(
        vertices.mode, range.count,
        [&](uint32_t i) {
          const uint32_t v = vertices.indices[range.first + i];
          if (v >= vertex_count) bad_index = true;
          return v;
        },
        vertices.edge_flag, out);
    if (!bad_index) continue;
    auto drop_bad = [&](auto& list, size_t from, auto uses_bad) {
      size_t keep = from;
      for (size_t i = from; i < list.size(); ++i)
        if (!uses_bad(list[i])) list[keep++] = list[i];
      list.resize(keep);
    };
    drop_bad(out.points, points, [&](uint32_t v) { return v >= vertex_count; });
    drop_bad(out.lines, lines, [&](const DecomposedLine& l) {
      return l.v[0] >= vertex_count || l.v[1] >= vertex_count;
    });
    drop_bad(out.triangles, triangles, [&](const DecomposedTriangle& t) {
      return t.v[0] >= vertex_count || t.v[1] >= vertex_count || t.v[2] >= vertex_count;
    });
  }
}

}  // namespace glpt::rec
