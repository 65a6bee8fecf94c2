#include "rt_core/raster/vertex_streams.hpp"

#include "rt_core/raster/resident_geometry.hpp"

namespace glpt::rt {

bool VertexStreams::takes(const rec::VertexData& v) {
  const uint32_t n = v.vertex_count();
  if (n == 0 || !v.material.empty() || v.bytes() >= ResidentGeometry::kMinBytes) return false;
  // Every attribute array holds no value, one, or one per vertex (frame_record.hpp).
  bool well_formed = true;
  for_each_attribute(v, [&](uint32_t, const auto& values, VkDeviceSize) {
    well_formed = well_formed && (values.size() <= 1 || values.size() == n);
  });
  return well_formed;
}

void VertexStreams::count(const rec::VertexData& v) {
  for_each_attribute(v, [&](uint32_t location, const auto& values, VkDeviceSize default_at) {
    element_bytes_[location] = sizeof(values[0]);
    default_at_[location] = default_at;
    if (!values.empty()) locations_ |= 1u << location;
  });
  vertices_ += v.vertex_count();
}

bool VertexStreams::reserve(Arena& arena) {
  if (vertices_ == 0 || vertices_ > kMaxVertices) return false;
  for (uint32_t location = 0; location < GLPT_RASTER_ATTR_COUNT; ++location)
    if (locations_ & (1u << location))
      offsets_[location] = arena.reserve(vertices_ * element_bytes_[location]);
  reserved_ = true;
  return true;
}

int32_t VertexStreams::add(const rec::VertexData& v, Arena& arena, const uint8_t* defaults) {
  const uint64_t first = next_;
  const size_t n = v.vertex_count();
  if (!fits(n)) return 0;  // (not counted: the caller's mistake; nothing is written past the end)
  for_each_attribute(v, [&](uint32_t location, const auto& values, VkDeviceSize default_at) {
    if (!(locations_ & (1u << location))) return;
    const size_t element = sizeof(values[0]);
    const VkDeviceSize at = offsets_[location] + first * element;
    if (values.size() == n)
      arena.add_external_at(at, reinterpret_cast<const uint8_t*>(values.data()), n * element);
    else  // one value, or the attribute's default, for every vertex
      arena.add_repeated_at(
          at,
          values.empty() ? defaults + default_at : reinterpret_cast<const uint8_t*>(values.data()),
          element, n);
  });
  next_ += n;
  return static_cast<int32_t>(first);
}

void VertexStreams::locate(VkDeviceSize default_offset,
                           std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& offsets,
                           std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& strides) const {
  for (uint32_t location = 0; location < GLPT_RASTER_ATTR_COUNT; ++location) {
    const bool streamed = locations_ & (1u << location);
    offsets[location] = streamed ? offsets_[location] : default_offset + default_at_[location];
    strides[location] = streamed ? element_bytes_[location] : 0;
  }
}

}  // namespace glpt::rt
