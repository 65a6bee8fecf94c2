// Internal to rt_core/raster: what RasterRenderer's implementation files share while they record
// one frame record into command buffers (raster_renderer.cpp: clears and draws;
// pixel_commands.cpp: pixel rectangles and the accumulation buffer).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "raster_types.h"
#include "rt_core/raster/raster_renderer.hpp"

namespace glpt::rt {

inline bool finite(const glm::vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// The front and back colour buffers (and the upside-down copy of mesa_orientation.cpp): how
// they are made and what the single-target render pass's framebuffers declare (all must agree).
inline constexpr VkImageUsageFlags kColorUsage =
    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT |
    VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
    VK_IMAGE_USAGE_STORAGE_BIT;

// The colour buffers are BGRA8 (kColorFormat); the front end speaks RGBA8.
inline void swap_red_and_blue(uint8_t* pixels, size_t count) {
  for (size_t i = 0; i < count; ++i) std::swap(pixels[4 * i], pixels[4 * i + 2]);
}

// Lays out the per-record upload buffer (pieces 16-byte aligned) and fills it. Data the renderer
// makes itself (indices, materials, quads) is copied into `local` at once; the record's vertex
// arrays are only referenced (add_external) and copied once, straight into the mapped Vulkan
// buffer (write_to): a frame's megabytes of vertices are not copied twice.
class Arena {
 public:
  explicit Arena(std::vector<uint8_t>& local) : local_(local) { local_.clear(); }
  template <typename T>
  VkDeviceSize add(const T* data, size_t count) {
    const size_t bytes = count * sizeof(T);
    const VkDeviceSize offset = place(nullptr, local_.size(), bytes);
    // Appended, not resized and then copied over: zero-filling megabytes first costs as much.
    const auto* p = reinterpret_cast<const uint8_t*>(data);
    if (bytes > 0) local_.insert(local_.end(), p, p + bytes);
    return offset;
  }
  // `data` must stay valid and unchanged until write_to.
  template <typename T>
  VkDeviceSize add_external(const T* data, size_t count) {
    return place(reinterpret_cast<const uint8_t*>(data), 0, count * sizeof(T));
  }
  // A region of `bytes` that add_external_at() and add_repeated_at() fill (all of it, before
  // write_to: nothing else writes it).
  VkDeviceSize reserve(size_t bytes) {
    const VkDeviceSize offset = place(nullptr, 0, 0);
    size_ = offset + bytes;
    return offset;
  }
  void add_external_at(VkDeviceSize offset, const uint8_t* data, size_t bytes) {
    if (bytes > 0) pieces_.push_back({offset, data, 0, bytes});
  }
  void add_repeated_at(VkDeviceSize offset, const uint8_t* element, size_t element_bytes,
                       size_t count) {
    const size_t local_offset = local_.size();
    local_.resize(local_offset + element_bytes * count);
    for (size_t k = 0; k < count; ++k)
      std::memcpy(local_.data() + local_offset + k * element_bytes, element, element_bytes);
    if (count > 0) pieces_.push_back({offset, nullptr, local_offset, element_bytes * count});
  }
  size_t size() const { return size_; }
  // Copies every piece to its offset in `destination` (size() bytes).
  void write_to(uint8_t* destination) const {
    for (const Piece& piece : pieces_) {
      const uint8_t* source = piece.external ? piece.external : local_.data() + piece.local_offset;
      std::memcpy(destination + piece.offset, source, piece.bytes);
    }
  }

 private:
  struct Piece {
    VkDeviceSize offset;
    const uint8_t* external;  // null: local_ at local_offset
    size_t local_offset;
    size_t bytes;
  };
  VkDeviceSize place(const uint8_t* external, size_t local_offset, size_t bytes) {
    const size_t offset = (size_ + 15) & ~size_t{15};
    size_ = offset + bytes;
    if (bytes > 0) pieces_.push_back({offset, external, local_offset, bytes});
    return offset;
  }
  std::vector<uint8_t>& local_;
  std::vector<Piece> pieces_;
  size_t size_ = 0;
};

inline VkRect2D intersect_with_framebuffer(int32_t x, int32_t y, int32_t w, int32_t h,
                                           const rec::DrawableConfig& d) {
  const int64_t x0 = std::clamp<int64_t>(x, 0, d.width), y0 = std::clamp<int64_t>(y, 0, d.height);
  const int64_t x1 = std::clamp<int64_t>(int64_t{x} + std::max(w, 0), 0, d.width);
  const int64_t y1 = std::clamp<int64_t>(int64_t{y} + std::max(h, 0), 0, d.height);
  return {{static_cast<int32_t>(x0), static_cast<int32_t>(y0)},
          {static_cast<uint32_t>(x1 - x0), static_cast<uint32_t>(y1 - y0)}};
}

inline VkRect2D scissor_of(const rec::FragmentOpsState& ops, const rec::DrawableConfig& d) {
  if (!ops.scissor_test) return {{0, 0}, {d.width, d.height}};
  return intersect_with_framebuffer(ops.scissor_box[0], ops.scissor_box[1], ops.scissor_box[2],
                                    ops.scissor_box[3], d);
}

// The vertex attributes of a draw as the raster pipelines read them: `f(location, values,
// default_at)` for each, where `values` is the record's array (possibly empty: the attribute then
// reads the default value at byte `default_at` of the renderer's defaults).
template <typename F>
void for_each_attribute(const rec::VertexData& v, F&& f) {
  f(GLPT_RASTER_ATTR_POSITION, v.position, 0);
  f(GLPT_RASTER_ATTR_NORMAL, v.normal, 16);
  f(GLPT_RASTER_ATTR_COLOR, v.color, 32);
  f(GLPT_RASTER_ATTR_SECONDARY, v.secondary_color, 64);
  f(GLPT_RASTER_ATTR_FOG, v.fog_coord, 64);
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    f(GLPT_RASTER_ATTR_TEXCOORD0 + u, v.tex_coord[u], 48);
}

// Where one draw's attributes and indices are: the upload buffer, unless `buffers` /
// `index_buffer` name another (resident geometry).
struct RasterRenderer::DrawGeometry {
  std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT> offsets{};
  std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT> strides{};
  std::array<VkBuffer, GLPT_RASTER_ATTR_COUNT> buffers{};  // null: the upload buffer
  VkDeviceSize index_offset = 0;
  uint32_t index_count = 0;
  VkBuffer index_buffer = VK_NULL_HANDLE;  // null: the upload buffer (or ascending_indices)
  // Where the indices are: the upload buffer, or (for triangles drawn in vertex order) the
  // renderer's buffer of ascending indices.
  bool ascending_indices = false;
  VkDeviceSize edge_offset = 0;  // unfilled draws: per-triangle boundary-edge masks
  RasterTopology topology = RasterTopology::kTriangles;
  // Per-vertex materials (RasterPushConstants::materials): all zero when the draw has none.
  glm::uvec4 materials{0u};
  // Added to every index (vkCmdDrawIndexed's vertexOffset): where the draw's vertices start in
  // the record's shared vertex streams (vertex_streams.hpp).
  int32_t vertex_offset = 0;
  // The draws after this one whose triangles it draws too (draw_merging.hpp); their own
  // geometry is empty.
  uint32_t merged_draws = 0;
};

// How one pixel rectangle (glBitmap, glDrawPixels, glCopyPixels) is drawn; prepared with the
// record's uploads (pixel_commands.cpp).
struct RasterRenderer::PixelPlan {
  bool prepared = false;
  uint32_t state = 0;       // its entry in the states buffer
  DrawGeometry quad;        // the image's window rectangle as two triangles
  uint32_t first_word = 0;  // its image (a copy: where the source is copied to) in pixels_
  bool blit = false;        // a glCopyPixels Mesa does as a plain copy (blit_copy_pixels)
  VkRect2D blit_source{}, blit_destination{};
};

struct RasterRenderer::Recording {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  const rec::FrameRecord* record = nullptr;
  FrameStats* stats = nullptr;
  std::vector<DrawGeometry> geometry;  // per command index (draws only)
  std::vector<uint32_t> clear_state;   // per command index: the state entry of a quad clear
  std::vector<PixelPlan> pixels;       // per command index (pixel rectangles only)
  // Per command index: a draw whose vertices go into the record's vertex streams
  // (VertexStreams::takes, asked once per draw).
  std::vector<uint8_t> streamed;
  // Per command index: 1 for a draw split by alpha (path-traced mode, DrawClass::kSplitByAlpha):
  // its opaque fragments into the G-buffer, its others over the trace. Null: none.
  const std::vector<uint8_t>* split_by_alpha = nullptr;
  bool split(size_t command) const {
    return split_by_alpha != nullptr && command < split_by_alpha->size() &&
           (*split_by_alpha)[command] != 0;
  }
  DrawGeometry clear_geometry;
  bool rendering = false;
  bool in_render_pass = false;  // rendering in RasterPipelines::render_pass (else dynamic)
  ColorTargets targets = ColorTargets::kBack;
  // The colour buffer whose pixels are in RasterRenderer::mesa_image_ upside down, where draws
  // rasterized in Mesa's orientation go (kNone: none; mesa_orientation.cpp).
  ColorTargets mesa_target = ColorTargets::kNone;
  VkPipeline bound_pipeline = VK_NULL_HANDLE;
  // Texture descriptors of the bound set, per binding (to skip redundant binds).
  std::array<VkImageView, 4 * GLPT_RASTER_MAX_UNITS> bound_views{};
  // ... and their samplers: a texture whose parameters changed keeps its view (same texels).
  std::array<VkSampler, 4 * GLPT_RASTER_MAX_UNITS> bound_samplers{};
  VkImageView bound_framebuffer = VK_NULL_HANDLE;  // ... and the colour buffer shaders read
  bool descriptors_pushed = false;
  // The sets written in this command buffer, by their textures: a frame that switches between a
  // few textures binds a few sets, not one per switch (the buffers are the same for all).
  struct WrittenSet {
    std::array<VkImageView, 4 * GLPT_RASTER_MAX_UNITS> views;
    std::array<VkSampler, 4 * GLPT_RASTER_MAX_UNITS> samplers;
    VkImageView framebuffer;
    VkDescriptorSet set;
  };
  std::vector<WrittenSet> written_sets;
  // Dynamic state last set in this command buffer.
  bool dynamic_valid = false;
  DynamicDrawState dynamic;
  // The key whose blend state was last set (RasterPipelines::set_blend_state), when valid.
  bool blend_valid = false;
  PipelineKey blend_key;
  VkViewport viewport{};
  VkRect2D scissor{};
  // The push constants last pushed in this command buffer, when valid.
  bool push_valid = false;
  gpu::RasterPushConstants pushed{};
  // The state index last pushed for the vertex stage (RasterPushConstants::indices.x), when
  // valid (both are invalid after a pipeline change).
  bool state_index_valid = false;
  uint32_t pushed_state_index = 0;
  // The vertex and index buffers last bound in this command buffer, when valid.
  bool geometry_bound = false;
  std::array<VkBuffer, GLPT_RASTER_ATTR_COUNT> bound_buffers{};
  std::array<VkDeviceSize, GLPT_RASTER_ATTR_COUNT> bound_offsets{}, bound_strides{};
  VkBuffer bound_index_buffer = VK_NULL_HANDLE;
  const GBufferTargets* gbuffer = nullptr;  // path-traced mode's G-buffer pass
  // The occlusion query the command being recorded counts into (0: none); its draw calls pass
  // it to OcclusionQueries::before_draw.
  uint64_t counting = 0;
};

}  // namespace glpt::rt
