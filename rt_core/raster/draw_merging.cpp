#include "rt_core/raster/draw_merging.hpp"

#include <cmath>
#include <cstring>

#include "rt_core/raster/resident_geometry.hpp"

namespace glpt::rt {
namespace {

bool finite(const glm::vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

bool mergeable_draw(const rec::FrameRecord& record, const rec::Draw& draw) {
  if (!draw.vertices || draw.state >= record.states.size()) return false;
  const rec::VertexData& v = *draw.vertices;
  const uint32_t n = v.vertex_count();
  if (n == 0 || rec::primitive_class(v.mode) != rec::PrimitiveClass::kTriangles ||
      !v.material.empty() || v.bytes() >= ResidentGeometry::kMinBytes)
    return false;
  const rec::PrimitiveState& p = record.states[draw.state].raster->primitive;
  if (p.polygon_mode_front != GL_FILL || p.polygon_mode_back != GL_FILL) return false;
  // Every attribute array holds no value, one, or one per vertex (frame_record.hpp).
  bool well_formed = true;
  for_each_attribute(v, [&](uint32_t, const auto& values, VkDeviceSize) {
    well_formed = well_formed && (values.size() <= 1 || values.size() == n);
  });
  return well_formed;
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

void merge_attributes(std::span<const rec::VertexData* const> draws, Arena& arena,
                      const uint8_t* defaults, VkDeviceSize default_offset,
                      std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& offsets,
                      std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& strides) {
  struct View {
    const uint8_t* data = nullptr;
    size_t count = 0;
  };
  // One attribute location at a time: its array in each draw.
  for_each_attribute(*draws[0], [&](uint32_t location, const auto& first, VkDeviceSize default_at) {
    using T = typename std::decay_t<decltype(first)>::value_type;
    const auto values_of = [&](const rec::VertexData& v) {
      View view;
      for_each_attribute(v, [&](uint32_t l, const auto& values, VkDeviceSize) {
        if (l != location) return;
        view = {reinterpret_cast<const uint8_t*>(values.data()), values.size()};
      });
      return view;
    };
    bool all_empty = true, one_shared = true;
    const View head = values_of(*draws[0]);
    for (const rec::VertexData* v : draws) {
      const View view = values_of(*v);
      all_empty = all_empty && view.count == 0;
      one_shared = one_shared && view.count == 1 && head.count == 1 &&
                   std::memcmp(view.data, head.data, sizeof(T)) == 0;
    }
    (void)first;
    if (all_empty) {
      offsets[location] = default_offset + default_at;
      strides[location] = 0;
      return;
    }
    if (one_shared) {
      offsets[location] = arena.add(reinterpret_cast<const T*>(head.data), 1);
      strides[location] = 0;
      return;
    }
    offsets[location] = arena.begin_joined();
    strides[location] = sizeof(T);
    for (const rec::VertexData* v : draws) {
      const View view = values_of(*v);
      const size_t n = v->vertex_count();
      if (view.count == n)
        arena.append(view.data, n * sizeof(T));
      else  // one value, or the attribute's default, for every vertex
        arena.append_repeated(view.count == 1 ? view.data : defaults + default_at, sizeof(T), n);
    }
  });
}

}  // namespace glpt::rt
