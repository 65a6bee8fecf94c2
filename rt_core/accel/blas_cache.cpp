#include "rt_core/accel/blas_cache.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "rt_core/accel/morton_sort.hpp"
#include "rt_core/scene/shading_data.hpp"
#include "common/stopwatch.hpp"
#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"
#include "shared_types.h"

namespace glpt::rt {
namespace {

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

VkDeviceSize entry_bytes(const BlasEntry& entry) {
  return entry.shading.size() + entry.storage.size();
}

}  // namespace

// What one build needs between creating the entry and recording the build command.
struct BlasCache::PendingBuild {
  uint64_t content_hash = 0;
  std::unique_ptr<BlasEntry> entry;
  VkAccelerationStructureGeometryKHR geometry = make_info<VkAccelerationStructureGeometryKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  VkDeviceSize scratch_size = 0;
};

std::unique_ptr<BlasEntry> BlasCache::create_entry(const Geometry& geometry,
                                                   PendingBuild& build) const {
  auto entry = std::make_unique<BlasEntry>();
  const size_t triangle_count = geometry.triangle_count();
  const std::span<const glm::vec3> positions(geometry.positions.data(), 3 * triangle_count);

  MortonOrder order = morton_order_triangles(positions);
  entry->triangle_order = std::move(order.permutation);
  entry->triangle_count = static_cast<uint32_t>(triangle_count);

  const size_t material_count = packed_material_count(geometry);
  const VkDeviceSize vertex_bytes = 3 * triangle_count * sizeof(gpu::ShadingVertex);
  const VkDeviceSize material_bytes = material_count * sizeof(gpu::GpuMaterial);
  entry->shading =
      GpuBuffer::create(device_, vertex_bytes + material_bytes,
                        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  auto* vertices = entry->shading.as<gpu::ShadingVertex>();
  auto* materials =
      reinterpret_cast<gpu::GpuMaterial*>(entry->shading.as<std::byte>() + vertex_bytes);
  pack_geometry(geometry, entry->triangle_order, {vertices, 3 * triangle_count},
                {materials, material_count});
  entry->vertices_address = entry->shading.address();
  entry->materials_address = entry->shading.address() + vertex_bytes;

  glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : positions) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  if (low.x <= high.x) {
    entry->bounds_min = low;
    entry->bounds_max = high;
  }
  entry->has_lit_material = geometry.materials.empty() ||
                            std::any_of(geometry.materials.begin(), geometry.materials.end(),
                                        [](const Material& material) { return material.lit; });

  // A non-indexed triangle soup read straight from the shading vertices.
  build.geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
  build.geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
  auto& triangles = build.geometry.geometry.triangles;
  triangles.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
  triangles.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
  triangles.vertexData.deviceAddress = entry->vertices_address;
  triangles.vertexStride = sizeof(gpu::ShadingVertex);
  triangles.maxVertex = static_cast<uint32_t>(3 * triangle_count - 1);
  triangles.indexType = VK_INDEX_TYPE_NONE_KHR;

  auto info =
      acceleration_build_info(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, &build.geometry);
  const uint32_t primitive_count = entry->triangle_count;
  auto sizes = make_info<VkAccelerationStructureBuildSizesInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
  const auto& as = device_.as_functions();
  as.get_build_sizes(device_.handle(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info,
                     &primitive_count, &sizes);
  build.scratch_size = sizes.buildScratchSize;

  entry->storage = GpuBuffer::create(device_, sizes.accelerationStructureSize,
                                     VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR);
  auto create_info = make_info<VkAccelerationStructureCreateInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR);
  create_info.buffer = entry->storage.handle();
  create_info.size = sizes.accelerationStructureSize;
  create_info.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  VkAccelerationStructureKHR blas = VK_NULL_HANDLE;
  GLPT_VK_CHECK(as.create(device_.handle(), &create_info, nullptr, &blas));
  entry->blas = vk::AccelerationStructure(blas, {device_.handle(), as.destroy});
  auto address_info = make_info<VkAccelerationStructureDeviceAddressInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR);
  address_info.accelerationStructure = blas;
  entry->blas_address = as.get_device_address(device_.handle(), &address_info);
  return entry;
}

