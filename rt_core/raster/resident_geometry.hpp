// Vertex data that later records draw again unchanged stays on the GPU.
//
// A record's draws are normally copied into the per-record upload buffer. A draw whose
// rec::VertexData is the same object in the next record (the same content_id: a static buffer
// object the front end hands out again, gl_shim/arrays/buffer_draw_cache.hpp) is uploaded once
// into a buffer of its own on its second execute and drawn from there while it keeps being
// drawn, together with what the renderer derived from it: whether its triangles are drawn in
// vertex order, with its own indices. A static VBO of 300 000 vertices then costs no copy and no
// decomposition per frame, as Mesa's llvmpipe reads a VBO in place. Draws below kMinBytes stay in
// the upload buffer: copying them costs less than a buffer of their own.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "raster_types.h"
#include "rt_core/record/decompose.hpp"
#include "rt_core/record/frame_record.hpp"
#include "rt_core/vk/gpu_buffer.hpp"

namespace glpt::rt {

class ResidentGeometry {
 public:
  static constexpr size_t kMinBytes = size_t{256} << 10;
  // An entry not drawn by this many executes in a row is released.
  static constexpr uint64_t kKeepExecutes = 8;

  struct Entry {
    GpuBuffer buffer;  // the draw's non-empty attribute arrays, then its indices
    std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT> offsets{};  // per attribute location
    VkDeviceSize index_offset = 0;                               // its indices, if it has them
    uint64_t last_used = 0;

    // Filled triangles found to be drawn in vertex order (their own or ascending indices), with
    // the assembly state they were found for when the decomposition consulted it.
    bool in_vertex_order(const rec::AssemblyState& assembly, uint32_t* index_count) const;
    // `assembly_consulted`: the decomposition depended on `assembly` (Decomposed).
    void found_in_vertex_order(uint32_t index_count, bool assembly_consulted,
                               const rec::AssemblyState& assembly);

   private:
    bool vertex_order_known_ = false;
    uint32_t vertex_order_index_count_ = 0;
    bool assembly_consulted_ = false;
    rec::AssemblyState assembly_;
  };

  // The resident entry of `vertices` when an earlier execute drew them too (uploaded now if this
  // is the second time); null for draws below kMinBytes and on first sight. `execute` counts the
  // caller's executes. Throws VulkanError.
  Entry* use(const VulkanDevice& device, const rec::VertexData& vertices, uint64_t execute);
  // Releases entries (and first sightings) not drawn in the last kKeepExecutes executes. The GPU
  // must be done with them (RasterRenderer waits for each execute's submission).
  void release_unused(uint64_t execute);
  size_t size() const { return entries_.size(); }
  // Bytes copied into new entries since the last call.
  size_t take_uploaded_bytes() { return std::exchange(uploaded_bytes_, 0); }

 private:
  size_t uploaded_bytes_ = 0;
  std::unordered_map<uint64_t, Entry> entries_;  // by content_id
  std::unordered_map<uint64_t, uint64_t> seen_;  // content_id -> execute that last drew it
};

}  // namespace glpt::rt
