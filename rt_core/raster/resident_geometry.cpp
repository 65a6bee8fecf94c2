#include "rt_core/raster/resident_geometry.hpp"

#include <cstring>

#include "rt_core/raster/raster_recording.hpp"

namespace glpt::rt {
namespace {

constexpr VkDeviceSize align16(VkDeviceSize offset) { return (offset + 15) & ~VkDeviceSize{15}; }

}  // namespace

bool ResidentGeometry::Entry::in_vertex_order(const rec::AssemblyState& assembly,
                                              uint32_t* index_count) const {
  if (!vertex_order_known_ || (assembly_consulted_ && !(assembly == assembly_))) return false;
  *index_count = vertex_order_index_count_;
  return true;
}

void ResidentGeometry::Entry::found_in_vertex_order(uint32_t index_count, bool assembly_consulted,
                                                    const rec::AssemblyState& assembly) {
  vertex_order_known_ = true;
  vertex_order_index_count_ = index_count;
  assembly_consulted_ = assembly_consulted;
  assembly_ = assembly;
}

ResidentGeometry::Entry* ResidentGeometry::use(const VulkanDevice& device,
                                               const rec::VertexData& vertices, uint64_t execute) {
  const uint64_t id = vertices.content_id();
  if (const auto it = entries_.find(id); it != entries_.end()) {
    it->second.last_used = execute;
    return &it->second;
  }
  if (vertices.bytes() < kMinBytes) return nullptr;
  const auto [sighting, first_sight] = seen_.try_emplace(id, execute);
  if (first_sight) return nullptr;
  seen_.erase(sighting);

  // Second sight: lay the arrays out as the upload buffer would and copy them once.
  Entry entry;
  entry.last_used = execute;
  VkDeviceSize size = 0;
  for_each_attribute(vertices, [&](uint32_t location, const auto& values, VkDeviceSize) {
    if (values.empty()) return;
    entry.offsets[location] = align16(size);
    size = entry.offsets[location] + values.size() * sizeof(values[0]);
  });
  entry.index_offset = align16(size);
  size = entry.index_offset + vertices.indices.size() * sizeof(uint32_t);
  entry.buffer = GpuBuffer::create(
      device, size, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  uploaded_bytes_ += size;
  auto* bytes = static_cast<uint8_t*>(entry.buffer.mapped());
  for_each_attribute(vertices, [&](uint32_t location, const auto& values, VkDeviceSize) {
    if (!values.empty())
      std::memcpy(bytes + entry.offsets[location], values.data(),
                  values.size() * sizeof(values[0]));
  });
  if (!vertices.indices.empty())
    std::memcpy(bytes + entry.index_offset, vertices.indices.data(),
                vertices.indices.size() * sizeof(uint32_t));
  return &entries_.emplace(id, std::move(entry)).first->second;
}

void ResidentGeometry::release_unused(uint64_t execute) {
  std::erase_if(entries_, [&](const auto& entry) {
    return entry.second.last_used + kKeepExecutes < execute;
  });
  std::erase_if(seen_,
                [&](const auto& sighting) { return sighting.second + kKeepExecutes < execute; });
}

}  // namespace glpt::rt
