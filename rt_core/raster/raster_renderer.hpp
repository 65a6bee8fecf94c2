// Raster mode: executes a frame record with Vulkan graphics pipelines that emulate GL 1.5 fixed
// function, on the drawable's persistent buffers (colour front and back, depth/stencil). The
// pixels are meant to equal Mesa's (docs/architecture.md, "Raster mode").
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "rt_core/frame_stats.hpp"
#include "rt_core/raster/accumulation.hpp"
#include "rt_core/raster/descriptor_set_ring.hpp"
#include "rt_core/raster/drawable_buffers.hpp"
#include "rt_core/raster/gbuffer_targets.hpp"
#include "rt_core/raster/occlusion_queries.hpp"
#include "rt_core/raster/pipeline_key.hpp"
#include "rt_core/raster/raster_pipelines.hpp"
#include "rt_core/raster/resident_geometry.hpp"
#include "rt_core/raster/texture_cache.hpp"
#include "rt_core/record/decompose.hpp"
#include "rt_core/record/frame_record.hpp"
#include "rt_core/renderer.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/gpu_image.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

namespace gpu {
struct RasterState;
struct RasterPushConstants;
}  // namespace gpu
class Arena;
class VertexStreams;

class RasterRenderer {
 public:
  explicit RasterRenderer(std::shared_ptr<VulkanDevice> device);

  // Applies the commands of `record` whose indices `commands` lists (all when empty) to the
  // drawable's `buffers`, which are (re)created when `drawable` changes. Throws VulkanError.
  // `end`: swap and/or read the front buffer in the same submission.
  // `gbuffer` (path-traced mode): the draws it marks go into the G-buffer instead of the colour
  // buffers (same coverage, depth and stencil); its SURFACE attachment starts cleared and every
  // colour clear clears it too.
  // `queries`: the samples these commands count into the record's occlusion queries are added
  // to it (an entry per query of the record, occlusion_queries.hpp).
  void execute(const rec::FrameRecord& record, DrawableBuffers& buffers,
               const rec::DrawableConfig& drawable, FrameStats& stats,
               const std::vector<size_t>* commands = nullptr, const FrameEnd* end = nullptr,
               const GBufferTargets* gbuffer = nullptr,
               std::vector<QuerySamples>* queries = nullptr,
               const std::vector<uint8_t>* split_by_alpha = nullptr);

  // The end of a frame, after the device completed it (every execute of the frame submits
  // without waiting unless it reads results on the host): adds the device time of the frame's
  // submissions to `stats` and releases textures and geometry unused for a while.
  void end_frame(FrameStats& stats);

  // Reads back a rectangle: colour as RGBA8 of GL_FRONT*/GL_BACK*, depth as [0, 1], stencil.
  // Pixels outside the drawable are zero. False before the buffers exist.
  bool read_color(DrawableBuffers& buffers, uint32_t buffer, int32_t x, int32_t y, uint32_t width,
                  uint32_t height, std::vector<uint8_t>& rgba);
  bool read_depth(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width, uint32_t height,
                  std::vector<float>& depth);
  bool read_stencil(DrawableBuffers& buffers, int32_t x, int32_t y, uint32_t width, uint32_t height,
                    std::vector<uint8_t>& stencil);
  // The textures of the records drawn so far (path-traced mode's rays sample them).
  TextureCache& textures() { return textures_; }
  // Copies the back buffer into the front buffer (the back keeps its contents).
  void swap_buffers(DrawableBuffers& buffers);
  // Replaces a whole colour buffer with `rgba` (RGBA8, rows bottom to top): the path tracer's
  // image, before the draws it does not take are rasterized over it.
  void write_color(bool front, const std::vector<uint8_t>& rgba);
  // The same for the front buffer of `buffers`, created for `drawable` first if they are not.
  void write_front_color(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                         const std::vector<uint8_t>& rgba);
  // The depth buffer of `buffers` (created for `drawable` if need be) takes `depth` (window z in
  // [0, 1], rows bottom to top, the drawable's size); stencil is kept.
  void write_depth(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                   const std::vector<float>& depth);
  // Renderer::write_pixels: a rectangle of colour, depth and stencil written as it is.
  void write_pixels(DrawableBuffers& buffers, const rec::DrawableConfig& drawable,
                    const PixelWrite& pixels);

  VulkanDevice& device() { return *device_; }
  // The buffers of the last execute, for path-traced mode (which writes the traced image into
  // them).
  const GpuImage& color_image(bool front) const { return front ? buffers_->front : buffers_->back; }
  const GpuImage& depth_stencil_image() const { return buffers_->depth_stencil; }

