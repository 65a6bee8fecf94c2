// glRasterPos* and glWindowPos* (GL 1.5 2.13; GL 1.4 2.13 for WindowPos).
//
// The raster position is computed on the CPU with Mesa's float arithmetic in Mesa's order of
// operations (src/mesa/main/rastpos.c, _mesa_RasterPos), because Mesa does exactly that for
// fixed-function state and its results decide where bitmaps land and what colour they have.
// Mesa's choices that differ from a literal reading of the spec, kept on purpose:
// - an invalid raster position leaves every other raster attribute as it was;
// - without lighting the raster colours are the current colours unclamped (queries show them);
// - the raster distance is the eye-space length sqrt(x^2 + y^2 + z^2) of the undivided eye
//   position (or the current fog coordinate with GL_FOG_COORDINATE);
// - lighting uses the front material only, the current normal as given (never normalized), and
//   the *object-space* vertex for positional lights and the local viewer; lights, the normal and
//   the viewer direction are in eye space or in object space depending on what Mesa calls
//   _NeedEyeCoords (see need_eye_coordinates).
#include "gl_shim/pixels/raster_position.hpp"

#include <algorithm>
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/textures/texture_snapshot.hpp"

namespace glpt {
namespace {

// ---- Mesa's vector macros (src/mesa/main/macros.h, src/mesa/math/m_xform.h) -------------------

// TRANSFORM_NORMAL: the row vector n times the upper 3x3 of m (with m the inverse modelview this
// is the inverse transpose applied to n).
glm::vec3 transform_normal(const glm::vec3& n, const glm::mat4& m) {
  glm::vec3 q;
  for (int c = 0; c < 3; ++c) q[c] = n.x * m[c][0] + n.y * m[c][1] + n.z * m[c][2];
  return q;
}

float dot3(const glm::vec3& a, const glm::vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float dot4(const glm::vec4& a, const glm::vec4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}

// NORMALIZE_3FV: scaled by the reciprocal of the length; a zero vector stays zero.
glm::vec3 normalize3(glm::vec3 v) {
  float len = dot3(v, v);
  if (len != 0.0f) {
    len = 1.0f / std::sqrt(len);
    v *= len;
  }
  return v;
}

bool is_spot(const rec::Light& light) { return light.spot_cutoff != 180.0f; }
bool is_positional(const rec::Light& light) { return light.position.w != 0.0f; }

// Mesa's ctx->_NeedEyeCoords: whether lighting and texture generation run in eye space (else
// lights are moved into object space, which Mesa does while the modelview preserves lengths).
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

// One light as Mesa prepares it (compute_light_positions, _mesa_update_material): in the space
// lighting runs in, with the material products.
struct PreparedLight {
  glm::vec3 position{0.0f};  // positional lights: divided by w
  glm::vec3 vp_infinite{0.0f}, h_infinite{0.0f};
  float infinite_spot_attenuation = 1.0f;
  glm::vec3 spot_direction{0.0f};
  float cos_cutoff = 0.0f;
  glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f};  // light x front material
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

// shade_rastpos: the lit raster colour and secondary colour (front face).
void shade(Context& ctx, bool eye, const glm::vec4& vertex, const glm::vec3& normal,
           glm::vec4& color, glm::vec4& secondary) {
  const rec::LightingState& l = ctx.lighting;
  const rec::Material& material = l.material[0];
  const glm::mat4& modelview = ctx.matrices.modelview.top();
  const glm::mat4& inverse = ctx.matrices.modelview.top_matrix().inverse();
  const glm::vec3 eye_z =
      eye ? glm::vec3(0.0f, 0.0f, 1.0f) : transform_normal(glm::vec3(0.0f, 0.0f, 1.0f), modelview);

  glm::vec3 base = glm::vec3(material.emission);
  for (int c = 0; c < 3; ++c) base[c] += material.ambient[c] * l.model_ambient[c];
  glm::vec3 diffuse_sum = base, specular_sum(0.0f);
  const glm::vec3 v(vertex);
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
  color = glm::clamp(glm::vec4(diffuse_sum, material.diffuse.a), 0.0f, 1.0f);
  secondary = glm::clamp(glm::vec4(specular_sum, 1.0f), 0.0f, 1.0f);
}

// compute_texgen: the generated coordinates of one unit (only the enabled ones change).
glm::vec4 generate_tex_coord(const TextureUnit& unit, const glm::vec4& object, const glm::vec4& eye,
                             const glm::vec3& normal, glm::vec4 tc) {
  const glm::vec3 u = normalize3(glm::vec3(eye));
  const float two_nu = 2.0f * dot3(normal, u);
  const glm::vec3 r(u.x - normal.x * two_nu, u.y - normal.y * two_nu, u.z - normal.z * two_nu);
  const float m = r.x * r.x + r.y * r.y + (r.z + 1.0f) * (r.z + 1.0f);
  const float m_inverse = m > 0.0f ? 0.5f * (1.0f / std::sqrt(m)) : 0.0f;
  for (int c = 0; c < 4; ++c) {
    if (!(unit.texgen_mask & (1u << c))) continue;
    const rec::TexGen& g = unit.texgen[c];
    switch (g.mode) {
      case GL_OBJECT_LINEAR:
        tc[c] = dot4(object, g.object_plane);
        break;
      case GL_EYE_LINEAR:
        tc[c] = dot4(eye, g.eye_plane);
        break;
      case GL_SPHERE_MAP:
        if (c < 2) tc[c] = r[c] * m_inverse + 0.5f;
        break;
      case GL_REFLECTION_MAP:
        if (c < 3) tc[c] = r[c];
        break;
      case GL_NORMAL_MAP:
        if (c < 3) tc[c] = normal[c];
        break;
      default:
        break;
    }
  }
  return tc;
}

// Mesa's _mesa_get_viewport_xform.
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

bool inside_view_volume(const glm::vec4& clip) {
  if (clip.z < -clip.w || clip.z > clip.w) return false;
  return !(clip.x > clip.w || clip.x < -clip.w || clip.y > clip.w || clip.y < -clip.w);
}

// Mesa tests user clip planes in clip space: each eye-space plane times the inverse projection
// (_ClipUserPlane).
bool inside_clip_planes(Context& ctx, const glm::vec4& clip) {
  const uint8_t mask = ctx.transform.clip_plane_mask;
  if (mask == 0) return true;
  const glm::mat4& inverse = ctx.matrices.projection.top_matrix().inverse();
  for (int p = 0; p < rec::kMaxClipPlanes; ++p) {
    if (!(mask & (1u << p))) continue;
    const glm::vec4 plane = transform_row_vector(ctx.transform.clip_planes[p], inverse);
    if (dot4(clip, plane) < 0.0f) return false;
  }
  return true;
}

}  // namespace

void set_raster_position(Context& ctx, const glm::vec4& object) {
  ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask);  // Mesa's _mesa_update_state
  ctx.flushed_tex_coord = ctx.current.tex_coord;                  // Mesa's FLUSH_CURRENT
  rec::RasterPosition& rp = ctx.raster_position;
  const glm::vec4 eye = transform_point(ctx.matrices.modelview.top(), object);
  const glm::vec4 clip = transform_point(ctx.matrices.projection.top(), eye);
  if (!inside_view_volume(clip) || !inside_clip_planes(ctx, clip)) {
    rp.valid = false;  // Mesa leaves the other raster attributes unchanged
    return;
  }
  const float d = clip.w == 0.0f ? 1.0f : 1.0f / clip.w;
  const glm::vec3 ndc(clip.x * d, clip.y * d, clip.z * d);
  glm::vec3 scale, translate;
  viewport_transform(ctx, scale, translate);
  rp.window = glm::vec4(ndc.x * scale.x + translate.x, ndc.y * scale.y + translate.y,
                        ndc.z * scale.z + translate.z, clip.w);
  rp.distance = ctx.raster.fog.coord_source == GL_FOG_COORDINATE
                    ? ctx.current.fog_coord
                    : std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);

