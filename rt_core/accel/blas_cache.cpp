#include "rt_core/accel/blas_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_set>

#include "common/content_hash.hpp"
#include "common/stopwatch.hpp"
#include "rt_core/accel/morton_sort.hpp"
#include "rt_core/scene/shading_data.hpp"
#include "rt_core/vk/vk_error.hpp"
#include "rt_core/vk/vk_info.hpp"
#include "shared_types.h"

namespace glpt::rt {
namespace {

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

VkDeviceSize entry_bytes(const BlasEntry& entry) {
  return entry.positions.size() + entry.previous_positions.size() + entry.storage.size();
}

uint64_t shading_key(uint64_t shape_hash, uint64_t shading_hash) {
  ContentHash h;
  h.add_bytes(&shape_hash, sizeof shape_hash);
  h.add_bytes(&shading_hash, sizeof shading_hash);
  return h.value();
}

}  // namespace

// What one build or refit needs between creating (or finding) the entry and recording the
// command.
struct BlasCache::PendingBuild {
  uint64_t shape_hash = 0;
  std::unique_ptr<BlasEntry> entry;  // a new entry, or a refit one taken out of the cache
  bool refit = false;
  VkAccelerationStructureGeometryKHR geometry = make_info<VkAccelerationStructureGeometryKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  VkDeviceSize scratch_size = 0;
};

namespace {

struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};
  float area() const {
    const glm::vec3 d = max - min;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

// The box of the finite positions (empty: a zero box at the origin).
Bounds bounds_of(std::span<const glm::vec3> positions) {
  glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : positions) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  if (low.x > high.x) return {};
  return {low, high};
}

// The surface-area cost of the tree lavapipe's builder makes of triangles in `order` (it halves
// the primitive index range, morton_sort.hpp): the summed areas of a binary tree over runs of
// kLeafTriangles consecutive triangles, relative to the root's area. A refit keeps the order of
// the shape the tree was built for; as the triangles move apart the boxes of index ranges grow
// and rays visit more of them: the cost of the refit tree against its cost when built is what
// the refit loses (BlasCache::refit_source).
float tree_cost(std::span<const glm::vec3> positions, std::span<const uint32_t> order) {
  constexpr size_t kLeafTriangles = 4;
  std::vector<Bounds> level;
  level.reserve((order.size() + kLeafTriangles - 1) / kLeafTriangles);
  const glm::vec3 empty_low(std::numeric_limits<float>::max());
  const glm::vec3 empty_high(std::numeric_limits<float>::lowest());
  for (size_t first = 0; first < order.size(); first += kLeafTriangles) {
    Bounds box{empty_low, empty_high};
    for (size_t i = first; i < std::min(order.size(), first + kLeafTriangles); ++i)
      for (size_t corner = 0; corner < 3; ++corner) {
        const glm::vec3& p = positions[3 * size_t{order[i]} + corner];
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) continue;
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
      }
    level.push_back(box);
  }
  auto area = [](const Bounds& box) { return box.min.x > box.max.x ? 0.0 : double{box.area()}; };
  double sum = 0.0;
  while (level.size() > 1) {
    size_t parents = 0;
    for (size_t i = 0; i < level.size(); i += 2) {
      sum += area(level[i]);
      Bounds parent = level[i];
      if (i + 1 < level.size()) {
        sum += area(level[i + 1]);
        parent.min = glm::min(parent.min, level[i + 1].min);
        parent.max = glm::max(parent.max, level[i + 1].max);
      }
      level[parents++] = parent;
    }
    level.resize(parents);
  }
  const double root = level.empty() ? 0.0 : area(level.front());
  return root > 0.0 ? static_cast<float>(sum / root) : 0.0f;
}

// The build input of a non-indexed triangle soup read straight from `entry`'s positions.
void describe_triangles(const BlasEntry& entry, VkAccelerationStructureGeometryKHR& geometry) {
  geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
  geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
  auto& triangles = geometry.geometry.triangles;
  triangles.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
  triangles.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
  triangles.vertexData.deviceAddress = entry.positions_address;
  triangles.vertexStride = sizeof(gpu::GpuPosition);
  triangles.maxVertex = 3 * entry.triangle_count - 1;
  triangles.indexType = VK_INDEX_TYPE_NONE_KHR;
}