 private:
  struct DrawGeometry;  // uploaded vertices and indices of one draw
  struct Recording;     // state of one command-buffer recording
  void ensure_buffers(DrawableBuffers& buffers, const rec::DrawableConfig& drawable);
  void record_clear(Recording& r, const rec::Clear& clear, uint32_t state_index);
  // Geometry for the run of draws at `position` of `commands` drawn as one (draw_merging.hpp),
  // into the first one's DrawGeometry; returns the run's length (0: the draw is not merged).
  size_t merge_draws(Recording& r, const std::vector<size_t>& commands, size_t position,
                     Arena& arena, VertexStreams& streams, const uint8_t* defaults,
                     VkDeviceSize default_offset);
  // A merged draw's vertices stay far from 32-bit indices and from megabyte index lists.
  static constexpr uint64_t kMaxMergedVertices = uint64_t{1} << 20;
  // `fs_flags`: GLPT_FS_* bits the draw's fragment shader adds (the part of a draw split by
  // alpha it draws).
  void record_draw(Recording& r, const rec::Draw& draw, const DrawGeometry& geometry,
                   bool to_gbuffer = false, uint32_t fs_flags = 0);
  void record_draw_pass(Recording& r, const rec::Draw& draw, const DrawGeometry& geometry,
                        VkCullModeFlags face_pass, bool to_gbuffer = false, uint32_t fs_flags = 0);
  void clear_gbuffer_surface(Recording& r, const VkRect2D& rect);
  // How draws into a rendering instance are made: pipelines for dynamic rendering, pipelines
  // blending in the shader (the render pass of RasterPipelines::render_pass, one colour target),
  // or only vkCmdClearAttachments, which any instance takes.
  enum class RenderingKind : uint8_t { kDynamic, kRenderPass, kAny };
  void begin_rendering(Recording& r, ColorTargets targets,
                       RenderingKind kind = RenderingKind::kDynamic);
  void end_rendering(Recording& r);  // ends the rendering instance (and counting in it)
  void bind(Recording& r, const PipelineKey& key, const rec::StateSnapshot* textures_of);
  // In GL's orientation, or mirrored for a draw in Mesa's (mesa_orientation.cpp).
  void set_dynamic_state(Recording& r, const DynamicDrawState& d, const VkViewport& viewport,
                         const VkRect2D& scissor);
  void set_oriented_dynamic_state(Recording& r, const DynamicDrawState& d,
                                  const VkViewport& viewport, const VkRect2D& scissor);
  void record_frame_end(VkCommandBuffer cmd, const FrameEnd& end);

  // ---- draws rasterized in Mesa's orientation (mesa_orientation.cpp) ----
  // Whether a draw of this setup is rasterized upside down, as Mesa renders window-system
  // buffers, so that its interpolated values (and the anisotropic filter's choices made from
  // their last bits) are Mesa's.
  bool draws_in_mesa_orientation(const PipelineKey& key, const DynamicDrawState& d,
                                 ColorTargets targets) const;
  // Makes `target` (a colour buffer, or kNone for none) the one draws go to upside down:
  // copies the buffer in use so far back, and `target` into mesa_image_, rows reversed.
  void use_mesa_orientation(Recording& r, ColorTargets target);
  // The view a draw into colour buffer `target` renders to (mesa_image_ for
  // Recording::mesa_target).
  VkImageView color_view(const Recording& r, ColorTargets target) const;
  // DrawableBuffers::back_is_front: records the copy of the front into the back (and clears the
  // flag); restore_back() submits it now, before a read or partial write of the back.
  void record_restore_back(VkCommandBuffer cmd);
  void restore_back();
  // Waits for the host's reads of the back image in flight (FrameEnd::front_pixels), or of both
  // colour images with `front_too`: before anything that may write them.
  void wait_for_host_reads(bool front_too);
  // Whether any of `commands` may write the front colour buffer.
  bool may_write_front(const rec::FrameRecord& record, const std::vector<size_t>& commands) const;
  // Whether the first of `commands` (of `record`) that touches colour is a clear of every pixel
  // and channel of the back buffer: what the back held before does not matter then.
  bool begins_with_whole_back_clear(const rec::FrameRecord& record,
                                    const std::vector<size_t>& commands) const;
  // read_color on the buffers of the call in progress (glAccum reads the read buffer).
  bool read_current_color(uint32_t buffer, int32_t x, int32_t y, uint32_t width, uint32_t height,
                          std::vector<uint8_t>& rgba);
  // Binds the geometry's buffers where they differ from the bound ones and draws it.
  // (The state index goes to the vertex stage as a push constant of its own: raster_types.h.)
  void draw_geometry(Recording& r, const DrawGeometry& geometry, uint32_t state_index);
  // vkCmdPushConstants where they differ from the last ones of the command buffer.
  void push_constants(Recording& r, const gpu::RasterPushConstants& push);
  // ascending_ holds 0, 1, 2, ... for at least `count` indices.
  void ensure_ascending_indices(uint32_t count);
  bool read_image(const GpuImage& image, VkImageAspectFlags aspect, uint32_t texel_bytes, int32_t x,
                  int32_t y, uint32_t width, uint32_t height, std::vector<uint8_t>& out);
  // Replaces the rectangle `rect` of a colour image with `rgba` (RGBA8, rows bottom to top).
  void write_image(const GpuImage& image, const VkRect2D& rect, const std::vector<uint8_t>& rgba);
  // Uploads `bytes` into the rectangle `rect` of one aspect of the depth-stencil image: 32-bit
  // words of 24-bit depth, or 8-bit stencil indices.
  void write_depth_stencil(VkImageAspectFlags aspect, const VkRect2D& rect, const void* bytes,
                           size_t size);

