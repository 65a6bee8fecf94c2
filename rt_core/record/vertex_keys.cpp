#include <cmath>
#include <limits>

#include "common/content_hash.hpp"
#include "rt_core/record/frame_record.hpp"

namespace glpt::rec {

const VertexKeys& VertexData::keys() const {
  if (cached_keys.valid) return cached_keys.keys;
  ContentHash geometry;
  geometry.add_bytes(&mode, sizeof mode);
  geometry.add_bytes(&source, sizeof source);
  geometry.add_bytes(&per_vertex, sizeof per_vertex);
  geometry.add(position);
  geometry.add(indices);
  geometry.add(primitives);

  ContentHash attributes;
  attributes.add(normal);
  attributes.add(color);
  attributes.add(secondary_color);
  attributes.add(fog_coord);
  for (const auto& t : tex_coord) attributes.add(t);
  attributes.add(edge_flag);
  attributes.add(material);

  glm::vec3 low(std::numeric_limits<float>::infinity()), high(-low);
  for (const glm::vec4& p : position) {
    if (!(p.w > 0.0f)) continue;
    const glm::vec3 q = p.w == 1.0f ? glm::vec3(p) : glm::vec3(p) / p.w;
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) continue;
    low = glm::min(low, q);
    high = glm::max(high, q);
  }
  cached_keys.keys = {geometry.value(), attributes.value(), glm::vec3(1.0f), glm::vec3(-1.0f)};
  if (low.x <= high.x) {
    cached_keys.keys.bounds_min = low;
    cached_keys.keys.bounds_max = high;
  }
  cached_keys.valid = true;
  return cached_keys.keys;
}

namespace {
// `bytes_of(array)` summed over every array of `d`.
template <typename BytesOf>
size_t sum_over_arrays(const VertexData& d, BytesOf bytes_of) {
  size_t sum = bytes_of(d.position) + bytes_of(d.normal) + bytes_of(d.color) +
               bytes_of(d.secondary_color) + bytes_of(d.fog_coord) + bytes_of(d.edge_flag) +
               bytes_of(d.material) + bytes_of(d.indices) + bytes_of(d.primitives);
  for (const auto& t : d.tex_coord) sum += bytes_of(t);
  return sum;
}
}  // namespace

size_t VertexData::bytes() const {
  return sum_over_arrays(*this, [](const auto& v) { return v.size() * sizeof(v[0]); });
}

size_t VertexData::capacity_bytes() const {
  return sum_over_arrays(*this, [](const auto& v) { return v.capacity() * sizeof(v[0]); });
}

uint64_t VertexData::content_id() const {
  uint64_t id = cached_keys.content_id.load(std::memory_order_relaxed);
  if (id != 0) return id;
  // Numbers are never reused in a process, so a consumer's entry for a number that no longer
  // exists can never be mistaken for new contents that happen to live at the same address.
  static std::atomic<uint64_t> next_id{1};
  const uint64_t fresh = next_id.fetch_add(1, std::memory_order_relaxed);
  // Two threads asking at once agree on one number.
  return cached_keys.content_id.compare_exchange_strong(id, fresh, std::memory_order_relaxed)
             ? fresh
             : id;
}

}  // namespace glpt::rec
