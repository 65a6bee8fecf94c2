// Bottom-level acceleration structures, one per distinct shape (Geometry::shape_hash), built once
// and reused across frames, and the shading data of each (shape, shading) pair in the same sorted
// order. Recolouring a shape (new colours, normals or materials) uploads new shading data and
// reuses the BLAS. A deforming object (the same draws, Geometry::lineage, with new positions of
// as many triangles) refits its previous shape's BLAS in place instead of building a new one,
// until what the refit tree costs the rays would exceed a build (BlasCache::kMaxRefits,
// kBuiltTrianglesPerTracedPixel).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "rt_core/scene/shading_data.hpp"
#include "rt_core/scene/trace_scene.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "rt_core/vk/vk_raii.hpp"

namespace glpt::rt {

struct BlasEntry {
  GpuBuffer positions;  // gpu::GpuPosition[3 * triangle_count]: the BLAS build input
  VkDeviceAddress positions_address = 0;
  GpuBuffer storage;  // backs `blas`
  vk::AccelerationStructure blas;
  VkDeviceAddress blas_address = 0;
  // BLAS primitive index -> triangle index in the Geometry (Morton order, see morton_sort.hpp).
  std::vector<uint32_t> triangle_order;
  uint32_t triangle_count = 0;
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};  // object space, finite vertices only
  uint64_t last_used_frame = 0;
  // Built with VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR (its lineage has deformed
  // before): it can be refit to new positions of the same triangles.
  bool updatable = false;
  VkDeviceSize update_scratch_size = 0;
  uint32_t refits = 0;  // since it was built
  // tree_cost() of the shape it was built for (refittable entries only), and the sum over its
  // refits of how much more the refit tree cost (cost / built_tree_cost - 1).
  float built_tree_cost = 0.0f;
  double refit_loss = 0.0;
  // The positions before its last refit (same size and order as `positions`), when the shape it
  // was refit from was used the frame before: how the surface deformed since, for the
  // denoiser's reprojection (GpuInstance.tables.zw). Valid in frame `previous_positions_frame`.
  GpuBuffer previous_positions;
  VkDeviceAddress previous_positions_address = 0;
  uint64_t previous_positions_frame = 0;
};

struct ShadingEntry {
  GpuBuffer data;  // gpu::ShadingVertex[3 * triangle_count], then gpu::GpuMaterial[]
  VkDeviceAddress vertices_address = 0;
  VkDeviceAddress materials_address = 0;
  uint64_t shape_hash = 0;
  uint64_t last_used_frame = 0;
  // The shape's triangles in BLAS primitive order with their emission, when any emits (host
  // memory: each frame places them in eye space for next-event estimation); else empty.
  std::vector<EmitterTriangle> emitters;
  // A material of it has a specular lobe (GL_SPECULAR not black, or the vertex colour under
  // GL_COLOR_MATERIAL(GL_SPECULAR)): light can reach the tracer's specular channel through it.
  bool reflects_specularly = false;
};

struct BlasPrepareStats {
  double upload_ms = 0;  // host work: sorting, packing, allocating
  // The builds' submission (0: none), not waited for: the trace submitted after it sees them.
  VulkanDevice::Ticket build_ticket = 0;
  uint32_t builds = 0;
  uint32_t refits = 0;  // BLASes updated in place to a deformed shape (counted apart from builds)
  uint32_t reused = 0;
  uint32_t shading_uploads = 0;
  uint64_t upload_bytes = 0;  // BLAS inputs (positions) and shading data written
};

class BlasCache {
 public:
  // Entries not used for this many frames are dropped (geometry that changes every frame would
  // otherwise accumulate without bound).
  static constexpr uint64_t kEvictAfterUnusedFrames = 60;
  // Above this many bytes (positions, BLASes, shading data), the least recently used entries not
  // needed by the current frame go early: a program that streams new geometry every frame would
  // otherwise keep 60 frames' worth of it.
  static constexpr VkDeviceSize kMemoryBudgetBytes = VkDeviceSize{512} << 20;

