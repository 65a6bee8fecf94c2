// GL lights -> the path tracer's light table, the default light, and per-instance shadow masks.
#pragma once

#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

#include "rt_core/scene/trace_scene.hpp"
#include "shared_types.h"

namespace glpt::rt {

// An axis-aligned box in eye space; starts empty.
struct EyeBounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};

  bool empty() const { return min.x > max.x; }
  void extend(const glm::vec3& point) {
    min = glm::min(min, point);
    max = glm::max(max, point);
  }
  void extend(const EyeBounds& other) {
    if (other.empty()) return;
    extend(other.min);
    extend(other.max);
  }
  float diagonal() const { return empty() ? 0.0f : glm::length(max - min); }
  bool contains(const glm::vec3& point) const {
    return glm::all(glm::greaterThanEqual(point, min)) && glm::all(glm::lessThanEqual(point, max));
  }
  // The eye-space box around an object-space box after `transform`.
  static EyeBounds transformed(const glm::vec3& object_min, const glm::vec3& object_max,
                               const glm::mat4& transform);
};

// Used when a frame has lit surfaces but no enabled light and the user asked for it
// (GLPT_DEFAULT_LIGHT=1; GL itself lights such a scene by ambient and emission alone):
// GL_LIGHT0's colours (diffuse and specular white, no ambient), directional, from the camera's
// upper left and slightly behind it: direction towards the light (-1, 1, 1) in eye space.
Light default_light();

struct LightSetup {
  std::vector<gpu::GpuLight> lights;
  std::vector<uint32_t> instance_masks;  // TLAS instance mask per instance (see shared_types.h)
};

// A positional light inside the bounds of an instance smaller than this fraction of the scene is
// taken to be inside a lamp marker (GL demos often draw a small sphere at the light position):
// that instance casts no shadow for that light, otherwise it would black out the whole light.
constexpr float kLampMarkerMaxSceneFraction = 0.1f;

// The size of GL's lights as light sources (docs/light-transport.md, "Lights").
struct LightSize {
  // Radius of positional lights (eye-space units); negative: the radius at which the light
  // subtends `angular_radius_rad` seen from the eye, so a light looks as large wherever it is.
  float radius = -1.0f;
  float angular_radius_rad = 0.0f;  // also the angular radius of directional lights
};

// Packs `lights` for the shader and computes each instance's shadow mask from its eye-space
// bounds (`instance_bounds`, one per instance) and the scene's bounds.
LightSetup setup_lights(std::span<const Light> lights, std::span<const EyeBounds> instance_bounds,
                        const EyeBounds& scene_bounds, const LightSize& size = {});

}  // namespace glpt::rt