BlasPrepareStats BlasCache::prepare(std::span<const Geometry* const> geometries,
                                    uint64_t frame_number) {
  BlasPrepareStats stats;
  const Stopwatch timer;
  std::vector<PendingBuild> pending;
  pending.reserve(geometries.size());  // PendingBuild::geometry is pointed to: no reallocation
  std::unordered_set<uint64_t> seen;
  for (const Geometry* geometry : geometries) {
    if (geometry == nullptr || geometry->triangle_count() == 0) continue;
    if (!seen.insert(geometry->content_hash).second) continue;
    if (auto found = entries_.find(geometry->content_hash); found != entries_.end()) {
      found->second->last_used_frame = frame_number;
      ++stats.reused;
      continue;
    }
    PendingBuild& build = pending.emplace_back();
    build.content_hash = geometry->content_hash;
    build.entry = create_entry(*geometry, build);
    build.entry->last_used_frame = frame_number;
  }
  stats.upload_ms = timer.elapsed_ms();
  if (pending.empty()) return stats;

  // All builds go into one vkCmdBuildAccelerationStructuresKHR, each with its own scratch range.
  const VkDeviceSize alignment = device_.scratch_alignment();
  VkDeviceSize scratch_total = 0;
  for (const PendingBuild& build : pending)
    scratch_total += align_up(build.scratch_size, alignment);
  ensure_capacity(device_, scratch_, scratch_total + alignment, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
  infos.reserve(pending.size());
  ranges.reserve(pending.size());
  VkDeviceAddress scratch_address = align_up(scratch_.address(), alignment);
  for (PendingBuild& build : pending) {
    VkAccelerationStructureBuildGeometryInfoKHR& info = infos.emplace_back();
    info = make_info<VkAccelerationStructureBuildGeometryInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
    info.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.dstAccelerationStructure = build.entry->blas.get();
    info.geometryCount = 1;
    info.pGeometries = &build.geometry;
    info.scratchData.deviceAddress = scratch_address;
    scratch_address += align_up(build.scratch_size, alignment);
    ranges.push_back({build.entry->triangle_count, 0, 0, 0});
  }
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> range_pointers;
  for (const auto& range : ranges) range_pointers.push_back(&range);

  stats.build_ms = device_.submit_and_wait([&](VkCommandBuffer cmd) {
    device_.as_functions().cmd_build(cmd, static_cast<uint32_t>(infos.size()), infos.data(),
                                     range_pointers.data());
  });
  for (PendingBuild& build : pending) {
    memory_bytes_ += entry_bytes(*build.entry);
    entries_.emplace(build.content_hash, std::move(build.entry));
  }
  stats.builds = static_cast<uint32_t>(pending.size());
  return stats;
}

const BlasEntry* BlasCache::find(uint64_t content_hash) const {
  auto found = entries_.find(content_hash);
  return found == entries_.end() ? nullptr : found->second.get();
}

void BlasCache::evict_unused(uint64_t frame_number) {
  std::erase_if(entries_, [&](const auto& item) {
    const bool expired = item.second->last_used_frame + kEvictAfterUnusedFrames < frame_number;
    if (expired) memory_bytes_ -= entry_bytes(*item.second);
    return expired;
  });
  if (memory_bytes_ <= kMemoryBudgetBytes) return;

  std::vector<std::pair<uint64_t, uint64_t>> by_age;  // (last used frame, content hash)
  for (const auto& [hash, entry] : entries_) {
    if (entry->last_used_frame < frame_number) by_age.emplace_back(entry->last_used_frame, hash);
  }
  std::sort(by_age.begin(), by_age.end());
  for (const auto& [last_used, hash] : by_age) {
    if (memory_bytes_ <= kMemoryBudgetBytes) break;
    auto found = entries_.find(hash);
    memory_bytes_ -= entry_bytes(*found->second);
    entries_.erase(found);
  }
}

}  // namespace glpt::rt