  // ---- pixel rectangles and the accumulation buffer (pixel_commands.cpp) ----
  struct PixelPlan;  // how one pixel rectangle is drawn
  // Starts a record's pixel rectangles: the number of state entries they add.
  size_t begin_pixel_commands(const rec::FrameRecord& record, const std::vector<size_t>& commands);
  // Prepares command `index` if it is a pixel rectangle (its state entry, next_state, is taken
  // and advanced; its quad goes to `arena`, its image to pixels_); false for other commands.
  bool prepare_pixels(Recording& r, size_t index, Arena& arena,
                      std::vector<gpu::RasterState>& states, size_t& next_state);
  void upload_pixels();
  void record_pixels(Recording& r, size_t index);
  // GL_ACCUM, GL_LOAD, GL_RETURN read or write colour: everything before them must have run.
  static bool accumulation_touches_color(const rec::Accum& accum);
  void execute_accum(const rec::FrameRecord& record, const rec::Accum& accum);
  void clear_accum(const rec::FrameRecord& record, const rec::Clear& clear);

  std::shared_ptr<VulkanDevice> device_;
  // Colour buffers in linear host-visible memory where the device supports it, so a frame is
  // presented from the front image in place (FrameEnd::front_pixels).
  bool host_readable_color_ = false;
  RasterPipelines pipelines_;
  TextureCache textures_;
  DescriptorSetRing descriptor_sets_;  // set 0 of every draw (descriptor_set_ring.hpp)
  PFN_vkCmdSetLineStippleEXT set_line_stipple_ = nullptr;
  // The drawable's buffers the current call works on (set by each public call: a renderer may
  // serve several drawables, and a drawable several renderers).
  DrawableBuffers* buffers_ = nullptr;
  GpuBuffer states_;    // RasterState per snapshot (+ one per clear drawn as a quad)
  GpuBuffer vertices_;  // this record's attributes and indices
  // The previous execute's states_, vertices_ and pixels_, which its submissions may still read
  // (path-traced mode's G-buffer pass while the draws after the trace are prepared): executes
  // alternate between the two sets, and wait for a set's last submission before refilling it.
  struct UploadSet {
    GpuBuffer states, vertices, pixels;
    VulkanDevice::Ticket ticket = 0;
  };
  UploadSet spare_uploads_;
  VulkanDevice::Ticket uploads_ticket_ = 0;       // the last submission reading the current set
  std::vector<VulkanDevice::Ticket> unreported_;  // submissions whose device time is not in stats
  GpuBuffer ascending_;        // indices 0, 1, 2, ...: draws whose triangles are in vertex order
  ResidentGeometry resident_;  // large draws drawn again unchanged: uploaded once
  GpuBuffer readback_;
  // Windows' host memory (FrameEnd::present_to), imported once per allocation (an empty buffer
  // when the device cannot import it), most recently used last.
  struct ImportedHostImage {
    uint64_t generation = 0;
    GpuBuffer buffer;
  };
  std::vector<ImportedHostImage> imported_;
  // Imageless framebuffers of RasterPipelines::render_pass, by drawable size.
  struct SizedFramebuffer {
    uint32_t width = 0, height = 0;
    vk::Framebuffer framebuffer;
  };
  std::vector<SizedFramebuffer> framebuffers_;
  VkFramebuffer single_target_framebuffer(uint32_t width, uint32_t height);
  GpuBuffer* present_ = nullptr;  // this execute's window memory, if imported
  GpuBuffer* imported_host_image(const HostImage& image);
  uint64_t frame_ = 0;
  // Blend states (and logic ops) by the records that used them: a state blends in the fragment
  // shader in its first kShaderBlendRecords records, then in the pipeline (shader_blends()).
  struct BlendStateUse {
    uint64_t last_record = 0;
    uint32_t records = 0;
  };
  std::unordered_map<uint64_t, BlendStateUse> blend_state_uses_;
  bool shader_blends(const PipelineKey& key);
  rec::Decomposed decomposed_;  // scratch
  // Scratch of execute(), kept across frames: a large frame's megabytes of vertices are not
  // allocated (and page-faulted in) again every frame.
  std::vector<uint8_t> upload_;
  std::vector<uint32_t> indices_;
  std::vector<uint8_t> edge_masks_;
  // A colour buffer upside down while draws rasterized in Mesa's orientation go to it (the
  // drawable's size; made on first use).
  GpuImage mesa_image_;
  GpuBuffer pixels_;                   // images of this record's pixel rectangles (32-bit words)
  std::vector<uint32_t> pixel_words_;  // scratch: what goes to pixels_
  OcclusionQueries queries_{*device_};
};

}  // namespace glpt::rt