  rec::TexturingState texturing;
  snapshot_texturing(ctx, texturing);
  const bool eye_space = need_eye_coordinates(ctx, texturing);
  const glm::vec3 normal =
      eye_space
          ? transform_normal(ctx.current.normal, ctx.matrices.modelview.top_matrix().inverse())
          : ctx.current.normal;
  if (ctx.lighting.enabled) {
    shade(ctx, eye_space, object, normal, rp.color, rp.secondary_color);
  } else {
    rp.color = ctx.current.color;
    rp.secondary_color = ctx.current.secondary_color;
  }
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    glm::vec4 tc = ctx.current.tex_coord[u];
    const TextureUnit& unit = ctx.textures.units[u];
    if (unit.texgen_mask != 0) tc = generate_tex_coord(unit, object, eye, normal, tc);
    rp.tex_coord[u] = transform_point(ctx.matrices.texture[u].top(), tc);
  }
  rp.valid = true;
}

void set_window_position(Context& ctx, float x, float y, float z) {
  ctx.flushed_tex_coord = ctx.current.tex_coord;  // Mesa's FLUSH_CURRENT
  rec::RasterPosition& rp = ctx.raster_position;
  const FramebufferState& fb = ctx.framebuffer;
  // In float, from Mesa's float depth range.
  const float n = static_cast<float>(fb.depth_near), f = static_cast<float>(fb.depth_far);
  const float depth = std::clamp(z, 0.0f, 1.0f) * (f - n) + n;
  rp.window = glm::vec4(x, y, depth, 1.0f);
  rp.valid = true;
  rp.distance = ctx.raster.fog.coord_source == GL_FOG_COORDINATE ? ctx.current.fog_coord : 0.0f;
  rp.color = glm::clamp(ctx.current.color, 0.0f, 1.0f);
  rp.secondary_color = glm::clamp(ctx.current.secondary_color, 0.0f, 1.0f);
  rp.tex_coord = ctx.current.tex_coord;
}