VkBuildAccelerationStructureFlagsKHR build_flags(const BlasEntry& entry) {
  VkBuildAccelerationStructureFlagsKHR flags =
      VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  if (entry.updatable) flags |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR;
  return flags;
}

}  // namespace

std::unique_ptr<BlasEntry> BlasCache::create_entry(const Geometry& geometry, bool updatable,
                                                   PendingBuild& build) const {
  auto entry = std::make_unique<BlasEntry>();
  const size_t triangle_count = geometry.triangle_count();
  const std::span<const glm::vec3> positions(geometry.positions.data(), 3 * triangle_count);

  MortonOrder order = morton_order_triangles(positions);
  entry->triangle_order = std::move(order.permutation);
  entry->triangle_count = static_cast<uint32_t>(triangle_count);
  entry->updatable = updatable;

  const VkDeviceSize position_bytes = 3 * triangle_count * sizeof(gpu::GpuPosition);
  entry->positions =
      GpuBuffer::create(device_, position_bytes,
                        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  pack_positions(geometry, entry->triangle_order,
                 {entry->positions.as<gpu::GpuPosition>(), 3 * triangle_count});
  entry->positions_address = entry->positions.address();

  const Bounds bounds = bounds_of(positions);
  entry->bounds_min = bounds.min;
  entry->bounds_max = bounds.max;
  if (updatable) entry->built_tree_cost = tree_cost(positions, entry->triangle_order);
  describe_triangles(*entry, build.geometry);

  auto info =
      acceleration_build_info(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, &build.geometry);
  info.flags = build_flags(*entry);
  const uint32_t primitive_count = entry->triangle_count;
  auto sizes = make_info<VkAccelerationStructureBuildSizesInfoKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
  const auto& as = device_.as_functions();
  as.get_build_sizes(device_.handle(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info,
                     &primitive_count, &sizes);
  build.scratch_size = sizes.buildScratchSize;
  entry->update_scratch_size = updatable ? sizes.updateScratchSize : 0;

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

std::unordered_map<uint64_t, std::unique_ptr<BlasEntry>>::iterator BlasCache::refit_source(
    const Geometry& geometry, uint64_t frame_number, double traced_pixels, double* refit_loss) {
  if (!refit_allowed_ || geometry.lineage == 0) return entries_.end();
  const auto shape = lineage_shapes_.find(geometry.lineage);
  if (shape == lineage_shapes_.end() || shape->second == geometry.shape_hash) return entries_.end();
  const auto found = entries_.find(shape->second);
  if (found == entries_.end()) return entries_.end();
  const BlasEntry& entry = *found->second;
  // Used this frame (by another draw of that shape, or already refit): it must stay as it is.
  if (!entry.updatable || entry.last_used_frame == frame_number ||
      entry.triangle_count != geometry.triangle_count() || entry.refits + 1 > kMaxRefits)
    return entries_.end();
  // What the refit trees have cost the rays since the build (in units of a frame's tracing),
  // against what building anew costs: refit until the loss would exceed a build.
  const std::span<const glm::vec3> positions(geometry.positions.data(),
                                             3 * geometry.triangle_count());
  const float growth = tree_cost(positions, entry.triangle_order) / entry.built_tree_cost;
  const double loss = entry.refit_loss + std::max(0.0, double{growth} - 1.0);
  const double build_cost = static_cast<double>(entry.triangle_count) /
                            (kBuiltTrianglesPerTracedPixel * std::max(1.0, traced_pixels));
  if (!(loss < build_cost)) return entries_.end();
  *refit_loss = loss;
  return found;
}

void BlasCache::keep_previous_positions(const BlasEntry& from, BlasEntry& to,
                                        uint64_t frame_number) const {
  if (from.triangle_count != to.triangle_count || from.triangle_order.size() != to.triangle_count)
    return;
  // from.triangle_order: BLAS index in `from` -> triangle; inverted: triangle -> index in `from`.
  std::vector<uint32_t> index_in_from(from.triangle_count);
  for (uint32_t i = 0; i < from.triangle_count; ++i) index_in_from[from.triangle_order[i]] = i;
  to.previous_positions =
      GpuBuffer::create(device_, to.positions.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  const auto* old_positions = from.positions.as<gpu::GpuPosition>();
  auto* previous = to.previous_positions.as<gpu::GpuPosition>();
  for (uint32_t i = 0; i < to.triangle_count; ++i) {
    const size_t source = 3 * size_t{index_in_from[to.triangle_order[i]]};
    for (size_t corner = 0; corner < 3; ++corner)
      previous[3 * size_t{i} + corner] = old_positions[source + corner];
  }
  to.previous_positions_address = to.previous_positions.address();
  to.previous_positions_frame = frame_number;
}

std::unique_ptr<ShadingEntry> BlasCache::create_shading(const Geometry& geometry,
                                                        const BlasEntry& shape) const {
  auto entry = std::make_unique<ShadingEntry>();
  const size_t material_count = packed_material_count(geometry);
  const VkDeviceSize vertex_bytes =
      3 * VkDeviceSize{shape.triangle_count} * sizeof(gpu::ShadingVertex);
  const VkDeviceSize material_bytes = material_count * sizeof(gpu::GpuMaterial);
  entry->data =
      GpuBuffer::create(device_, vertex_bytes + material_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  auto* vertices = entry->data.as<gpu::ShadingVertex>();
  auto* materials = reinterpret_cast<gpu::GpuMaterial*>(entry->data.as<std::byte>() + vertex_bytes);
  pack_shading(geometry, shape.triangle_order, {vertices, 3 * size_t{shape.triangle_count}},
               {materials, material_count});
  entry->vertices_address = entry->data.address();
  entry->materials_address = entry->data.address() + vertex_bytes;
  entry->shape_hash = geometry.shape_hash;
  entry->emitters = emitter_triangles(geometry, shape.triangle_order);
  for (const Material& m : geometry.materials)
    entry->reflects_specularly = entry->reflects_specularly ||
                                 m.color_source == ColorSource::kSpecular || m.specular.r != 0.0f ||
                                 m.specular.g != 0.0f || m.specular.b != 0.0f;
  return entry;
}

BlasPrepareStats BlasCache::prepare(std::span<const Geometry* const> geometries,
                                    uint64_t frame_number, double traced_pixels) {
  BlasPrepareStats stats;
  const Stopwatch timer;
  std::vector<PendingBuild> pending;
  pending.reserve(geometries.size());  // PendingBuild::geometry is pointed to: no reallocation
  std::unordered_map<uint64_t, const BlasEntry*> shapes;  // this frame's, built or found
  auto wanted = [](const Geometry* geometry) {
    return geometry != nullptr && (geometry->triangle_count() > 0 || geometry->resident);
  };
  // Shapes held already are marked used first, so a refit never takes one this frame needs.
  std::vector<const Geometry*> missing;
  for (const Geometry* geometry : geometries) {
    if (!wanted(geometry) || shapes.count(geometry->shape_hash)) continue;
    if (auto found = entries_.find(geometry->shape_hash); found != entries_.end()) {
      found->second->last_used_frame = frame_number;
      shapes[geometry->shape_hash] = found->second.get();
      ++stats.reused;
    } else if (!geometry->resident) {  // resident but not held: drawn without it this frame
      shapes[geometry->shape_hash] = nullptr;
      missing.push_back(geometry);
    }
  }
  // Refit entries leave the cache until their command is submitted (their old shape is gone);
  // should anything below throw, they are dropped with `pending`, never kept half-updated.
  for (const Geometry* geometry : missing) {
    PendingBuild& build = pending.emplace_back();
    build.shape_hash = geometry->shape_hash;
    const std::span<const glm::vec3> positions(geometry->positions.data(),
                                               3 * geometry->triangle_count());
    double refit_loss = 0.0;
    if (auto source = refit_source(*geometry, frame_number, traced_pixels, &refit_loss);
        source != entries_.end()) {
      build.refit = true;
      build.entry = std::move(source->second);
      build.entry->refit_loss = refit_loss;
      memory_bytes_ -= entry_bytes(*build.entry);
      entries_.erase(source);
      BlasEntry& entry = *build.entry;
      // Keep the shape it deforms from when that was last frame's: the denoiser reprojects
      // through the difference (the previous trace read these positions and has completed).
      if (entry.last_used_frame + 1 == frame_number) {
        if (entry.previous_positions.size() != entry.positions.size())
          entry.previous_positions = GpuBuffer::create(device_, entry.positions.size(),
                                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::memcpy(entry.previous_positions.as<std::byte>(), entry.positions.as<std::byte>(),
                    entry.positions.size());
        entry.previous_positions_address = entry.previous_positions.address();
        entry.previous_positions_frame = frame_number;
      }
      pack_positions(*geometry, entry.triangle_order,
                     {entry.positions.as<gpu::GpuPosition>(), 3 * size_t{entry.triangle_count}});
      const Bounds bounds = bounds_of(positions);
      entry.bounds_min = bounds.min;
      entry.bounds_max = bounds.max;
      ++entry.refits;
      describe_triangles(entry, build.geometry);
      build.scratch_size = entry.update_scratch_size;
    } else {
      // A lineage seen with another shape before deforms: its new BLAS is built refittable.
      const auto previous =
          geometry->lineage != 0 ? lineage_shapes_.find(geometry->lineage) : lineage_shapes_.end();
      const bool deforms =
          previous != lineage_shapes_.end() && previous->second != geometry->shape_hash;
      build.entry = create_entry(*geometry, refit_allowed_ && deforms, build);
      // Rebuilt (not refit) while deforming: the shape it deforms from, drawn last frame, gives
      // the denoiser the same per-vertex motion a refit would, in the new BLAS's order.
      if (deforms) {
        const auto from = entries_.find(previous->second);
        if (from != entries_.end() && from->second->last_used_frame + 1 == frame_number)
          keep_previous_positions(*from->second, *build.entry, frame_number);
      }
    }
    build.entry->last_used_frame = frame_number;
    stats.upload_bytes += build.entry->positions.size();
    shapes[geometry->shape_hash] = build.entry.get();
  }
  for (const Geometry* geometry : geometries)
    if (wanted(geometry) && geometry->lineage != 0)
      lineage_shapes_[geometry->lineage] = geometry->shape_hash;
  // Shading data needs only the shape's triangle order, known before the BLAS is built.
  for (const Geometry* geometry : geometries) {
    if (!wanted(geometry)) continue;
    const uint64_t key = shading_key(geometry->shape_hash, geometry->shading_hash);
    if (auto found = shading_.find(key); found != shading_.end()) {
      found->second->last_used_frame = frame_number;
      continue;
    }
    const auto shape = shapes.find(geometry->shape_hash);
    if (geometry->resident || shape == shapes.end() || shape->second == nullptr) continue;
    std::unique_ptr<ShadingEntry> entry = create_shading(*geometry, *shape->second);
    entry->last_used_frame = frame_number;
    memory_bytes_ += entry->data.size();
    stats.upload_bytes += entry->data.size();
    shading_.emplace(key, std::move(entry));
    ++stats.shading_uploads;
  }
  stats.upload_ms = timer.elapsed_ms();
  if (pending.empty()) return stats;

  // All builds and refits go into one vkCmdBuildAccelerationStructuresKHR, each with its own
  // scratch range.
  const VkDeviceSize alignment = device_.scratch_alignment();
  device_.wait(last_build_);  // its scratch_ is reused (or replaced) here
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
    info =
        acceleration_build_info(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, &build.geometry);
    info.flags = build_flags(*build.entry);
    info.dstAccelerationStructure = build.entry->blas.get();
    if (build.refit) {
      // In place, as the specification allows for updates.
      info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR;
      info.srcAccelerationStructure = build.entry->blas.get();
    }
    info.scratchData.deviceAddress = scratch_address;
    scratch_address += align_up(build.scratch_size, alignment);
    ranges.push_back({build.entry->triangle_count, 0, 0, 0});
  }
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> range_pointers;
  for (const auto& range : ranges) range_pointers.push_back(&range);

  last_build_ = stats.build_ticket = device_.submit([&](VkCommandBuffer cmd) {
    device_.as_functions().cmd_build(cmd, static_cast<uint32_t>(infos.size()), infos.data(),
                                     range_pointers.data());
  });
  // The builds run on the device after this returns; `pending` owns what they write into until
  // the cache does. Should the hand-over throw (out of memory), the entries still in `pending`
  // go with it: the builds must be complete first.
  try {
    for (PendingBuild& build : pending) {
      const size_t bytes = entry_bytes(*build.entry);
      (build.refit ? stats.refits : stats.builds) += 1;
      entries_.emplace(build.shape_hash, std::move(build.entry));
      memory_bytes_ += bytes;
    }
  } catch (...) {
    device_.wait(last_build_);
    throw;
  }
  return stats;
}

const BlasEntry* BlasCache::find(uint64_t shape_hash) const {
  auto found = entries_.find(shape_hash);
  return found == entries_.end() ? nullptr : found->second.get();
}

bool BlasCache::holds(uint64_t shape_hash, uint64_t shading_hash) const {
  return entries_.count(shape_hash) != 0 &&
         shading_.count(shading_key(shape_hash, shading_hash)) != 0;
}

const ShadingEntry* BlasCache::find_shading(uint64_t shape_hash, uint64_t shading_hash) const {
  auto found = shading_.find(shading_key(shape_hash, shading_hash));
  return found == shading_.end() ? nullptr : found->second.get();
}

void BlasCache::evict_unused(uint64_t frame_number) {
  auto expired = [&](uint64_t last_used) {
    return last_used + kEvictAfterUnusedFrames < frame_number;
  };
  std::erase_if(entries_, [&](const auto& item) {
    if (!expired(item.second->last_used_frame)) return false;
    memory_bytes_ -= entry_bytes(*item.second);
    return true;
  });
  // Shading data goes with its shape (and on its own when unused).
  std::erase_if(shading_, [&](const auto& item) {
    if (!expired(item.second->last_used_frame) && entries_.count(item.second->shape_hash))
      return false;
    memory_bytes_ -= item.second->data.size();
    return true;
  });
  std::erase_if(lineage_shapes_,
                [&](const auto& item) { return entries_.count(item.second) == 0; });
  if (memory_bytes_ <= kMemoryBudgetBytes) return;

  std::vector<std::pair<uint64_t, uint64_t>> by_age;  // (last used frame, shape hash)
  for (const auto& [hash, entry] : entries_) {
    if (entry->last_used_frame < frame_number) by_age.emplace_back(entry->last_used_frame, hash);
  }
  std::sort(by_age.begin(), by_age.end());
  for (const auto& aged : by_age) {
    // Not a structured binding: Clang 14 cannot capture one in the lambda below (P1091, Clang 16).
    const auto hash = aged.second;
    if (memory_bytes_ <= kMemoryBudgetBytes) break;
    auto found = entries_.find(hash);
    memory_bytes_ -= entry_bytes(*found->second);
    entries_.erase(found);
    std::erase_if(shading_, [&](const auto& item) {
      if (item.second->shape_hash != hash) return false;
      memory_bytes_ -= item.second->data.size();
      return true;
    });
  }
  // Old shading of shapes still in use (recoloured every frame): dropped when unused this frame.
  if (memory_bytes_ > kMemoryBudgetBytes) {
    std::erase_if(shading_, [&](const auto& item) {
      if (item.second->last_used_frame >= frame_number) return false;
      memory_bytes_ -= item.second->data.size();
      return true;
    });
  }
}

}  // namespace glpt::rt
