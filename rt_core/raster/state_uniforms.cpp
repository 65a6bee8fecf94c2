#include "rt_core/raster/state_uniforms.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "rt_core/raster/sampler_setup.hpp"

namespace glpt::rt {
namespace {

glm::vec3 normalize_or_zero(glm::vec3 v) {
  const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return len > 0.0f ? v / len : v;
}

gpu::RasterLight pack(const rec::Light& l) {
  gpu::RasterLight out{};
  out.ambient = l.ambient;
  out.diffuse = l.diffuse;
  out.specular = l.specular;
  if (l.position.w != 0.0f) {
    out.position = l.position;
  } else {
    // Mesa normalizes the direction of an infinite light and precomputes its half vector for
    // an infinite viewer.
    const glm::vec3 vp = normalize_or_zero(glm::vec3(l.position));
    out.position = glm::vec4(vp, 0.0f);
    out.half_vector = glm::vec4(normalize_or_zero(vp + glm::vec3(0, 0, 1)), 0.0f);
  }
  out.spot = glm::vec4(normalize_or_zero(l.spot_direction), packed_spot_cosine(l));
  out.attenuation = glm::vec4(l.constant_attenuation, l.linear_attenuation, l.quadratic_attenuation,
                              l.spot_exponent);
  return out;
}

}  // namespace

float packed_spot_cosine(const rec::Light& l) {
  // Mesa's cosine of the cutoff: cosf of the angle converted in double, clamped to >= 0.
  if (l.spot_cutoff == 180.0f) return -2.0f;
  return std::max(std::cos(static_cast<float>(l.spot_cutoff * M_PI / 180.0)), 0.0f);
}

uint32_t light_kind_bits(const rec::LightingState& lighting) {
  uint32_t bits = 0;
  for (int i = 0; i < rec::kMaxLights; ++i) {
    if ((lighting.light_mask & (1u << i)) == 0) continue;
    const rec::Light& l = lighting.lights[i];
    // The shader's own tests of the packed values (RasterLight position.w, spot.w).
    if (l.position.w != 0.0f) bits |= GLPT_LIGHT_POSITIONAL << i;
    if (packed_spot_cosine(l) > -1.5f) bits |= GLPT_LIGHT_SPOT << i;
  }
  return bits;
}

gpu::RasterMaterial pack_material(const rec::Material& m) {
  return {m.ambient, m.diffuse, m.specular, m.emission, glm::vec4(m.shininess, 0, 0, 0)};
}

void pack_state_uniforms(const rec::StateSnapshot& state, gpu::RasterState& out) {
  std::memset(&out, 0, sizeof out);
  const rec::TransformState& t = *state.transform;
  out.modelview = t.modelview;
  out.mvp = t.modelview_projection;
  // The normal matrix is the inverse transpose of the modelview's upper 3x3 (GL 1.5 2.11.3).
  const glm::mat4& inverse = t.modelview_inverse;
  out.normal_matrix = glm::transpose(inverse);
  const float row = std::sqrt(inverse[0][2] * inverse[0][2] + inverse[1][2] * inverse[1][2] +
                              inverse[2][2] * inverse[2][2]);
  out.normal_scale = glm::vec4(row > 0.0f ? 1.0f / row : 1.0f, 0, 0, 0);
  out.viewport = glm::vec4(t.viewport[0], t.viewport[1], t.viewport[2], t.viewport[3]);
  out.depth_range = glm::vec4(t.depth_near, t.depth_far, 0, 0);
  for (int i = 0; i < rec::kMaxClipPlanes; ++i) out.clip_planes[i] = t.clip_planes[i];

  const rec::LightingState& l = *state.lighting;
  out.light_model_ambient = l.model_ambient;
  for (int i = 0; i < rec::kMaxLights; ++i) out.lights[i] = pack(l.lights[i]);
  out.material[0] = pack_material(l.material[0]);
  out.material[1] = pack_material(l.material[1]);

  const rec::TexturingState& tex = *state.texturing;
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    const rec::TextureUnitState& unit = tex.units[u];
    out.texture_matrix[u] = unit.matrix;
    for (int c = 0; c < 4; ++c) {
      out.texgen_object[u * 4 + c] = unit.texgen[c].object_plane;
      out.texgen_eye[u * 4 + c] = unit.texgen[c].eye_plane;
    }
    out.env_color[u] = unit.env.color;
    out.env_scale[u] = glm::vec4(unit.env.rgb_scale, unit.env.alpha_scale, 0, 0);
    pack_texture_unit(unit, u, out);
  }

  const rec::RasterState& r = *state.raster;
  out.fog_color = r.fog.color;
  // As Mesa: a zero-length linear fog range gives scale 1 instead of a division by zero.
  const float range = r.fog.end - r.fog.start;
  out.fog_params =
      glm::vec4(r.fog.density, r.fog.start, r.fog.end, range != 0.0f ? 1.0f / range : 1.0f);
  out.alpha_ref = glm::vec4(r.ops.alpha_ref, 0, 0, 0);
  for (int row = 0; row < 32; ++row)
    out.stipple[row / 4][row % 4] = r.primitive.stipple_pattern[row];
  out.point_size =
      glm::vec4(r.primitive.point_size, std::max(r.primitive.point_size_min, 1.0f),
                std::min(r.primitive.point_size_max, 256.0f), r.primitive.point_fade_threshold);
  out.point_attenuation = glm::vec4(r.primitive.point_distance_attenuation, 0.0f);
  // Mesa's units: twice the minimum resolvable difference of a 24-bit depth buffer.
  out.polygon_offset = glm::vec4(r.primitive.offset_factor,
                                 r.primitive.offset_units * 2.0f / 16777215.0f, 0.0f, 0.0f);
}

}  // namespace glpt::rt