namespace impl {

// Every variant converts to float first, as Mesa does.
void glRasterPos2d(Context& ctx, GLdouble x, GLdouble y) {
  set_raster_position(ctx, {float(x), float(y), 0.0f, 1.0f});
}
void glRasterPos2f(Context& ctx, GLfloat x, GLfloat y) {
  set_raster_position(ctx, {x, y, 0.0f, 1.0f});
}
void glRasterPos2i(Context& ctx, GLint x, GLint y) {
  set_raster_position(ctx, {float(x), float(y), 0.0f, 1.0f});
}
void glRasterPos2s(Context& ctx, GLshort x, GLshort y) {
  set_raster_position(ctx, {float(x), float(y), 0.0f, 1.0f});
}
void glRasterPos3d(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  set_raster_position(ctx, {float(x), float(y), float(z), 1.0f});
}
void glRasterPos3f(Context& ctx, GLfloat x, GLfloat y, GLfloat z) {
  set_raster_position(ctx, {x, y, z, 1.0f});
}
void glRasterPos3i(Context& ctx, GLint x, GLint y, GLint z) {
  set_raster_position(ctx, {float(x), float(y), float(z), 1.0f});
}
void glRasterPos3s(Context& ctx, GLshort x, GLshort y, GLshort z) {
  set_raster_position(ctx, {float(x), float(y), float(z), 1.0f});
}
void glRasterPos4d(Context& ctx, GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  set_raster_position(ctx, {float(x), float(y), float(z), float(w)});
}
void glRasterPos4f(Context& ctx, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  set_raster_position(ctx, {x, y, z, w});
}
void glRasterPos4i(Context& ctx, GLint x, GLint y, GLint z, GLint w) {
  set_raster_position(ctx, {float(x), float(y), float(z), float(w)});
}
void glRasterPos4s(Context& ctx, GLshort x, GLshort y, GLshort z, GLshort w) {
  set_raster_position(ctx, {float(x), float(y), float(z), float(w)});
}
// The vector forms ignore a null pointer, as the generated attribute families do.
void glRasterPos2dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glRasterPos2d(ctx, v[0], v[1]);
}
void glRasterPos2fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glRasterPos2f(ctx, v[0], v[1]);
}
void glRasterPos2iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glRasterPos2i(ctx, v[0], v[1]);
}
void glRasterPos2sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glRasterPos2s(ctx, v[0], v[1]);
}
void glRasterPos3dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glRasterPos3d(ctx, v[0], v[1], v[2]);
}
void glRasterPos3fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glRasterPos3f(ctx, v[0], v[1], v[2]);
}
void glRasterPos3iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glRasterPos3i(ctx, v[0], v[1], v[2]);
}
void glRasterPos3sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glRasterPos3s(ctx, v[0], v[1], v[2]);
}
void glRasterPos4dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glRasterPos4d(ctx, v[0], v[1], v[2], v[3]);
}
void glRasterPos4fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glRasterPos4f(ctx, v[0], v[1], v[2], v[3]);
}
void glRasterPos4iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glRasterPos4i(ctx, v[0], v[1], v[2], v[3]);
}
void glRasterPos4sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glRasterPos4s(ctx, v[0], v[1], v[2], v[3]);
}