  // Refit or build anew: a refit costs little (lavapipe, this machine: 0.06 us a triangle
  // against 0.3 us for a build, and half the host work) but keeps the tree of the shape it was
  // built for, whose boxes grow as the triangles move apart, so every ray through it costs more
  // (tree_cost() in blas_cache.cpp estimates by how much). A deforming shape is refit until the
  // refits' summed loss (growth of the tree's cost over its built cost, per frame) would exceed
  // what a build costs: its triangles / (kBuiltTrianglesPerTracedPixel x the pixels traced per
  // frame), since tracing a frame's pixel costs about as much as building 5 triangles (measured
  // with bench/bench_refit.sh: docs/classification.md, "Deforming geometry"). So a small mesh
  // under many pixels is rebuilt every frame or two and a large one refit for many frames; at
  // most kMaxRefits in a row.
  static constexpr uint32_t kMaxRefits = 16;
  static constexpr double kBuiltTrianglesPerTracedPixel = 5.0;

  explicit BlasCache(VulkanDevice& device) : device_(device) {}
  // GLPT_BLAS_REFIT=0: every deformed shape is built anew (for A/B measurements).
  void allow_refit(bool allow) { refit_allowed_ = allow; }

  // Makes sure every geometry (with at least one triangle) has a BLAS entry for its shape and a
  // shading entry for its shading, building all missing BLASes in one submission. Duplicates
  // count once. Resident geometries (no arrays) only mark their entries used. A geometry whose
  // lineage had another shape in an earlier frame refits that shape's BLAS when it is unused
  // this frame, has as many triangles and may still be refit. Throws VulkanError; entries whose
  // build did not complete are not kept.
  // `traced_pixels`: paths the frame traces (pixels x scale^2 x samples), which decides between
  // refit and build (kBuiltTrianglesPerTracedPixel).
  BlasPrepareStats prepare(std::span<const Geometry* const> geometries, uint64_t frame_number,
                           double traced_pixels);

  const BlasEntry* find(uint64_t shape_hash) const;
  // Both the shape's BLAS and this shading of it are held.
  bool holds(uint64_t shape_hash, uint64_t shading_hash) const;
  const ShadingEntry* find_shading(uint64_t shape_hash, uint64_t shading_hash) const;
  // Drops entries unused for kEvictAfterUnusedFrames, then, while over kMemoryBudgetBytes, the
  // least recently used ones not used in `frame_number`.
  void evict_unused(uint64_t frame_number);
  size_t size() const { return entries_.size(); }
  VkDeviceSize memory_bytes() const { return memory_bytes_; }

 private:
  struct PendingBuild;
  std::unique_ptr<BlasEntry> create_entry(const Geometry& geometry, bool updatable,
                                          PendingBuild& build) const;
  // The entry of the shape `geometry`'s lineage had before, when it can be refit to `geometry`
  // this frame and refitting costs less than a build (`traced_pixels`: prepare()'s); else
  // entries_.end(). `refit_loss`: the entry's summed loss after this refit.
  std::unordered_map<uint64_t, std::unique_ptr<BlasEntry>>::iterator refit_source(
      const Geometry& geometry, uint64_t frame_number, double traced_pixels, double* refit_loss);
  // Gives `to`, a new BLAS of a shape `from` deforms into (as many triangles, another order),
  // `from`'s positions as its previous positions, in `to`'s order.
  void keep_previous_positions(const BlasEntry& from, BlasEntry& to, uint64_t frame_number) const;
  std::unique_ptr<ShadingEntry> create_shading(const Geometry& geometry,
                                               const BlasEntry& shape) const;

  VulkanDevice& device_;
  std::unordered_map<uint64_t, std::unique_ptr<BlasEntry>> entries_;
  std::unordered_map<uint64_t, std::unique_ptr<ShadingEntry>> shading_;  // by shading_key()
  GpuBuffer scratch_;  // shared by all builds; only one batch is in flight at a time
  VulkanDevice::Ticket last_build_ = 0;  // the batch that last used scratch_
  VkDeviceSize memory_bytes_ = 0;        // bytes of every entry's buffers
  // Each lineage's latest shape (bounded by the entries: dropped with its shape).
  std::unordered_map<uint64_t, uint64_t> lineage_shapes_;
  bool refit_allowed_ = true;
};

}  // namespace glpt::rt
