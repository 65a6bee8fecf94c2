#include "rt_core/passes/path_tracer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <exception>
#include <glm/trigonometric.hpp>
#include <limits>
#include <map>
#include <span>
#include <unordered_map>

#include "common/stopwatch.hpp"
#include "gbuffer_layout.h"
#include "rt_core/accel/morton_sort.hpp"
#include "rt_core/passes/blue_noise_mask.hpp"
#include "rt_core/raster/sampler_setup.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "shared_types.h"

namespace glpt::rt {
namespace {

// GLPT_REFERENCE renders its samples in at most this many G-buffer passes (jitter positions):
// enough for anti-aliased edges, few enough that the G-buffer rasterization stays a small part.
constexpr uint32_t kMaxReferencePasses = 64;

// The TLAS facing of a draw: Vulkan calls a triangle's face front when a ray meets it from the
// side its right-handed normal (p1 - p0) x (p2 - p0) points to (its vertices counter-clockwise
// as seen from that side; Vulkan spec, "Ray Face Culling"), and the trace pass's queries cull by
// facing (shaders/trace/queries.h): so the face GL culls must be Vulkan's back face. A draw GL
// does not cull is solid from both sides.
VkGeometryInstanceFlagsKHR facing_flags(TracedSurface::CulledSide culled) {
  switch (culled) {
    case TracedSurface::CulledSide::kNone:
      return VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
    case TracedSurface::CulledSide::kCounterClockwise:
      return VK_GEOMETRY_INSTANCE_TRIANGLE_FLIP_FACING_BIT_KHR;
    case TracedSurface::CulledSide::kClockwise:
      return 0;
  }
  return VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
}

// VkTransformMatrixKHR is the top 3 rows of a row-major 4x4; glm is column-major.
VkTransformMatrixKHR to_vk_transform(const glm::mat4& m) {
  VkTransformMatrixKHR transform;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) transform.matrix[row][column] = m[column][row];
  }
  return transform;
}

glm::uvec2 split_address(VkDeviceAddress address) {
  return {static_cast<uint32_t>(address), static_cast<uint32_t>(address >> 32)};
}

RenderSettings sanitized(RenderSettings settings) {
  settings.samples_per_pixel = std::max(settings.samples_per_pixel, 1u);
  settings.max_accumulated = std::max(settings.max_accumulated, 1u);
  if (!std::isfinite(settings.light_angular_radius_deg)) settings.light_angular_radius_deg = 0.0f;
  settings.light_angular_radius_deg = std::clamp(settings.light_angular_radius_deg, 0.0f, 45.0f);
  if (!(settings.trace_scale >= 0.25f)) settings.trace_scale = 0.25f;  // NaN too
  settings.trace_scale = std::min(settings.trace_scale, 1.0f);
  return settings;
}

// The radical inverse of `index` in `base`: the Halton sequence, well spread over [0, 1).
float halton(uint32_t index, uint32_t base) {
  float result = 0.0f, fraction = 1.0f;
  for (; index > 0; index /= base) {
    fraction /= static_cast<float>(base);
    result += fraction * static_cast<float>(index % base);
  }
  return result;
}

static_assert(static_cast<uint32_t>(LightChoice::kContribution) == GLPT_LIGHT_CHOICE_CONTRIBUTION);
static_assert(static_cast<uint32_t>(LightChoice::kUniform) == GLPT_LIGHT_CHOICE_UNIFORM);
static_assert(static_cast<uint32_t>(LightChoice::kAll) == GLPT_LIGHT_CHOICE_ALL);

uint32_t options_bits(const RenderSettings& settings) {
  uint32_t bits = 0;
  if (settings.shadows) bits |= GLPT_OPTION_SHADOWS;
  if (settings.ambient_occlusion) bits |= GLPT_OPTION_AO;
  if (settings.gl_parity()) bits |= GLPT_OPTION_GL_PARITY;
  if (settings.unlit == UnlitPolicy::kAo) bits |= GLPT_OPTION_UNLIT_AO;
  if (settings.unlit == UnlitPolicy::kEmit) bits |= GLPT_OPTION_UNLIT_EMIT;
  if (settings.environment == Environment::kClear) bits |= GLPT_OPTION_ENVIRONMENT;
  if (settings.blue_noise) bits |= GLPT_OPTION_BLUE_NOISE;
  return bits;
}

gpu::GpuTraceState pack_state(const TraceState& state) {
  gpu::GpuTraceState packed{};
  packed.global_ambient = state.global_ambient;
  packed.viewer = state.viewer;
  packed.fog_color = state.fog_color;
  packed.fog_params = state.fog_params;
  const uint32_t count = static_cast<uint32_t>(std::min<size_t>(state.lights.size(), 8));
  const uint32_t flags = (state.local_viewer ? GLPT_STATE_LOCAL_VIEWER : 0u) |
                         (state.two_side ? GLPT_STATE_TWO_SIDE : 0u) |
                         (state.separate_specular ? GLPT_STATE_SEPARATE_SPECULAR : 0u) |
                         (state.specular_material ? GLPT_STATE_SPECULAR_MATERIAL : 0u);
  packed.info = glm::uvec4(count, state.fog_mode, state.targets, flags);
  for (uint32_t i = 0; i < count; ++i) packed.lights[i / 4][i % 4] = state.lights[i];
  return packed;
}

