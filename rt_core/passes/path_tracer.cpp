#include "rt_core/passes/path_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "common/stopwatch.hpp"
#include "rt_core/accel/blas_cache.hpp"
#include "rt_core/accel/morton_sort.hpp"
#include "rt_core/accel/tlas.hpp"
#include "rt_core/passes/path_trace_pass.hpp"
#include "rt_core/passes/tonemap_pass.hpp"
#include "rt_core/scene/frame_signature.hpp"
#include "rt_core/scene/light_setup.hpp"
#include "rt_core/vk/gpu_buffer.hpp"
#include "rt_core/vk/vk_device.hpp"
#include "shared_types.h"

namespace glpt::rt {
namespace {

// Ambient occlusion radius as a fraction of the diagonal of the scene's eye-space bounding box:
// large enough to darken creases and contact regions, small enough that open surfaces near
// other objects keep their GL ambient.
constexpr float kAoRadiusSceneFraction = 0.1f;

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
  return settings;
}

}  // namespace

class PathTracer::Impl {
 public:
  Impl(const RenderSettings& settings, std::shared_ptr<VulkanDevice> device)
      : settings_(sanitized(settings)),
        device_(std::move(device)),
        blas_cache_(*device_),
        tlas_(*device_),
        path_trace_(*device_),
        tonemap_(*device_) {
    frame_uniforms_ =
        GpuBuffer::create(*device_, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    counters_ =
        GpuBuffer::create(*device_, sizeof(gpu::GpuCounters), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  }

  const std::string& device_name() const { return device_->name(); }

  // Throws on Vulkan failures; PathTracer::render turns that into false + message.
  void render(const TraceScene& frame, std::vector<uint8_t>& rgba, FrameStats& stats);

  // After a failure nothing about the previous frame can be trusted.
  void forget_previous_frame() noexcept {
    previous_signature_ = FrameSignature();
    accumulated_samples_ = 0;
  }

 private:
  // Per-frame scene description on the host, rebuilt from the TraceScene each time.
  struct SceneSetup {
    std::vector<VkAccelerationStructureInstanceKHR> tlas_instances;
    std::vector<gpu::GpuInstance> instance_table;
    std::vector<EyeBounds> instance_bounds;
    EyeBounds scene_bounds;
    bool any_lit = false;
    uint64_t triangles = 0;
  };
  void build_scene_setup(const TraceScene& frame, SceneSetup& setup) const;
  // lavapipe's TLAS builder, like its BLAS builder, splits the instance *index* range, and GL
  // draw order is not spatial: put instances in Morton order of their bounds' centres. The
  // instance table order (instanceCustomIndex) is unaffected.
  static void sort_instances_spatially(SceneSetup& setup);

  RenderSettings settings_;
  // Declared first: every member below holds Vulkan objects of this device.
  std::shared_ptr<VulkanDevice> device_;
  BlasCache blas_cache_;
  Tlas tlas_;
  PathTracePass path_trace_;
  TonemapPass tonemap_;
  GpuBuffer frame_uniforms_;
  GpuBuffer counters_;
  GpuBuffer instance_table_;
  GpuBuffer lights_;
  GpuBuffer accumulation_;
  GpuBuffer output_;

  FrameSignature previous_signature_;
  uint32_t accumulated_samples_ = 0;
  uint64_t frame_number_ = 0;
  SceneSetup scene_;  // kept to reuse its vectors' capacity
};

void PathTracer::Impl::build_scene_setup(const TraceScene& frame, SceneSetup& setup) const {
  setup.tlas_instances.clear();
  setup.instance_table.clear();
  setup.instance_bounds.clear();
  setup.scene_bounds = EyeBounds();
  setup.any_lit = false;
  setup.triangles = 0;
  for (const Instance& instance : frame.instances) {
    if (!instance.geometry || instance.geometry->triangle_count() == 0) continue;
    const BlasEntry* entry = blas_cache_.find(instance.geometry->content_hash);
    if (entry == nullptr) continue;  // cannot happen after BlasCache::prepare

    VkAccelerationStructureInstanceKHR tlas_instance{};
    tlas_instance.transform = to_vk_transform(instance.modelview);
    tlas_instance.instanceCustomIndex = static_cast<uint32_t>(setup.instance_table.size());
    tlas_instance.mask = GLPT_MASK_VISIBLE;  // shadow bits added by setup_lights
    tlas_instance.instanceShaderBindingTableRecordOffset = 0;
    tlas_instance.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR |
                          VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR;
    tlas_instance.accelerationStructureReference = entry->blas_address;
    setup.tlas_instances.push_back(tlas_instance);

    const glm::uvec2 vertices = split_address(entry->vertices_address);
    const glm::uvec2 materials = split_address(entry->materials_address);
    setup.instance_table.push_back({glm::uvec4(vertices, materials)});

    const EyeBounds bounds =
        EyeBounds::transformed(entry->bounds_min, entry->bounds_max, instance.modelview);
    setup.instance_bounds.push_back(bounds);
    setup.scene_bounds.extend(bounds);
    setup.any_lit = setup.any_lit || entry->has_lit_material;
    setup.triangles += entry->triangle_count;
  }
}

void PathTracer::Impl::sort_instances_spatially(SceneSetup& setup) {
  if (setup.tlas_instances.size() < 3) return;
  std::vector<glm::vec3> centres;
  centres.reserve(setup.instance_bounds.size());
  for (const EyeBounds& bounds : setup.instance_bounds) {
    centres.push_back(bounds.empty() ? glm::vec3(0.0f) : (bounds.min + bounds.max) * 0.5f);
  }
  const MortonOrder order = morton_order_points(centres);
  std::vector<VkAccelerationStructureInstanceKHR> sorted;
  sorted.reserve(setup.tlas_instances.size());
  for (uint32_t index : order.permutation) sorted.push_back(setup.tlas_instances[index]);
  setup.tlas_instances = std::move(sorted);
}

void PathTracer::Impl::render(const TraceScene& frame, std::vector<uint8_t>& rgba,
                              FrameStats& stats) {
  stats = FrameStats();
  ++frame_number_;
  if (frame.width == 0 || frame.height == 0) {
    rgba.clear();
    forget_previous_frame();
    return;
  }

  // ---- acceleration structures of new geometry
  std::vector<const Geometry*> geometries;
  geometries.reserve(frame.instances.size());
  for (const Instance& instance : frame.instances) geometries.push_back(instance.geometry.get());
  const BlasPrepareStats blas = blas_cache_.prepare(geometries, frame_number_);
  stats.blas_builds = blas.builds;
  stats.blas_reused = blas.reused;
  stats.blas_ms = blas.build_ms;

  // ---- per-frame tables
  const Stopwatch upload_timer;
  build_scene_setup(frame, scene_);
  stats.triangles = scene_.triangles;
  std::vector<Light> lights = frame.lights;
  if (lights.empty() && scene_.any_lit) lights.push_back(default_light());
  const LightSetup light_setup = setup_lights(lights, scene_.instance_bounds, scene_.scene_bounds);
  for (size_t i = 0; i < scene_.tlas_instances.size(); ++i) {
    scene_.tlas_instances[i].mask = light_setup.instance_masks[i] & 0xFFu;
  }
  sort_instances_spatially(scene_);
  const size_t table_bytes = scene_.instance_table.size() * sizeof(gpu::GpuInstance);
  ensure_capacity(*device_, instance_table_, table_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  instance_table_.write(scene_.instance_table.data(), table_bytes);
  const size_t light_bytes = light_setup.lights.size() * sizeof(gpu::GpuLight);
  ensure_capacity(*device_, lights_, light_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  lights_.write(light_setup.lights.data(), light_bytes);

  // ---- accumulation: continue only while everything the image depends on is unchanged
  FrameSignature signature(frame);
  const bool scene_unchanged = signature == previous_signature_;
  if (!(settings_.accumulate && scene_unchanged)) accumulated_samples_ = 0;
  const uint32_t samples = std::min(
      settings_.samples_per_pixel,
      settings_.max_accumulated - std::min(accumulated_samples_, settings_.max_accumulated));
  const size_t pixel_count = size_t{frame.width} * frame.height;
  ensure_capacity(*device_, accumulation_, pixel_count * sizeof(glm::vec4),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  ensure_capacity(*device_, output_, pixel_count * sizeof(uint32_t),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

  gpu::FrameUniforms uniforms{};
  uniforms.inverse_projection = glm::mat4(glm::inverse(glm::dmat4(frame.projection)));
  uniforms.clear_color = frame.clear_color;
  uniforms.global_ambient = frame.global_ambient;
  uniforms.viewport =
      glm::ivec4(frame.viewport.x, frame.viewport.y, static_cast<int32_t>(frame.viewport.width),
                 static_cast<int32_t>(frame.viewport.height));
  // The seed changes every frame so accumulated frames (and restarted ones) see new samples.
  uniforms.image = glm::uvec4(frame.width, frame.height, static_cast<uint32_t>(lights.size()),
                              static_cast<uint32_t>(frame_number_ * 0x9E3779B9u));
  uniforms.sampling =
      glm::uvec4(accumulated_samples_, samples, settings_.bounces, accumulated_samples_ + samples);
  float ao_radius = kAoRadiusSceneFraction * scene_.scene_bounds.diagonal();
  if (!std::isfinite(ao_radius)) ao_radius = 0.0f;  // 0: ambient never occluded
  uniforms.params =
      glm::vec4(ao_radius, std::cos(glm::radians(settings_.light_angular_radius_deg)), 0.0f, 0.0f);
  frame_uniforms_.write(&uniforms, sizeof uniforms);
  const gpu::GpuCounters zero_counters{};
  counters_.write(&zero_counters, sizeof zero_counters);
  stats.upload_ms = blas.upload_ms + upload_timer.elapsed_ms();

  // ---- TLAS: the instance list is part of the signature, so an unchanged frame reuses it
  if (!scene_unchanged || !tlas_.handle()) stats.tlas_ms = tlas_.build(scene_.tlas_instances);

  // ---- trace
  if (samples > 0) {
    const PathTraceResources resources{tlas_.handle(), &instance_table_, &lights_,
                                       &accumulation_, &counters_,       &frame_uniforms_};
    stats.trace_ms = device_->submit_and_wait([&](VkCommandBuffer cmd) {
      path_trace_.record(cmd, resources, frame.width, frame.height);
    });
    stats.rays = counters_.as<gpu::GpuCounters>()->rays.x;
  }
  accumulated_samples_ += samples;
  previous_signature_ = std::move(signature);

  // ---- tonemap and read back
  const Stopwatch readback_timer;
  const TonemapResources tonemap_resources{&accumulation_, &output_, &frame_uniforms_};
  device_->submit_and_wait([&](VkCommandBuffer cmd) {
    tonemap_.record(cmd, tonemap_resources, frame.width, frame.height);
  });
  rgba.resize(pixel_count * 4);
  std::memcpy(rgba.data(), output_.mapped(), pixel_count * 4);
  stats.readback_ms = readback_timer.elapsed_ms();
  stats.accumulated_samples = accumulated_samples_;

  blas_cache_.evict_unused(frame_number_);
}

PathTracer::PathTracer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PathTracer::~PathTracer() = default;

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
    auto impl = std::make_unique<Impl>(settings, std::move(device));
    return std::unique_ptr<PathTracer>(new PathTracer(std::move(impl)));
  } catch (const std::exception& e) {
    if (error != nullptr) *error = e.what();
  } catch (...) {
    if (error != nullptr) *error = "glpt: unknown error while creating the Vulkan renderer";
  }
  return nullptr;
}

std::unique_ptr<PathTracer> PathTracer::create(const RenderSettings& settings, std::string* error) {
  try {
    DeviceOptions options;
    options.validation = settings.validation;
    if (const char* filter = std::getenv("GLPT_VK_DEVICE")) options.name_filter = filter;
    return create(VulkanDevice::create(options), settings, error);
  } catch (const std::exception& e) {
    if (error != nullptr) *error = e.what();
  }
  return nullptr;
}

bool PathTracer::render(const TraceScene& frame, std::vector<uint8_t>& rgba, FrameStats& stats,
                        std::string* error) {
  try {
    impl_->render(frame, rgba, stats);
    return true;
  } catch (const std::exception& e) {
    if (error != nullptr) *error = std::string("glpt: render failed: ") + e.what();
  } catch (...) {
    if (error != nullptr) *error = "glpt: render failed: unknown error";
  }
  impl_->forget_previous_frame();
  return false;
}

const std::string& PathTracer::device_name() const { return impl_->device_name(); }

}  // namespace glpt::rt
