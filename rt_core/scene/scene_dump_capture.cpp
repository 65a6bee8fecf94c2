#include "rt_core/scene/scene_dump_capture.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

namespace glpt::rt {

SceneDumpCapture::SceneDumpCapture() {
  if (const char* path = std::getenv("GLPT_DUMP_SCENE"); path && *path) path_ = path;
  if (const char* frame = std::getenv("GLPT_DUMP_SCENE_FRAME"); frame && *frame) {
    char* end = nullptr;
    const unsigned long long n = std::strtoull(frame, &end, 10);
    if (end != nullptr && *end == '\0' && n > 0)
      target_ = n;
    else
      std::fprintf(stderr, "glpt: GLPT_DUMP_SCENE_FRAME=%s is not a positive number; using 3\n",
                   frame);
  }
}

void SceneDumpCapture::capture(const TraceScene& scene,
                               std::span<const VkAccelerationStructureInstanceKHR> instances,
                               const BlasCache& blases, std::span<const gpu::GpuLight> lights,
                               const gpu::FrameUniforms& uniforms, uint64_t frame_number) {
  dump_ = SceneDump();
  dump_.frame = frame_number;
  dump_.width = scene.width;
  dump_.height = scene.height;
  dump_.viewport = scene.camera_viewport;
  std::memcpy(dump_.projection.data(), &scene.camera_projection[0][0], sizeof(float) * 16);
  dump_.camera_valid = scene.camera_valid ? 1u : 0u;
  dump_.samples = uniforms.sampling.y;
  dump_.bounces = uniforms.sampling.z;
  dump_.options = uniforms.options.x;

  // BLAS device address -> its entry, and the entry's shape index in the dump.
  std::unordered_map<uint64_t, const BlasEntry*> by_address;
  for (const Instance& instance : scene.instances)
    if (instance.geometry)
      if (const BlasEntry* entry = blases.find(instance.geometry->shape_hash))
        by_address.emplace(entry->blas_address, entry);
  std::unordered_map<uint64_t, uint32_t> shape_of;
  for (const VkAccelerationStructureInstanceKHR& tlas_instance : instances) {
    const auto found = by_address.find(tlas_instance.accelerationStructureReference);
    if (found == by_address.end()) continue;  // cannot happen: every instance has its BLAS
    const BlasEntry& entry = *found->second;
    auto [shape, added] = shape_of.emplace(entry.blas_address, dump_.shapes.size());
    if (added) {
      SceneDumpShape& out = dump_.shapes.emplace_back();
      const auto* positions = entry.positions.as<gpu::GpuPosition>();
      out.positions.reserve(size_t{entry.triangle_count} * 9);
      for (size_t v = 0; v < size_t{entry.triangle_count} * 3; ++v)
        for (int c = 0; c < 3; ++c) out.positions.push_back(positions[v].position[c]);
    }
    SceneDumpInstance& out = dump_.instances.emplace_back();
    out.shape = shape->second;
    out.mask = tlas_instance.mask;
    out.flags = tlas_instance.flags;
    for (int row = 0; row < 3; ++row)
      for (int column = 0; column < 4; ++column)
        out.transform[4 * row + column] = tlas_instance.transform.matrix[row][column];
  }
  place_instances(dump_);
  for (const gpu::GpuLight& light : lights) {
    SceneDumpLight& out = dump_.lights.emplace_back();
    for (int c = 0; c < 4; ++c) out.position[c] = light.position[c];
    std::memcpy(&out.radius, &light.params.y, sizeof out.radius);
    out.shadow_mask = light.params.x;
  }
  captured_ = true;
}

void SceneDumpCapture::finish(const FrameStats& stats) {
  if (!captured_) return;
  captured_ = false;
  done_ = true;
  dump_.rays = stats.rays;
  dump_.trace_ms = stats.trace_ms;
  std::string error;
  if (write_scene_dump(path_, dump_, &error))
    std::fprintf(stderr,
                 "glpt: GLPT_DUMP_SCENE: frame %llu (%u instances, %llu triangles, %zu lights, "
                 "%llu rays, trace %.2f ms) written to %s\n",
                 static_cast<unsigned long long>(dump_.frame),
                 static_cast<unsigned>(dump_.instances.size()),
                 static_cast<unsigned long long>(dump_.triangle_count()), dump_.lights.size(),
                 static_cast<unsigned long long>(dump_.rays), dump_.trace_ms, path_.c_str());
  else
    std::fprintf(stderr, "glpt: GLPT_DUMP_SCENE: %s\n", error.c_str());
  dump_ = SceneDump();
}

}  // namespace glpt::rt