void glWindowPos2d(Context& ctx, GLdouble x, GLdouble y) {
  set_window_position(ctx, float(x), float(y), 0.0f);
}
void glWindowPos2f(Context& ctx, GLfloat x, GLfloat y) { set_window_position(ctx, x, y, 0.0f); }
void glWindowPos2i(Context& ctx, GLint x, GLint y) {
  set_window_position(ctx, float(x), float(y), 0.0f);
}
void glWindowPos2s(Context& ctx, GLshort x, GLshort y) {
  set_window_position(ctx, float(x), float(y), 0.0f);
}
void glWindowPos3d(Context& ctx, GLdouble x, GLdouble y, GLdouble z) {
  set_window_position(ctx, float(x), float(y), float(z));
}
void glWindowPos3f(Context& ctx, GLfloat x, GLfloat y, GLfloat z) {
  set_window_position(ctx, x, y, z);
}
void glWindowPos3i(Context& ctx, GLint x, GLint y, GLint z) {
  set_window_position(ctx, float(x), float(y), float(z));
}
void glWindowPos3s(Context& ctx, GLshort x, GLshort y, GLshort z) {
  set_window_position(ctx, float(x), float(y), float(z));
}
void glWindowPos2dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glWindowPos2d(ctx, v[0], v[1]);
}
void glWindowPos2fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glWindowPos2f(ctx, v[0], v[1]);
}
void glWindowPos2iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glWindowPos2i(ctx, v[0], v[1]);
}
void glWindowPos2sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glWindowPos2s(ctx, v[0], v[1]);
}
void glWindowPos3dv(Context& ctx, const GLdouble* v) {
  if (v != nullptr) glWindowPos3d(ctx, v[0], v[1], v[2]);
}
void glWindowPos3fv(Context& ctx, const GLfloat* v) {
  if (v != nullptr) glWindowPos3f(ctx, v[0], v[1], v[2]);
}
void glWindowPos3iv(Context& ctx, const GLint* v) {
  if (v != nullptr) glWindowPos3i(ctx, v[0], v[1], v[2]);
}
void glWindowPos3sv(Context& ctx, const GLshort* v) {
  if (v != nullptr) glWindowPos3s(ctx, v[0], v[1], v[2]);
}

}  // namespace impl
}  // namespace glpt
