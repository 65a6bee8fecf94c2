// The path tracer of path-traced mode: acceleration structures of the traced geometry, the
// per-frame tables, accumulation, and the trace pass that lights the G-buffer's pixels into the
// colour buffers (docs/architecture.md, "Path-traced mode"). Used by Renderer, which rasterizes
// the G-buffer between begin_frame and trace.
//
// Not thread-safe: one PathTracer is used by one thread at a time (the GL context's).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rt_core/accel/blas_cache.hpp"
#include "rt_core/accel/tlas.hpp"
#include "rt_core/frame_stats.hpp"
#include "rt_core/passes/composite_pass.hpp"
#include "rt_core/passes/gbuffer.hpp"
#include "rt_core/passes/path_trace_pass.hpp"
#include "rt_core/passes/svgf_denoiser.hpp"
#include "rt_core/passes/temporal_aa_pass.hpp"
#include "rt_core/raster/texture_cache.hpp"
#include "rt_core/render_settings.hpp"
#include "rt_core/scene/frame_signature.hpp"
#include "rt_core/scene/light_setup.hpp"
#include "rt_core/scene/scene_dump_capture.hpp"
#include "rt_core/scene/trace_scene.hpp"
#include "rt_core/vk/vk_device.hpp"

namespace glpt::rt {

// What the trace pass reads and writes.
struct TraceTargets {
  const GBuffer* gbuffer = nullptr;
  // The raster renderer's textures (the G-buffer pass prepared the traced draws'): rays sample
  // units 0 and 1 of the draws they hit.
  TextureCache* textures = nullptr;
  VkImageView front = VK_NULL_HANDLE;  // colour buffers (front twice when single-buffered)
  VkImageView back = VK_NULL_HANDLE;
  // Whose frame this is (the drawable): the denoiser's history belongs to one.
  const void* history_owner = nullptr;
};

class PathTracer {
 public:
  // nullptr + a message in *error when `device` has no ray queries (or creation failed).
  static std::unique_ptr<PathTracer> create(std::shared_ptr<VulkanDevice> device,
                                            const RenderSettings& settings, std::string* error);
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  // Starts a frame: its samples are added to the previous frames' while `signature` equals the
  // previous frame's (and GLPT_ACCUMULATE is on); otherwise accumulation restarts. Returns the
  // sub-pixel offset (pixels) for this frame's G-buffer: 0 for an accumulation's first samples,
  // so a single frame samples GL's pixel centres, then a Halton (2, 3) sequence in [-0.5, 0.5)
  // indexed by the G-buffers accumulated (not the samples), so it covers the pixel at any
  // GLPT_SPP. With GLPT_REFERENCE every frame starts a new accumulation.
  glm::vec2 begin_frame(FrameSignature signature);
  // GLPT_REFERENCE: after the first trace of a frame, whether another G-buffer pass and trace
  // are needed to reach the reference's samples; if so, `jitter` is that pass's offset.
  bool next_reference_pass(glm::vec2* jitter);
  // Builds what `scene` needs (BLASes, TLAS, tables) and runs the trace pass over the G-buffer of
  // the frame begun last, writing the colour buffers. Throws VulkanError.
  // Submits without waiting (the renderer waits at the frame's end, then calls finish_frame);
  // waits for the previous trace first, whose tables and descriptors this one rewrites.
  void trace(const TraceScene& scene, const TraceTargets& targets, FrameStats& stats);
  // After the device completed the frame: adds what only the device knows (rays, dropped
  // samples, device time of the builds and the trace) to `stats`, and releases unused BLASes.
  void finish_frame(FrameStats& stats);
  // After a failure, or a frame that traced nothing: the next frame starts a new accumulation.
  void forget_previous_frame() noexcept;
  // Whether a geometry of these hashes is held (the scene builder then need not decompose it).
  bool holds_geometry(uint64_t shape_hash, uint64_t shading_hash) const {
    return blas_cache_.holds(shape_hash, shading_hash);
  }
  // glpt-replay's frame `frame_index` starts (its shards must give the same pixels as a whole
  // replay): the random sequence of this and the following records is seeded by `frame_index`
  // instead of the tracer's own count of frames, and the frame builds on the history (denoiser,
  // accumulation) of the frames before it only within its window of `history_window` frames
  // (windows start at frame 0, W, 2W...; 0 or 1: every frame starts afresh) and only when the
  // frame before it was the last one started. Starting the same frame again changes nothing.
  void start_independent_frame(uint64_t frame_index, uint32_t history_window) noexcept;

