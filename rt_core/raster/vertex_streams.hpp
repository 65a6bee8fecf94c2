// The vertices of a record's small draws in one array per attribute, shared by all of them.
//
// Each draw used to bind its own vertex arrays and index list (vkCmdBindVertexBuffers2 with every
// attribute location, vkCmdBindIndexBuffer) before its vkCmdDrawIndexed. lavapipe records each
// command as a heap entry and hands every new binding to llvmpipe's draw module again: with
// the draws' vertices back to back in shared streams, consecutive draws bind nothing and differ
// only in vkCmdDrawIndexed's firstIndex and vertexOffset (bench/many_draws, 2,000 draws a frame:
// binding once per command buffer measured 16 % less CPU). The price is one copy of a draw's
// single values (the current normal of a whole glBegin/glEnd, say) per vertex.
//
// Taken: draws without per-vertex materials (the vertex shader finds those by gl_VertexIndex,
// which vertexOffset moves) below ResidentGeometry::kMinBytes (larger ones are read where they
// are, or stay resident). Attribute locations no taken draw gives values for read the default.
#pragma once

#include <array>
#include <cstdint>

#include "rt_core/raster/raster_recording.hpp"

namespace glpt::rt {

class VertexStreams {
 public:
  // Whether `v`'s vertices go into the streams.
  static bool takes(const rec::VertexData& v);

  // First every draw the streams take, to size them; then reserve().
  void count(const rec::VertexData& v);
  // Lays the streams out in `arena`; false (nothing taken) when there is nothing to take or too
  // much for 32-bit vertex offsets.
  bool reserve(Arena& arena);
  bool reserved() const { return reserved_; }
  // Whether `count` more vertices fit in what was counted (add() writes nothing past it).
  bool fits(uint64_t count) const { return reserved_ && next_ + count <= vertices_; }

  // Places `v`'s attributes at the streams' next vertex (defaults: the renderer's default values,
  // by for_each_attribute's default_at); returns that vertex, the draw's vertexOffset. Only for
  // vertices that fit().
  int32_t add(const rec::VertexData& v, Arena& arena, const uint8_t* defaults);

  // Where a taken draw's attributes are: the streams, or `default_offset + default_at` with
  // stride 0 for locations no taken draw gives.
  void locate(VkDeviceSize default_offset,
              std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& offsets,
              std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT>& strides) const;

 private:
  static constexpr uint64_t kMaxVertices = uint64_t{1} << 26;
  uint32_t locations_ = 0;  // bit per attribute location a taken draw gives values for
  uint64_t vertices_ = 0;   // counted
  uint64_t next_ = 0;       // added
  bool reserved_ = false;
  std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT> offsets_{}, element_bytes_{};
  std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT> default_at_{};
};

}  // namespace glpt::rt
