#include "rt_core/raster/draw_merging.hpp"

namespace glpt::rt {

bool mergeable_draw(const rec::FrameRecord& record, const rec::Draw& draw, bool streamed) {
  if (!streamed || !draw.vertices || draw.state >= record.states.size()) return false;
  if (rec::primitive_class(draw.vertices->mode) != rec::PrimitiveClass::kTriangles) return false;
  const rec::PrimitiveState& p = record.states[draw.state].raster->primitive;
  return p.polygon_mode_front == GL_FILL && p.polygon_mode_back == GL_FILL;
}

uint64_t append_filled_triangles(const rec::VertexData& v, const rec::AssemblyState& assembly,
                                 uint32_t base, rec::Decomposed& scratch,
                                 std::vector<uint32_t>& out) {
  const auto good = [&](uint32_t a, uint32_t b, uint32_t c) {
    return finite(v.position[a]) && finite(v.position[b]) && finite(v.position[c]);
  };
  uint64_t dropped = 0;
  if (rec::triangles_in_element_order(v, assembly)) {  // without decomposing (checked indices)
    const uint32_t count = v.primitives[0].count;
    const bool indexed = !v.indices.empty();
    for (uint32_t e = 0; e + 2 < count; e += 3) {
      const uint32_t a = indexed ? v.indices[e] : e, b = indexed ? v.indices[e + 1] : e + 1,
                     c = indexed ? v.indices[e + 2] : e + 2;
      if (good(a, b, c))
        out.insert(out.end(), {base + a, base + b, base + c});
      else
        ++dropped;
    }
    return dropped;
  }
  scratch.clear();
  rec::decompose(v, assembly, scratch);
  for (const rec::DecomposedTriangle& t : scratch.triangles) {
    if (good(t.v[0], t.v[1], t.v[2]))
      out.insert(out.end(), {base + t.v[0], base + t.v[1], base + t.v[2]});
    else
      ++dropped;
  }
  return dropped;
}

}  // namespace glpt::rt