 private:
  PathTracer(const RenderSettings& settings, std::shared_ptr<VulkanDevice> device);

  // Per-frame scene description on the host, rebuilt from the TraceScene each time.
  struct SceneSetup {
    // The frame's texture tables by target (GLPT_TRACE_TARGET_*: GLPT_PT_BINDING_TEXTURES and
    // the 1-D, 3-D and cube tables): view and sampler by slot.
    std::array<std::vector<VkDescriptorImageInfo>, 4> texture_tables;
    std::vector<VkAccelerationStructureInstanceKHR> tlas_instances;
    std::vector<gpu::GpuInstance> instance_table;
    // The emissive triangles of the frame in eye space, with their choice probabilities
    // (empty when nothing emits).
    std::vector<gpu::GpuEmitter> emitters;
    std::vector<gpu::GpuClipPlanes> clip_planes;  // one per instance with user clip planes
    std::vector<EyeBounds> instance_bounds;
    std::vector<uint8_t> sky;  // per instance: 1 for the sky (TLAS mask GLPT_MASK_SKY only)
    EyeBounds scene_bounds;
    uint64_t triangles = 0;
    // Some instance's shading reflects specularly (ShadingEntry::reflects_specularly): else the
    // specular channel is zero and the denoiser leaves it out (GLPT_DN_NO_SPECULAR).
    bool reflects_specularly = false;
    // Per record state: 1 where an instance of it carries its shape's previous positions
    // (GpuInstance.tables.zw; GpuStateHistory.info.z).
    std::vector<uint8_t> deformed_states;
  };
  void build_scene_setup(const TraceScene& scene, TextureCache* textures, SceneSetup& setup) const;
  // Whether this frame's samples are denoised: SVGF on, samples to add, no reference, and the
  // accumulation (if any) not yet at GLPT_DENOISE_UNTIL.
  bool denoises_this_frame() const;
  // Whether this frame is anti-aliased temporally (GLPT_TAA, and the denoiser runs): then its
  // G-buffer is drawn at a sub-pixel jitter even where nothing accumulates.
  bool anti_aliases_this_frame() const;
  // Writes the denoiser's uniforms (flags 0 when `denoise` is false: the composite shows the
  // raw samples) and, when denoising, the per-state histories of `scene`.
  void write_denoise_inputs(const TraceScene& scene, bool denoise, bool history_valid,
                            FrameStats& stats);
  void ensure_channels(uint32_t width, uint32_t height);
  // The samples per pixel of the next pass: GLPT_SPP, or a reference's share.
  uint32_t samples_of_next_pass() const;
  glm::vec2 jitter_of_next_pass() const;
  // The Sobol sample number of the next pass's first sample (FrameUniforms::options.w).
  uint32_t sobol_sample_number() const;
  // lavapipe's TLAS builder, like its BLAS builder, splits the instance *index* range, and GL
  // draw order is not spatial: put instances in Morton order of their bounds' centres. The
  // instance table order (instanceCustomIndex) is unaffected.
  //
  // Orders the TLAS instances along a Morton curve of their centres (a better tree from
  // lavapipe's builder). The same instances as last frame (the same BLASes in the same record
  // order) keep last frame's order, so the TLAS can be updated in place rather than rebuilt.
  void sort_instances_spatially(SceneSetup& setup);
  // Appends an instance's emissive triangles in eye space (their power in p1.w for now) and the
  // side GL culls (`culled`, as TracedSurface::culled_side); returns the index of the first + 1
  // (GpuInstance::tables.x), 0 when it has none or the table is full (GLPT_MAX_EMITTERS: then
  // bounces alone find its light).
  static uint32_t add_emitters(std::span<const EmitterTriangle> triangles,
                               const glm::mat4& modelview, TracedSurface::CulledSide culled,
                               std::vector<gpu::GpuEmitter>& emitters);
  // Turns the powers into choice probabilities and their running sum; returns the emitter count
  // for the trace pass, 0 when nothing emits.
  static uint32_t finish_emitters(std::vector<gpu::GpuEmitter>& emitters);