// Writes `values` into `buffer` (at least one element, so a buffer always exists to bind).
// Returns the bytes written.
template <typename T>
size_t upload(const VulkanDevice& device, GpuBuffer& buffer, const std::vector<T>& values) {
  ensure_capacity(device, buffer, std::max<size_t>(values.size(), 1) * sizeof(T),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  buffer.write(values.data(), values.size() * sizeof(T));
  return values.size() * sizeof(T);
}

}  // namespace

PathTracer::PathTracer(const RenderSettings& settings, std::shared_ptr<VulkanDevice> device)
    : settings_(sanitized(settings)),
      device_(std::move(device)),
      blas_cache_(*device_),
      tlas_(*device_),
      trace_pass_(*device_),
      composite_pass_(*device_),
      denoiser_(*device_),
      temporal_aa_(*device_) {
  blas_cache_.allow_refit(settings_.blas_refit);
  denoise_uniforms_ =
      GpuBuffer::create(*device_, sizeof(gpu::DenoiseUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  taa_uniforms_ = GpuBuffer::create(*device_, sizeof(gpu::TemporalAaUniforms),
                                    VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  frame_uniforms_ =
      GpuBuffer::create(*device_, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  counters_ =
      GpuBuffer::create(*device_, sizeof(gpu::GpuCounters), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  no_denoise_tiles_ = GpuBuffer::create(*device_, (GLPT_DN_TILES_HEADER + 2) * sizeof(uint32_t),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  static_assert(kBlueNoiseMask.size() == GLPT_BLUE_NOISE_SIZE * GLPT_BLUE_NOISE_SIZE);
  blue_noise_ =
      GpuBuffer::create(*device_, sizeof(kBlueNoiseMask), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  blue_noise_.write(kBlueNoiseMask.data(), sizeof(kBlueNoiseMask));
}

std::unique_ptr<PathTracer> PathTracer::create(std::shared_ptr<VulkanDevice> device,
                                               const RenderSettings& settings, std::string* error) {
  if (!device) {
    if (error != nullptr) *error = "glpt: no Vulkan device for the path tracer";
    return nullptr;
  }
  if (!device->has_ray_query()) {
    if (error != nullptr)
      *error = "glpt: no Vulkan device with VK_KHR_ray_query and VK_KHR_acceleration_structure (" +
               device->name() + " lacks " + device->ray_query_missing() + "). " +
               vulkan_install_hint();
    return nullptr;
  }
  try {
    return std::unique_ptr<PathTracer>(new PathTracer(settings, std::move(device)));
  } catch (const std::exception& e) {
    if (error != nullptr) *error = e.what();
  } catch (...) {
    if (error != nullptr) *error = "glpt: unknown error while creating the path tracer";
  }
  return nullptr;
}

void PathTracer::forget_previous_frame() noexcept {
  previous_signature_ = FrameSignature();
  accumulated_samples_ = 0;
  accumulated_passes_ = 0;
  frame_samples_ = 0;
  tlas_valid_ = false;
  denoiser_.forget_history();
  temporal_aa_.forget_history();
}

void PathTracer::start_independent_frame(uint64_t frame_index, uint32_t history_window) noexcept {
  if (seeded_by_frame_index_ && frame_index == seed_frame_index_) return;  // the same frame
  const bool continues = seeded_by_frame_index_ && history_window > 1 &&
                         frame_index == seed_frame_index_ + 1 && frame_index % history_window != 0;
  if (!continues) forget_previous_frame();
  seeded_by_frame_index_ = true;
  seed_frame_index_ = frame_index;
}

uint32_t PathTracer::samples_of_next_pass() const {
  uint32_t target = settings_.max_accumulated, per_pass = settings_.samples_per_pixel;
  if (settings_.reference_samples > 0) {
    target = settings_.reference_samples;
    per_pass = std::max(per_pass, (target + kMaxReferencePasses - 1) / kMaxReferencePasses);
  }
  return std::min(per_pass, target - std::min(accumulated_samples_, target));
}

uint32_t PathTracer::sobol_sample_number() const {
  // Each frame index owns a run of sample numbers as long as its samples, so a pixel's samples
  // are consecutive points of its sequence from frame to frame (accumulation and the denoiser's
  // history average consecutive points), and a replayed frame gets the same numbers whichever
  // frames were rendered before it. A reference traces its samples in several passes of one
  // frame: those count on within the run. (32 bits wrap after 4 billion samples: harmless.)
  const uint64_t frame = seeded_by_frame_index_ ? seed_frame_index_ : frame_number_;
  const bool reference = settings_.reference_samples > 0;
  const uint64_t run = reference ? settings_.reference_samples : settings_.samples_per_pixel;
  return static_cast<uint32_t>(frame * run + (reference ? accumulated_samples_ : 0u));
}

glm::vec2 PathTracer::jitter_of_next_pass() const {
  if (frame_samples_ == 0) return glm::vec2(0.0f);
  if (accumulated_samples_ == 0) {
    // A frame without an anti-aliasing history before it (the first, one after a cut) shows
    // pixel centres, as raster mode and GL do; the frames after it are jittered.
    if (!anti_aliases_this_frame() || !temporal_aa_.has_history()) return glm::vec2(0.0f);
    // The anti-aliasing history averages consecutive frames: 16 Halton points (from the
    // second: the first is a pixel corner) by the frame index, so a replayed frame is jittered
    // alike whichever frames were rendered before it.
    const uint64_t frame = seeded_by_frame_index_ ? seed_frame_index_ : frame_number_;
    const uint32_t index = static_cast<uint32_t>(frame % 16) + 1;
    return glm::vec2(halton(index, 2), halton(index, 3)) - 0.5f;
  }
  return glm::vec2(halton(accumulated_passes_, 2), halton(accumulated_passes_, 3)) - 0.5f;
}

glm::vec2 PathTracer::begin_frame(FrameSignature signature) {
  ++frame_number_;
  same_scene_ = signature == previous_signature_;
  if (!(settings_.accumulate && same_scene_) || settings_.reference_samples > 0) {
    accumulated_samples_ = 0;
    accumulated_passes_ = 0;
  }
  previous_signature_ = std::move(signature);
  frame_samples_ = samples_of_next_pass();
  frame_jitter_ = jitter_of_next_pass();
  return frame_jitter_;
}

bool PathTracer::next_reference_pass(glm::vec2* jitter) {
  if (settings_.reference_samples == 0) return false;
  frame_samples_ = samples_of_next_pass();
  if (frame_samples_ == 0) return false;
  same_scene_ = true;  // the same record again: the TLAS stays
  *jitter = frame_jitter_ = jitter_of_next_pass();
  return true;
}

bool PathTracer::denoises_this_frame() const {
  const DenoiseSettings& d = settings_.denoise;
  // GL's lighting equation (GL parity) draws no random samples: there is no noise to filter.
  return d.denoiser == Denoiser::kSvgf && !settings_.gl_parity() &&
         settings_.reference_samples == 0 && frame_samples_ > 0 &&
         accumulated_samples_ < d.until_samples;
}

bool PathTracer::anti_aliases_this_frame() const {
  return settings_.denoise.taa && denoises_this_frame();
}

void PathTracer::write_denoise_inputs(const TraceScene& scene, bool denoise, bool history_valid,
                                      FrameStats& stats) {
  const DenoiseSettings& d = settings_.denoise;
  gpu::DenoiseUniforms uniforms{};
  if (denoise) {
    uint32_t flags = GLPT_DN_ACTIVE;
    if (history_valid) flags |= GLPT_DN_HISTORY_VALID;
    if (settings_.unlit == UnlitPolicy::kAo) flags |= GLPT_DN_UNLIT_AO;
    // No surface with a specular lobe: the specular channel holds nothing, and leaving it out
    // saves the denoiser a third of its work.
    if (!scene_.reflects_specularly) flags |= GLPT_DN_NO_SPECULAR;
    if (!denoiser_.history_has_specular()) flags |= GLPT_DN_PREVIOUS_NO_SPECULAR;
    if (d.mean_variance) flags |= GLPT_DN_MEAN_VARIANCE;
    if (anti_aliases_this_frame()) flags |= GLPT_DN_MOTION;
    uniforms.image = glm::uvec4(scene.width, scene.height, flags, d.iterations);
    uniforms.temporal = glm::vec4(d.alpha, d.moments_alpha, d.fast_alpha, d.fast_clamp);
    uniforms.sigmas =
        glm::vec4(d.sigma_depth, d.sigma_normal, d.sigma_luminance, static_cast<float>(d.kernel));
    // A history that was clamped counts as this many frames long: 2 brings a switched-on
    // light's error back to the (anti-aliased) steady level in 4 frames (3 took 5), for a
    // little more noise where noise clamps (docs/denoiser.md, "No stale light").
    constexpr float kClampedHistoryLength = 2.0f;
    // The accumulated average takes over linearly as it approaches GLPT_DENOISE_UNTIL samples.
    const float accumulated_weight =
        d.until_samples > 0
            ? static_cast<float>(accumulated_samples_) / static_cast<float>(d.until_samples)
            : 1.0f;
    uniforms.params = glm::vec4(scene.pixel_spread, scene.pixel_size_parallel,
                                kClampedHistoryLength, accumulated_weight);
    uniforms.jitter = glm::vec4(frame_jitter_, 0.0f, 0.0f);
    uniforms.slots = glm::uvec4(denoiser_.history_slot(), denoiser_.previous_history_slot(),
                                denoiser_.stamp(), denoiser_.previous_stamp());
    denoiser_.write_addresses(uniforms);
    uniforms.channels = glm::uvec4(channels_.address_words(), 0u, 0u);
    std::vector<gpu::GpuStateHistory>& histories = state_history_table_;
    histories.assign(std::max<size_t>(scene.states.size(), 1), gpu::GpuStateHistory{});
    for (size_t i = 0; i < scene.states.size(); ++i) {
      const TraceState& state = scene.states[i];
      gpu::GpuStateHistory& h = histories[i];
      h.to_previous_eye = state.to_previous_eye;
      h.previous_projection = state.previous_projection;
      h.viewport =
          glm::vec4(state.viewport[0], state.viewport[1], state.viewport[2], state.viewport[3]);
      const bool deformed = i < scene_.deformed_states.size() && scene_.deformed_states[i] != 0;
      h.info = glm::uvec4(state.history_id, state.has_previous ? 1u : 0u, deformed ? 1u : 0u, 0u);
    }
    stats.upload_bytes += upload(*device_, state_histories_, histories);
  }
  denoise_uniforms_.write(&uniforms, sizeof uniforms);
}

void PathTracer::ensure_channels(uint32_t width, uint32_t height) {
  if (width == channels_width_ && height == channels_height_ && channels_) return;
  channels_ = GpuBuffer();
  accumulation_ = GpuBuffer();
  channels_width_ = channels_height_ = 0;
  const VkDeviceSize pixels = VkDeviceSize{width} * height;
  channels_ =
      GpuBuffer::create(*device_, pixels * GLPT_CHANNELS * sizeof(glm::vec4),
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  // Sums and counts (composite.comp, three vec4 layers): what the composite finds there before
  // the first frame of an accumulation is never read.
  accumulation_ = GpuBuffer::create(*device_, pixels * 3 * sizeof(glm::vec4),
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  // No samples (alpha 0) until the first trace: a composite before it shows the colour buffer.
  device_->submit_and_wait(
      [&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, channels_.handle(), 0, VK_WHOLE_SIZE, 0u); });
  channels_width_ = width;
  channels_height_ = height;
}

void PathTracer::build_scene_setup(const TraceScene& scene, TextureCache* textures,
                                   SceneSetup& setup) const {
  for (auto& table : setup.texture_tables) table.clear();
  setup.tlas_instances.clear();
  setup.instance_table.clear();
  setup.emitters.clear();
  setup.clip_planes.clear();
  setup.instance_bounds.clear();
  setup.sky.clear();
  setup.scene_bounds = EyeBounds();
  setup.reflects_specularly = false;
  setup.triangles = 0;
  // (content version, sampler) -> slot + 1: the version names the images only, and one frame
  // may sample them with different parameters or unit LOD biases.
  std::map<std::pair<uint64_t, VkSampler>, uint32_t> texture_slots;
  // `unit` packed as GpuInstance.units holds it (shared_types.h); 0: the unit is off for rays
  // (no texture, not prepared, or its target's table is full).
  auto packed_unit = [&](const TracedUnit& unit) -> uint32_t {
    if (!unit.texture || textures == nullptr) return 0;
    const rec::TextureObjectSnapshot& texture = *unit.texture;
    const uint32_t target = texture.target == GL_TEXTURE_1D         ? GLPT_TRACE_TARGET_1D
                            : texture.target == GL_TEXTURE_3D       ? GLPT_TRACE_TARGET_3D
                            : texture.target == GL_TEXTURE_CUBE_MAP ? GLPT_TRACE_TARGET_CUBE
                                                                    : GLPT_TRACE_TARGET_2D;
    std::vector<VkDescriptorImageInfo>& table = setup.texture_tables[target];
    const size_t capacity =
        target == GLPT_TRACE_TARGET_2D ? GLPT_TRACE_TEXTURES : GLPT_TRACE_TEXTURES_OTHER;
    const VkSampler sampler = textures->sampler(texture, unit.lod_bias);
    const std::pair<uint64_t, VkSampler> key(texture.content_version, sampler);
    uint32_t slot = 0;
    if (auto found = texture_slots.find(key); found != texture_slots.end()) {
      slot = found->second;
    } else {
      const VkImageView view = textures->view(texture);
      if (view == VK_NULL_HANDLE || table.size() >= capacity) return 0;
      table.push_back({sampler, view, VK_IMAGE_LAYOUT_GENERAL});
      slot = static_cast<uint32_t>(table.size());
      texture_slots.emplace(key, slot);
    }
    const uint32_t clamp = make_sampler_setup(texture, unit.lod_bias).shader.clamp_coords & 7u;
    return slot | (target << 8) | (clamp << 10) | ((unit.env_mode & 0xFFFFu) << 16);
  };
  setup.deformed_states.assign(scene.states.size(), 0);
  for (const Instance& instance : scene.instances) {
    if (!instance.geometry) continue;
    const Geometry& geometry = *instance.geometry;
    const BlasEntry* entry = blas_cache_.find(geometry.shape_hash);
    const ShadingEntry* shading =
        blas_cache_.find_shading(geometry.shape_hash, geometry.shading_hash);
    if (entry == nullptr || shading == nullptr) continue;  // cannot happen after prepare
    setup.reflects_specularly = setup.reflects_specularly || shading->reflects_specularly;

    VkAccelerationStructureInstanceKHR tlas_instance{};
    tlas_instance.transform = to_vk_transform(instance.modelview);
    tlas_instance.instanceCustomIndex = static_cast<uint32_t>(setup.instance_table.size());
    tlas_instance.mask = GLPT_MASK_VISIBLE;  // shadow bits added by setup_lights
    tlas_instance.instanceShaderBindingTableRecordOffset = 0;
    // Alpha-tested and clipped draws are not opaque: the queries' candidate loops test each
    // hit's alpha and clip planes.
    tlas_instance.flags =
        facing_flags(instance.surface.culled_side) |
        (instance.surface.tests_candidates() ? VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR
                                             : VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR);
    tlas_instance.accelerationStructureReference = entry->blas_address;
    setup.tlas_instances.push_back(tlas_instance);

    const EyeBounds bounds =
        EyeBounds::transformed(entry->bounds_min, entry->bounds_max, instance.modelview);
    const glm::uvec2 positions = split_address(entry->positions_address);
    // How the shape deformed since last frame (a BLAS refit this frame from last frame's shape).
    glm::uvec2 previous_positions(0u);
    if (settings_.denoise.vertex_motion && entry->previous_positions_frame == frame_number_ &&
        entry->previous_positions_address != 0) {
      previous_positions = split_address(entry->previous_positions_address);
      for (uint32_t state : instance.draw_states)
        if (state < setup.deformed_states.size()) setup.deformed_states[state] = 1;
    }
    const glm::uvec2 vertices = split_address(shading->vertices_address);
    const glm::uvec2 materials = split_address(shading->materials_address);
    float size = bounds.diagonal();
    if (!std::isfinite(size)) size = std::numeric_limits<float>::max();
    uint32_t clip_index = 0;  // + 1
    if (instance.surface.clip_plane_count > 0) {
      gpu::GpuClipPlanes& planes = setup.clip_planes.emplace_back();
      for (size_t i = 0; i < TracedSurface::kMaxClipPlanes; ++i)
        planes.planes[i] = instance.surface.clip_planes[i];
      planes.count = glm::uvec4(instance.surface.clip_plane_count, 0u, 0u, 0u);
      clip_index = static_cast<uint32_t>(setup.clip_planes.size());
    }
    setup.instance_table.push_back(
        {glm::uvec4(positions, vertices),
         glm::uvec4(materials, instance.state, std::bit_cast<uint32_t>(size)),
         glm::uvec4(packed_unit(instance.surface.units[0]), packed_unit(instance.surface.units[1]),
                    packed_unit(instance.surface.units[2]), packed_unit(instance.surface.units[3])),
         glm::uvec4(instance.surface.alpha_func,
                    std::bit_cast<uint32_t>(instance.surface.alpha_ref), 0u, 0u),
         glm::uvec4(add_emitters(shading->emitters, instance.modelview,
                                 instance.surface.culled_side, setup.emitters),
                    clip_index, previous_positions)});

    setup.instance_bounds.push_back(bounds);
    setup.sky.push_back(instance.sky ? 1 : 0);
    // The sky box is no part of the world's extent (which sizes lights and AO).
    if (!instance.sky) setup.scene_bounds.extend(bounds);
    setup.triangles += entry->triangle_count;
  }
}

uint32_t PathTracer::add_emitters(std::span<const EmitterTriangle> triangles,
                                  const glm::mat4& modelview, TracedSurface::CulledSide culled,
                                  std::vector<gpu::GpuEmitter>& emitters) {
  if (triangles.empty() || emitters.size() + triangles.size() > GLPT_MAX_EMITTERS) return 0;
  const uint32_t first = static_cast<uint32_t>(emitters.size());
  // The culled side relative to the eye-space normal (p1 - p0) x (p2 - p0) of the transformed
  // corners, which a mirroring modelview turns against the object-space one.
  const float mirror = glm::determinant(glm::dmat3(glm::mat3(modelview))) < 0.0 ? -1.0f : 1.0f;
  const float culled_side = culled == TracedSurface::CulledSide::kCounterClockwise ? mirror
                            : culled == TracedSurface::CulledSide::kClockwise      ? -mirror
                                                                                   : 0.0f;
  for (const EmitterTriangle& triangle : triangles) {
    gpu::GpuEmitter& out = emitters.emplace_back();
    glm::vec3 p[3];
    for (int corner = 0; corner < 3; ++corner)
      p[corner] = glm::vec3(modelview * glm::vec4(triangle.positions[corner], 1.0f));
    const float area = 0.5f * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    const glm::vec3 mean =
        (triangle.emission[0] + triangle.emission[1] + triangle.emission[2]) / 3.0f;
    float power = area * glm::dot(mean, glm::vec3(0.2126f, 0.7152f, 0.0722f));  // luminance
    // Degenerate or non-finite triangles are never chosen (power 0) and have no density.
    if (!std::isfinite(power) || !(area > 0.0f)) power = 0.0f;
    out.p0 = glm::vec4(p[0], 0.0f);
    out.p1 = glm::vec4(p[1], power);  // normalised into a probability by finish_emitters
    out.p2 = glm::vec4(p[2], power > 0.0f ? area : 0.0f);
    out.emission0 = glm::vec4(triangle.emission[0], culled_side);
    out.emission1 = glm::vec4(triangle.emission[1], 0.0f);
    out.emission2 = glm::vec4(triangle.emission[2], 0.0f);
  }
  return first + 1;
}

uint32_t PathTracer::finish_emitters(std::vector<gpu::GpuEmitter>& emitters) {
  double total = 0.0;
  for (const gpu::GpuEmitter& emitter : emitters) total += emitter.p1.w;
  if (!(total > 0.0) || !std::isfinite(total)) return 0;
  double cumulative = 0.0;
  for (gpu::GpuEmitter& emitter : emitters) {
    cumulative += emitter.p1.w;
    emitter.p1.w = static_cast<float>(emitter.p1.w / total);
    emitter.p0.w = static_cast<float>(cumulative / total);
  }
  // Rounding must not leave a gap above the last emitter that can be chosen.
  for (auto it = emitters.rbegin(); it != emitters.rend() && it->p0.w >= 1.0f - 1.0e-6f; ++it)
    it->p0.w = 1.0f;
  return static_cast<uint32_t>(emitters.size());
}

void PathTracer::sort_instances_spatially(SceneSetup& setup) {
  if (setup.tlas_instances.size() < 3) return;
  bool same = sorted_references_.size() == setup.tlas_instances.size() &&
              sorted_order_.size() == setup.tlas_instances.size();
  for (size_t i = 0; same && i < setup.tlas_instances.size(); ++i)
    same = sorted_references_[i] == setup.tlas_instances[i].accelerationStructureReference;
  if (!same) {
    std::vector<glm::vec3> centres;
    centres.reserve(setup.instance_bounds.size());
    for (const EyeBounds& bounds : setup.instance_bounds)
      centres.push_back(bounds.empty() ? glm::vec3(0.0f) : (bounds.min + bounds.max) * 0.5f);
    sorted_order_ = morton_order_points(centres).permutation;
    sorted_references_.clear();
    for (const VkAccelerationStructureInstanceKHR& instance : setup.tlas_instances)
      sorted_references_.push_back(instance.accelerationStructureReference);
  }
  std::vector<VkAccelerationStructureInstanceKHR> sorted;
  sorted.reserve(setup.tlas_instances.size());
  for (uint32_t index : sorted_order_) sorted.push_back(setup.tlas_instances[index]);
  setup.tlas_instances = std::move(sorted);
}

void PathTracer::trace(const TraceScene& scene, const TraceTargets& targets, FrameStats& stats) {
  stats = FrameStats();
  if (scene.width == 0 || scene.height == 0 || targets.gbuffer == nullptr) return;
  // The previous trace (a GLPT_REFERENCE pass of this frame, or the last frame's, long done)
  // reads the tables, counters and descriptor sets rewritten below.
  device_->wait(trace_ticket_);
  read_counters();

  // ---- acceleration structures and shading data of new geometry
  std::vector<const Geometry*> geometries;
  geometries.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) geometries.push_back(instance.geometry.get());
  // Paths traced this frame: how much a refit tree's extra cost weighs against a build.
  const double trace_scale = settings_.reference_samples > 0 ? 1.0 : settings_.trace_scale;
  const double traced_pixels =
      static_cast<double>(scene.width) * scene.height * trace_scale * trace_scale *
      std::max<uint32_t>(1u, settings_.reference_samples > 0 ? settings_.reference_samples
                                                             : settings_.samples_per_pixel);
  const BlasPrepareStats blas = blas_cache_.prepare(geometries, frame_number_, traced_pixels);
  stats.blas_builds = blas.builds;
  stats.blas_refits = blas.refits;
  stats.blas_reused = blas.reused;
  stats.upload_bytes += blas.upload_bytes;
  if (blas.build_ticket != 0) unreported_.push_back({blas.build_ticket, &FrameStats::blas_ms});

  // ---- per-frame tables
  const Stopwatch upload_timer;
  build_scene_setup(scene, targets.textures, scene_);
  stats.triangles = scene_.triangles;
  const LightSize light_size{settings_.light_radius,
                             glm::radians(settings_.light_angular_radius_deg)};
  const LightSetup light_setup =
      setup_lights(scene.lights, scene_.instance_bounds, scene_.scene_bounds, light_size);
  bool any_sky = false;
  for (size_t i = 0; i < scene_.tlas_instances.size(); ++i) {
    // Sky instances are seen by the sky lookup of rays that miss the world only.
    scene_.tlas_instances[i].mask =
        scene_.sky[i] ? GLPT_MASK_SKY : light_setup.instance_masks[i] & 0xFFu;
    any_sky = any_sky || scene_.sky[i];
  }
  sort_instances_spatially(scene_);
  stats.upload_bytes += upload(*device_, instance_table_, scene_.instance_table);
  stats.upload_bytes += upload(*device_, lights_, light_setup.lights);
  const uint32_t emitter_count = finish_emitters(scene_.emitters);
  stats.upload_bytes += upload(*device_, emitters_, scene_.emitters);
  stats.upload_bytes += upload(*device_, clip_planes_, scene_.clip_planes);
  stats.emitters = emitter_count;
  std::vector<gpu::GpuTraceState> states;
  states.reserve(scene.states.size());
  for (const TraceState& state : scene.states) states.push_back(pack_state(state));
  stats.upload_bytes += upload(*device_, states_, states);

  ensure_channels(scene.width, scene.height);
  const bool denoise = denoises_this_frame() && denoiser_.fits(scene.width, scene.height);
  // The pass blends the colour buffer the frame draws into (GL_BACK, or the front where the
  // program draws there); none under glDrawBuffer(GL_NONE).
  const bool anti_alias = denoise && anti_aliases_this_frame() && (scene.default_targets & 3u) != 0;
  bool history_valid = false;
  if (denoise) history_valid = denoiser_.prepare(scene.width, scene.height, targets.history_owner);
  write_denoise_inputs(scene, denoise, history_valid, stats);

  gpu::FrameUniforms uniforms{};
  // The seed changes every frame so accumulated frames (and restarted ones) see new samples.
  uniforms.image =
      glm::uvec4(scene.width, scene.height, scene.default_targets,
                 static_cast<uint32_t>(
                     (seeded_by_frame_index_ ? seed_frame_index_ : frame_number_) * 0x9E3779B9u));
  uniforms.sampling = glm::uvec4(accumulated_samples_, frame_samples_, settings_.bounces,
                                 accumulated_samples_ + frame_samples_);
  const float angle = glm::radians(settings_.light_angular_radius_deg);
  const float half_sin = std::sin(0.5f * angle);
  uniforms.params = glm::vec4(settings_.ao_radius, std::cos(angle), 2.0f * half_sin * half_sin,
                              scene.pixel_spread);
  uniforms.options = glm::uvec4(options_bits(settings_) | (any_sky ? GLPT_OPTION_SKY : 0u) |
                                    (denoise ? GLPT_OPTION_DENOISE_TILES : 0u),
                                static_cast<uint32_t>(settings_.light_choice), emitter_count,
                                sobol_sample_number());
  uniforms.environment = scene.clear_color;
  uniforms.buffers = glm::uvec4(accumulation_.address_words(), channels_.address_words());
  // GLPT_SCALE: the coarse grid the trace pass traces (none for the reference, whose every
  // pixel is traced); which pixel of each cell moves from frame to frame along a Halton sequence.
  const float scale = settings_.reference_samples > 0 ? 1.0f : settings_.trace_scale;
  const uint64_t grid_index = (seeded_by_frame_index_ ? seed_frame_index_ : frame_number_) + 1;
  uniforms.trace_grid = glm::vec4(scale, scale, halton(static_cast<uint32_t>(grid_index), 2),
                                  halton(static_cast<uint32_t>(grid_index), 3));
  // One cell more than the shader counts (ceil of the same float product) keeps rounding on the
  // safe side: the shader skips cells beyond its own count.
  const uint32_t grid_width =
      scale >= 1.0f ? scene.width
                    : static_cast<uint32_t>(std::ceil(static_cast<float>(scene.width) * scale)) + 1;
  const uint32_t grid_height =
      scale >= 1.0f
          ? scene.height
          : static_cast<uint32_t>(std::ceil(static_cast<float>(scene.height) * scale)) + 1;
  frame_uniforms_.write(&uniforms, sizeof uniforms);
  if (frame_samples_ > 0 && scene_dump_.wanted())
    scene_dump_.capture(scene, scene_.tlas_instances, blas_cache_, light_setup.lights, uniforms,
                        frame_number_);
  const gpu::GpuCounters zero_counters{};
  counters_.write(&zero_counters, sizeof zero_counters);
  stats.upload_ms = blas.upload_ms + upload_timer.elapsed_ms();

  // ---- TLAS: the instance list follows from the signature, so an unchanged frame reuses it
  if (!same_scene_ || !tlas_valid_ || !tlas_.handle()) {
    tlas_valid_ = false;
    bool updated = false;
    stats.upload_bytes += scene_.tlas_instances.size() * sizeof(VkAccelerationStructureInstanceKHR);
    unreported_.push_back({tlas_.build(scene_.tlas_instances, &updated), &FrameStats::tlas_ms});
    ++(updated ? stats.tlas_updates : stats.tlas_builds);
    tlas_valid_ = true;
  }

  // ---- trace, then composite, in one submission (also when no sample is left to add: the
  // composite pass writes the accumulated image); with the denoiser between them, three
  // submissions, each timed on its own
  PathTraceResources trace;
  trace.scene = tlas_.handle();
  trace.instances = &instance_table_;
  trace.lights = &lights_;
  trace.emitters = &emitters_;
  trace.clip_planes = &clip_planes_;
  trace.states = &states_;
  trace.counters = &counters_;
  trace.frame = &frame_uniforms_;
  trace.denoise_tiles = denoise ? &denoiser_.tiles() : &no_denoise_tiles_;
  trace.blue_noise = &blue_noise_;
  // Unused slots of the texture tables sample a white dummy of their target (the shader never
  // indexes them; dummy_view takes TextureCache's kinds: 1-D, 2-D, 3-D, cube).
  auto fill = [&](std::span<VkDescriptorImageInfo> out, uint32_t target, uint32_t dummy_kind) {
    const std::vector<VkDescriptorImageInfo>& table = scene_.texture_tables[target];
    for (size_t t = 0; t < out.size(); ++t)
      out[t] = t < table.size() ? table[t]
                                : VkDescriptorImageInfo{targets.textures->dummy_sampler(),
                                                        targets.textures->dummy_view(dummy_kind),
                                                        VK_IMAGE_LAYOUT_GENERAL};
  };
  fill(trace.textures, GLPT_TRACE_TARGET_2D, 1);
  fill(trace.textures_1d, GLPT_TRACE_TARGET_1D, 0);
  fill(trace.textures_3d, GLPT_TRACE_TARGET_3D, 2);
  fill(trace.textures_cube, GLPT_TRACE_TARGET_CUBE, 3);
  CompositeResources composite;
  composite.frame = &frame_uniforms_;
  composite.states = &states_;
  for (int a = 0; a < GLPT_GBUFFER_ATTACHMENTS; ++a)
    trace.gbuffer[a] = composite.gbuffer[a] = targets.gbuffer->image(a).view();
  composite.front = targets.front;
  composite.back = targets.back;
  composite.denoise_uniforms = &denoise_uniforms_;
  // Each pass reads what the one before wrote (also across submissions: a barrier's first scope
  // covers earlier submissions to the queue).
  auto barrier = [](VkCommandBuffer cmd) {
    VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr, VK_ACCESS_SHADER_WRITE_BIT,
                           VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &memory, 0, nullptr, 0,
                         nullptr);
  };
  if (!denoise) {
    trace_ticket_ = device_->submit([&](VkCommandBuffer cmd) {
      trace_pass_.record(cmd, trace, scene.width, scene.height, grid_width, grid_height);
      barrier(cmd);
      composite_pass_.record(cmd, composite, scene.width, scene.height);
    });
    unreported_.push_back({trace_ticket_, &FrameStats::trace_ms});
  } else {
    DenoiseResources resources;
    resources.uniforms = &denoise_uniforms_;
    resources.states = &state_histories_;
    resources.scene = trace.scene;
    resources.instances = trace.instances;
    resources.position = targets.gbuffer->image(GLPT_GBUFFER_POSITION).view();
    resources.surface = targets.gbuffer->image(GLPT_GBUFFER_SURFACE).view();
    unreported_.push_back({device_->submit([&](VkCommandBuffer cmd) {
                             denoiser_.record_before_trace(cmd);
                             trace_pass_.record(cmd, trace, scene.width, scene.height, grid_width,
                                                grid_height);
                           }),
                           &FrameStats::trace_ms});
    unreported_.push_back({device_->submit([&](VkCommandBuffer cmd) {
                             barrier(cmd);
                             denoiser_.record(cmd, resources, settings_.denoise.iterations,
                                              scene_.reflects_specularly);
                           }),
                           &FrameStats::denoise_ms});
    trace_ticket_ = device_->submit([&](VkCommandBuffer cmd) {
      barrier(cmd);
      composite_pass_.record(cmd, composite, scene.width, scene.height);
    });
    unreported_.push_back({trace_ticket_, &FrameStats::composite_ms});
    stats.denoised = 1;
    if (anti_alias) {
      gpu::TemporalAaUniforms taa{};
      const bool taa_history =
          temporal_aa_.prepare(scene.width, scene.height, targets.history_owner) && history_valid;
      // While a still image accumulates, the composite shows the average of its frames, which
      // is anti-aliased already: the history takes it unchanged.
      const bool take_current = accumulated_samples_ > 0;
      taa.image = glm::uvec4(
          scene.width, scene.height,
          (taa_history ? GLPT_TAA_HISTORY_VALID : 0u) | (take_current ? GLPT_TAA_TAKE_CURRENT : 0u),
          denoiser_.recorded_stamp());
      taa.params = glm::vec4(settings_.denoise.taa_alpha, settings_.denoise.taa_gamma, 0.0f, 0.0f);
      taa.buffers = glm::uvec4(denoiser_.motion_address(), 0u, 0u);
      temporal_aa_.write_addresses(taa);
      taa_uniforms_.write(&taa, sizeof taa);
      TemporalAaResources resources;
      resources.uniforms = &taa_uniforms_;
      resources.colour = (scene.default_targets & 2u) != 0 ? targets.back : targets.front;
      resources.tiles = &denoiser_.tiles();
      resources.surface = targets.gbuffer->image(GLPT_GBUFFER_SURFACE).view();
      trace_ticket_ = device_->submit([&](VkCommandBuffer cmd) {
        barrier(cmd);
        temporal_aa_.record(cmd, resources, scene.width, scene.height, !take_current);
      });
      unreported_.push_back({trace_ticket_, &FrameStats::taa_ms});
    }
  }
  if (!anti_alias) temporal_aa_.forget_history();
  counters_read_ = false;
  denoised_unread_ = denoise;
  accumulated_samples_ += frame_samples_;
  if (frame_samples_ > 0) ++accumulated_passes_;
  frame_samples_ = 0;
  stats.accumulated_samples = accumulated_samples_;
}

void PathTracer::read_counters() {
  if (counters_read_) return;
  const gpu::GpuCounters* counters = counters_.as<gpu::GpuCounters>();
  counted_rays_ += counters->rays.x;
  counted_non_finite_ += counters->rays.y;
  if (denoised_unread_) counted_denoised_tiles_ += denoiser_.listed_tiles();
  denoised_unread_ = false;
  counters_read_ = true;
}

void PathTracer::finish_frame(FrameStats& stats) {
  device_->wait(trace_ticket_);  // done already where the caller waited for the frame
  read_counters();
  stats.rays += counted_rays_;
  stats.non_finite_samples += counted_non_finite_;
  stats.denoised_tiles += counted_denoised_tiles_;
  counted_rays_ = counted_non_finite_ = 0;
  counted_denoised_tiles_ = 0;
  for (const auto& [ticket, member] : unreported_) stats.*member += device_->take_device_ms(ticket);
  unreported_.clear();
  scene_dump_.finish(stats);
  // Nothing pending uses a BLAS any more.
  blas_cache_.evict_unused(frame_number_);
}

}  // namespace glpt::rt
