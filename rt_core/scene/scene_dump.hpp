// GLPT_DUMP_SCENE: one path-traced frame's ray-traced world written to a file, for measurements
// outside glpt (bench/ray_ceiling traces the same triangles with a bare ray-query shader and with
// Embree). The format (docs/ray-ceiling.md, "Scene dump format") is little-endian binary:
//
//   header    "GLPTSCN1", u32 version (1), then the SceneDump scalars in declaration order
//   shapes    u32 count; per shape: u32 triangle count, f32[9 * count] object-space positions in
//             BLAS primitive order (the Morton order glpt built the BLAS in)
//   instances u32 count, in TLAS order; per instance: u32 shape, u32 mask, u32 flags
//             (VkGeometryInstanceFlagsKHR), f32[12] transform (VkTransformMatrixKHR: 3 rows of 4,
//             object -> eye space), u64 first triangle in `eye_triangles`, u32 triangle count
//   triangles u64 count; f32[9 * count]: every instance's triangles in eye space, in instance
//             order (instance i's transform applied to its shape's positions)
//   lights    u32 count; per light: f32[4] eye-space position (w = 0: direction towards the
//             light), f32 sphere radius (0: a point light), u32 shadow-ray cull mask
//
// Depends on the standard library only (the bench program reads it without the renderer).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace glpt::rt {

struct SceneDumpShape {
  std::vector<float> positions;  // 9 floats per triangle, object space
  uint32_t triangle_count() const { return static_cast<uint32_t>(positions.size() / 9); }
};

struct SceneDumpInstance {
  uint32_t shape = 0;  // index into SceneDump::shapes
  uint32_t mask = 0;   // TLAS instance mask (shared_types.h: GLPT_MASK_*)
  uint32_t flags = 0;  // VkGeometryInstanceFlagsKHR
  std::array<float, 12> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};  // row-major 3x4
  uint64_t first_triangle = 0;  // in SceneDump::eye_triangles
  uint32_t triangle_count = 0;
};

struct SceneDumpLight {
  std::array<float, 4> position{0, 0, 1, 0};  // eye space; w == 0: direction towards the light
  float radius = 0.0f;
  uint32_t shadow_mask = 0;  // cull mask of its shadow rays
};

struct SceneDump {
  static constexpr uint32_t kVersion = 1;
  uint64_t frame = 0;  // glpt's count of path-traced frames when it was taken (0-based)
  uint32_t width = 0;  // drawable size in pixels
  uint32_t height = 0;
  std::array<int32_t, 4> viewport{0, 0, 0, 0};  // the main camera's GL viewport
  std::array<float, 16> projection{};           // its projection, column-major (GL order)
  uint32_t camera_valid = 0;                    // 0: no main camera was found
  uint32_t samples = 0;                         // paths per pixel this frame (GLPT_SPP)
  uint32_t bounces = 0;                         // GLPT_BOUNCES
  uint32_t options = 0;                         // FrameUniforms::options.x (GLPT_OPTION_*)
  uint64_t rays = 0;                            // rays the trace pass counted this frame
  double trace_ms = 0.0;                        // device time of the trace pass this frame
  std::vector<SceneDumpShape> shapes;
  std::vector<SceneDumpInstance> instances;
  std::vector<float> eye_triangles;  // 9 floats per triangle
  std::vector<SceneDumpLight> lights;

  uint64_t triangle_count() const { return eye_triangles.size() / 9; }
};

// Fills eye_triangles and each instance's first_triangle / triangle_count from the shapes and
// transforms.
void place_instances(SceneDump& dump);

// false and a message in *error (may be null) when the file cannot be written / read or is not
// a valid dump.
bool write_scene_dump(const std::string& path, const SceneDump& dump, std::string* error);
bool read_scene_dump(const std::string& path, SceneDump& dump, std::string* error);

}  // namespace glpt::rt
