#include "gl_shim/state/vertex_shading.hpp"

#include <algorithm>
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "rt_core/record/texgen.hpp"

namespace glpt {
namespace {

// Mesa's vector macros: rt_core/record/mesa_vector.hpp

using rec::dot3;

bool is_spot(const rec::Light& light) { return light.spot_cutoff != 180.0f; }
bool is_positional(const rec::Light& light) { return light.position.w != 0.0f; }

// One light as Mesa prepares it (compute_light_positions, _mesa_update_material): in the space
// lighting runs in, with the material products.
struct PreparedLight {
  glm::vec3 position{0.0f};  // positional lights: divided by w
  glm::vec3 vp_infinite{0.0f}, h_infinite{0.0f};
  float infinite_spot_attenuation = 1.0f;
  glm::vec3 spot_direction{0.0f};
  float cos_cutoff = 0.0f;
  glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f};  // light x material
};

PreparedLight prepare_light(const rec::Light& light, const rec::Material& material, bool eye,
                            const glm::mat4& modelview, const glm::mat4& inverse,
                            const glm::vec3& eye_z, bool local_viewer) {
  PreparedLight p;
  const glm::vec4 position = eye ? light.position : transform_point(inverse, light.position);
  // _CosCutoff as Mesa stores it at glLight time: cos in double, negative values clamped to 0.
  p.cos_cutoff =
      std::max(0.0f, static_cast<float>(std::cos(double{light.spot_cutoff} * M_PI / 180.0)));
  if (!is_positional(light)) {
    p.vp_infinite = normalize3(glm::vec3(position));
    if (!local_viewer) p.h_infinite = normalize3(p.vp_infinite + eye_z);
  } else {
    const float w_inverse = 1.0f / position.w;
    p.position = glm::vec3(position.x * w_inverse, position.y * w_inverse, position.z * w_inverse);
  }
  if (is_spot(light)) {
    p.spot_direction = normalize3(light.spot_direction);
    if (!eye) p.spot_direction = transform_normal(p.spot_direction, modelview);
    p.spot_direction = normalize3(p.spot_direction);
    if (!is_positional(light)) {
      const float pv_dot_dir = -dot3(p.vp_infinite, p.spot_direction);
      p.infinite_spot_attenuation =
          pv_dot_dir > p.cos_cutoff ? std::pow(pv_dot_dir, light.spot_exponent) : 0.0f;
    }
  }
  p.ambient = glm::vec3(light.ambient) * glm::vec3(material.ambient);
  p.diffuse = glm::vec3(light.diffuse) * glm::vec3(material.diffuse);
  p.specular = glm::vec3(light.specular) * glm::vec3(material.specular);
  return p;
}

}  // namespace

glm::vec3 transform_normal(const glm::vec3& n, const glm::mat4& m) {
  glm::vec3 q;
  for (int c = 0; c < 3; ++c) q[c] = n.x * m[c][0] + n.y * m[c][1] + n.z * m[c][2];
  return q;
}

bool need_eye_coordinates(const Context& ctx, const rec::TexturingState& texturing) {
  const rec::LightingState& l = ctx.lighting;
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    const TextureUnit& unit = ctx.textures.units[u];
    if (texturing.units[u].target == 0) continue;  // Mesa looks at texgen of enabled units only
    for (int c = 0; c < 4; ++c) {
      if (!(unit.texgen_mask & (1u << c))) continue;
      const uint32_t mode = unit.texgen[c].mode;
      if (mode == GL_EYE_LINEAR || mode == GL_SPHERE_MAP || mode == GL_REFLECTION_MAP ||
          mode == GL_NORMAL_MAP)
        return true;
    }
  }
  if (ctx.raster.primitive.point_distance_attenuation != glm::vec3(1.0f, 0.0f, 0.0f)) return true;
  if (!l.enabled) return false;
  if (l.local_viewer || l.separate_specular) return true;
  for (int i = 0; i < rec::kMaxLights; ++i)
    if ((l.light_mask & (1u << i)) && (is_positional(l.lights[i]) || is_spot(l.lights[i])))
      return true;
  return !ctx.matrices.modelview.top_matrix().length_preserving();
}

