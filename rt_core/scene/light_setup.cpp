#include "rt_core/scene/light_setup.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/trigonometric.hpp>

namespace glpt::rt {
namespace {

uint32_t shadow_bit(size_t light_index) {
  return 1u << std::min<size_t>(light_index, GLPT_MASK_SHADOW_BITS - 1);
}

glm::vec3 normalize_or(const glm::vec3& v, const glm::vec3& fallback) {
  float length = glm::length(v);
  return length > 0.0f && std::isfinite(length) ? v / length : fallback;
}

gpu::GpuLight pack_light(const Light& light, size_t index, const LightSize& size) {
  gpu::GpuLight packed{};
  packed.position = light.position;
  if (light.position.w == 0.0f) {
    packed.position = glm::vec4(normalize_or(glm::vec3(light.position), glm::vec3(0, 0, 1)), 0.0f);
  }
  packed.ambient = light.ambient;
  packed.diffuse = light.diffuse;
  packed.specular = light.specular;
  // GL: cutoff 180 is "no spot". GL 1.5 2.14.1 and Mesa apply a spot cutoff to directional
  // lights too (the light's direction is VP), as piglit's infinite-spot-light checks; the trace
  // pass does so in its GL-parity evaluation only (a distant light has no position to be a spot).
  const bool spot = light.spot_cutoff < 180.0f;
  const float cutoff = glm::radians(std::clamp(light.spot_cutoff, 0.0f, 90.0f));
  packed.spot = glm::vec4(normalize_or(light.spot_direction, glm::vec3(0, 0, -1)),
                          spot ? std::cos(cutoff) : -2.0f);
  packed.attenuation = glm::vec4(light.constant_attenuation, light.linear_attenuation,
                                 light.quadratic_attenuation, light.spot_exponent);
  float radius = 0.0f;
  if (light.position.w != 0.0f) {
    const glm::vec3 centre = glm::vec3(light.position) / light.position.w;
    radius =
        size.radius >= 0.0f ? size.radius : std::sin(size.angular_radius_rad) * glm::length(centre);
    if (!std::isfinite(radius) || radius < 0.0f) radius = 0.0f;
  }
  packed.params = glm::uvec4(shadow_bit(index), std::bit_cast<uint32_t>(radius), 0u, 0u);
  return packed;
}

}  // namespace

EyeBounds EyeBounds::transformed(const glm::vec3& object_min, const glm::vec3& object_max,
                                 const glm::mat4& transform) {
  EyeBounds bounds;
  for (int corner = 0; corner < 8; ++corner) {
    glm::vec3 p((corner & 1) ? object_max.x : object_min.x,
                (corner & 2) ? object_max.y : object_min.y,
                (corner & 4) ? object_max.z : object_min.z);
    bounds.extend(glm::vec3(transform * glm::vec4(p, 1.0f)));
  }
  return bounds;
}

Light default_light() {
  Light light;
  light.position = glm::vec4(glm::normalize(glm::vec3(-1.0f, 1.0f, 1.0f)), 0.0f);
  light.ambient = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  light.diffuse = glm::vec4(1.0f);
  light.specular = glm::vec4(1.0f);
  return light;
}

LightSetup setup_lights(std::span<const Light> lights, std::span<const EyeBounds> instance_bounds,
                        const EyeBounds& scene_bounds, const LightSize& size) {
  LightSetup setup;
  for (size_t i = 0; i < lights.size(); ++i) setup.lights.push_back(pack_light(lights[i], i, size));

  const float lamp_max_diagonal = kLampMarkerMaxSceneFraction * scene_bounds.diagonal();
  setup.instance_masks.reserve(instance_bounds.size());
  for (const EyeBounds& bounds : instance_bounds) {
    // A shadow bit is cleared only if every light sharing it is inside this (small) instance.
    uint32_t lights_on_bit[GLPT_MASK_SHADOW_BITS] = {};
    uint32_t enclosed_on_bit[GLPT_MASK_SHADOW_BITS] = {};
    const bool small = !bounds.empty() && bounds.diagonal() < lamp_max_diagonal;
    for (size_t i = 0; i < lights.size(); ++i) {
      const size_t bit = std::min<size_t>(i, GLPT_MASK_SHADOW_BITS - 1);
      ++lights_on_bit[bit];
      const glm::vec4& position = lights[i].position;
      if (small && position.w != 0.0f && bounds.contains(glm::vec3(position) / position.w)) {
        ++enclosed_on_bit[bit];
      }
    }
    uint32_t mask = GLPT_MASK_VISIBLE | ((1u << GLPT_MASK_SHADOW_BITS) - 1);
    for (uint32_t bit = 0; bit < GLPT_MASK_SHADOW_BITS; ++bit) {
      if (lights_on_bit[bit] != 0 && enclosed_on_bit[bit] == lights_on_bit[bit])
        mask &= ~(1u << bit);
    }
    setup.instance_masks.push_back(mask);
  }
  return setup;
}

}  // namespace glpt::rt
