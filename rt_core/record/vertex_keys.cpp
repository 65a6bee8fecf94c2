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

  cached_keys.keys = {geometry.value(), attributes.value()};
  cached_keys.valid = true;
  return cached_keys.keys;
}

}  // namespace glpt::rec
