// The rays bench/ray_ceiling traces, and the scene as both tracers take it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rt_core/scene/scene_dump.hpp"

namespace ray_ceiling {

// Matches `Ray` in trace.comp (std430, 48 bytes).
struct Ray {
  float org[3];
  float tmin;
  float dir[3];
  float tmax;
  uint32_t flags;  // kTerminateOnFirstHit
  uint32_t mask;   // cull mask
  uint32_t pad[2];
};
static_assert(sizeof(Ray) == 48);
constexpr uint32_t kTerminateOnFirstHit = 1;
constexpr float kUnbounded = 1.0e30f;

// Matches `Hit` in trace.comp.
struct Hit {
  float t;  // -1: miss
  int32_t instance;
  int32_t primitive;
  uint32_t pad;
};
static_assert(sizeof(Hit) == 16);

// The acceleration-structure input: shapes (object-space triangles) and instances of them.
struct AccelInput {
  std::vector<std::vector<float>> shapes;  // 9 floats per triangle
  struct Instance {
    uint32_t shape;
    uint32_t mask;
    std::array<float, 12> transform;  // row-major 3x4
  };
  std::vector<Instance> instances;
  // Instance i's primitive p is triangle global[i][p] of the dump's eye_triangles.
  std::vector<std::vector<uint32_t>> global;
};
// The TLAS glpt traced: its instances, masks and BLASes (primitive order as glpt built them).
AccelInput instanced_input(const glpt::rt::SceneDump& dump);
// One identity instance per distinct mask, each over a BLAS of all the eye-space triangles of
// the instances with that mask, Morton-sorted like glpt's BLASes.
AccelInput flat_input(const glpt::rt::SceneDump& dump);

// The eye-space triangle a hit refers to, -1 for a miss.
int64_t global_triangle(const AccelInput& input, const Hit& hit);

// One wave of rays with where they came from (pixel), in 8x8 pixel tiles like the trace pass.
struct Wave {
  std::vector<Ray> rays;
  std::vector<uint32_t> pixel;
};
enum class Kind : uint32_t { kShadow = 0, kAo = 1, kBounce = 2 };

// Primary rays through the dump's camera (the main camera's projection and viewport), one per
// pixel of the viewport, in 8x8 tiles; mask GLPT_MASK_VISIBLE.
Wave primary_rays(const glpt::rt::SceneDump& dump);

struct MixOptions {
  bool ao = true;      // an ambient-occlusion ray at the primary hit (glpt's default)
  bool bounce = true;  // one bounce (GLPT_BOUNCES >= 1)
  uint32_t seed = 1;
};
// From the primary hits (`hits`, per primary ray; eye-space triangles of `dump`): per hit pixel
// a shadow ray towards one light chosen at random (terminate on first hit; skipped when the
// light is below the surface, as glpt skips it), an AO ray and a bounce ray (cosine-distributed,
// closest hit). `kinds` gets each ray's Kind.
Wave first_vertex_rays(const glpt::rt::SceneDump& dump, const Wave& primary,
                       const std::vector<Hit>& hits, const AccelInput& input,
                       const MixOptions& options, std::vector<Kind>& kinds);
// From the bounce rays' hits: a shadow ray each, as above.
Wave bounce_vertex_rays(const glpt::rt::SceneDump& dump, const Wave& first,
                        const std::vector<Kind>& kinds, const std::vector<Hit>& hits,
                        const AccelInput& input, const MixOptions& options);

}  // namespace ray_ceiling