  RenderSettings settings_;
  // Declared first: every member below holds Vulkan objects of this device.
  std::shared_ptr<VulkanDevice> device_;
  BlasCache blas_cache_;
  Tlas tlas_;
  PathTracePass trace_pass_;
  CompositePass composite_pass_;
  SvgfDenoiser denoiser_;
  TemporalAaPass temporal_aa_;
  GpuBuffer denoise_uniforms_;
  GpuBuffer taa_uniforms_;
  GpuBuffer state_histories_;
  std::vector<gpu::GpuStateHistory> state_history_table_;  // kept to reuse its capacity
  glm::vec2 frame_jitter_{0.0f};  // of the G-buffer pass the next trace reads
  // This frame's radiance (trace -> denoiser, composite): GLPT_CHANNELS layers of a vec4 a pixel.
  GpuBuffer channels_;
  uint32_t channels_width_ = 0, channels_height_ = 0;
  GpuBuffer frame_uniforms_;
  GpuBuffer blue_noise_;  // kBlueNoiseMask, written once
  GpuBuffer counters_;
  GpuBuffer instance_table_;
  GpuBuffer lights_;
  GpuBuffer emitters_;
  GpuBuffer clip_planes_;
  GpuBuffer states_;
  GpuBuffer accumulation_;  // sized with the channels (ensure_channels)
  // The trace pass's tile-list binding in frames the denoiser skips (which it never writes).
  GpuBuffer no_denoise_tiles_;

  FrameSignature previous_signature_;
  bool same_scene_ = false;  // this frame's signature equals the previous frame's
  bool tlas_valid_ = false;
  uint32_t accumulated_samples_ = 0;  // before this frame
  uint32_t accumulated_passes_ = 0;   // G-buffers (jitter positions) those samples came from
  uint32_t frame_samples_ = 0;        // this frame
  uint64_t frame_number_ = 0;
  bool seeded_by_frame_index_ = false;  // start_independent_frame was called
  uint64_t seed_frame_index_ = 0;
  SceneSetup scene_;             // kept to reuse its vectors' capacity
  SceneDumpCapture scene_dump_;  // GLPT_DUMP_SCENE
  // Submissions of this frame not yet reported: their device time goes to the member of
  // FrameStats named here.
  std::vector<std::pair<VulkanDevice::Ticket, double FrameStats::*>> unreported_;
  // sort_instances_spatially's last input (each instance's BLAS, record order) and its order.
  std::vector<uint64_t> sorted_references_;
  std::vector<uint32_t> sorted_order_;
  VulkanDevice::Ticket trace_ticket_ = 0;               // the last trace submission
  bool counters_read_ = true;                           // its counters_ are in counted_ already
  uint64_t counted_rays_ = 0, counted_non_finite_ = 0;  // of this frame's completed traces
  bool denoised_unread_ = false;  // the last trace's denoiser tile count is not counted yet
  uint32_t counted_denoised_tiles_ = 0;
  // Adds the last trace's counters to the counted ones (it has completed).
  void read_counters();
};

}  // namespace glpt::rt