// shade_rastpos: the lit colour and secondary colour.
LitColors light_vertex(Context& ctx, const rec::Material& material, bool eye,
                       const glm::vec3& vertex, const glm::vec3& normal) {
  const rec::LightingState& l = ctx.lighting;
  const glm::mat4& modelview = ctx.matrices.modelview.top();
  const glm::mat4& inverse = ctx.matrices.modelview.top_matrix().inverse();
  const glm::vec3 eye_z =
      eye ? glm::vec3(0.0f, 0.0f, 1.0f) : transform_normal(glm::vec3(0.0f, 0.0f, 1.0f), modelview);

  glm::vec3 base = glm::vec3(material.emission);
  for (int c = 0; c < 3; ++c) base[c] += material.ambient[c] * l.model_ambient[c];
  glm::vec3 diffuse_sum = base, specular_sum(0.0f);
  const glm::vec3& v = vertex;
  for (int i = 0; i < rec::kMaxLights; ++i) {
    if (!(l.light_mask & (1u << i))) continue;
    const rec::Light& light = l.lights[i];
    const PreparedLight p =
        prepare_light(light, material, eye, modelview, inverse, eye_z, l.local_viewer);
    float attenuation = 1.0f;
    glm::vec3 vp;
    if (!is_positional(light)) {
      vp = p.vp_infinite;
      attenuation = p.infinite_spot_attenuation;
    } else {
      vp = p.position - v;
      const float d = std::sqrt(dot3(vp, vp));
      if (d > 1.0e-6f) vp *= 1.0f / d;
      attenuation = 1.0f / (light.constant_attenuation +
                            d * (light.linear_attenuation + d * light.quadratic_attenuation));
      if (is_spot(light)) {
        const float pv_dot_dir = -dot3(vp, p.spot_direction);
        if (pv_dot_dir < p.cos_cutoff) continue;
        attenuation *= std::pow(pv_dot_dir, light.spot_exponent);
      }
    }
    if (attenuation < 1e-3f) continue;
    const float n_dot_vp = dot3(normal, vp);
    if (n_dot_vp < 0.0f) {
      diffuse_sum += attenuation * p.ambient;
      continue;
    }
    glm::vec3 contribution = p.ambient + n_dot_vp * p.diffuse;
    glm::vec3 specular_contribution(0.0f);
    glm::vec3 h;
    if (l.local_viewer) {
      h = normalize3(vp - normalize3(v));
    } else if (is_positional(light)) {
      h = normalize3(vp + eye_z);
    } else {
      h = p.h_infinite;
    }
    const float n_dot_h = dot3(normal, h);
    if (n_dot_h > 0.0f) {
      const float coefficient = std::pow(n_dot_h, material.shininess);
      if (coefficient > 1.0e-10f) {
        if (l.separate_specular)
          specular_contribution += coefficient * p.specular;
        else
          contribution += coefficient * p.specular;
      }
    }
    diffuse_sum += attenuation * contribution;
    specular_sum += attenuation * specular_contribution;
  }
  LitColors lit;
  lit.color = glm::clamp(glm::vec4(diffuse_sum, material.diffuse.a), 0.0f, 1.0f);
  lit.secondary = glm::clamp(glm::vec4(specular_sum, 1.0f), 0.0f, 1.0f);
  return lit;
}

glm::vec4 generate_tex_coord(const TextureUnit& unit, const glm::vec4& object, const glm::vec4& eye,
                             const glm::vec3& normal, glm::vec4 tc) {
  return rec::generate_tex_coord(unit.texgen_mask, unit.texgen, object, eye, normal, tc);
}

void viewport_transform(const Context& ctx, glm::vec3& scale, glm::vec3& translate) {
  const FramebufferState& fb = ctx.framebuffer;
  const float x = static_cast<float>(fb.viewport_x), y = static_cast<float>(fb.viewport_y);
  const float half_width = 0.5f * static_cast<float>(fb.viewport_width);
  const float half_height = 0.5f * static_cast<float>(fb.viewport_height);
  // Mesa keeps the depth range in float and computes this in double.
  const double n = static_cast<float>(fb.depth_near), f = static_cast<float>(fb.depth_far);
  scale = glm::vec3(half_width, half_height, static_cast<float>(0.5 * (f - n)));
  translate = glm::vec3(half_width + x, half_height + y, static_cast<float>(0.5 * (n + f)));
}

}  // namespace glpt
