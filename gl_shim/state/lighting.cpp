// glLight*, glLightModel*, glMaterial*, glColorMaterial, glShadeModel and their queries
// (GL 1.5 spec 2.14). The live state is ctx.lighting, a rec::LightingState.
#include "gl_shim/state/lighting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/geometry/attributes.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/mesa_matrix.hpp"
#include "gl_shim/state/normalized_values.hpp"
#include "gl_shim/state/query_values.hpp"

namespace glpt {

namespace {

// Integer colours map [-2^31, 2^31-1] linearly to [-1, 1] (spec 2.14.1), rounded as Mesa does;
// other integer parameters convert directly.
template <typename T>
float color_component(T v) {
  return normalized_component(v);
}
float plain_component(GLint v) { return static_cast<float>(v); }
float plain_component(GLfloat v) { return v; }
// An enum passed as a value, converted as Mesa does ((GLenum)(GLint) value). A float no GLint
// holds (NaN, infinities, beyond 2^31) names no enum; converting it would be undefined.
GLenum enum_component(GLint v) { return static_cast<GLenum>(v); }
GLenum enum_component(GLfloat v) {
  return std::isfinite(v) && std::fabs(v) < 2147483520.0f
             ? static_cast<GLenum>(static_cast<GLint>(v))
             : GLenum{0};
}

template <typename T>
glm::vec4 color4(const T* p) {
  return {color_component(p[0]), color_component(p[1]), color_component(p[2]),
          color_component(p[3])};
}
template <typename T>
glm::vec4 plain4(const T* p) {
  return {plain_component(p[0]), plain_component(p[1]), plain_component(p[2]),
          plain_component(p[3])};
}

rec::Light* light_of(Context& ctx, GLenum light) {
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + rec::kMaxLights) {
    record_error(ctx, GL_INVALID_ENUM);
    return nullptr;
  }
  return &ctx.lighting.lights[light - GL_LIGHT0];
}

// The scalar forms (glLightf, glLighti, glLightModelf, ...) pass (param, 0, 0, 0) to the vector
// form for every pname, vector ones included, without an error: what Mesa does (GL 1.5 only
// defines them for single-valued parameters, and programs rely on Mesa's leniency).
template <typename T>
void set_light(Context& ctx, GLenum light, GLenum pname, const T* p) {
  if (p == nullptr) return record_error(ctx, GL_INVALID_VALUE);
  rec::Light* l = light_of(ctx, light);
  if (!l) return;
  switch (pname) {
    case GL_AMBIENT:
      l->ambient = color4(p);
      break;
    case GL_DIFFUSE:
      l->diffuse = color4(p);
      break;
    case GL_SPECULAR:
      l->specular = color4(p);
      break;
    // Stored in eye space, transformed with Mesa's order of operations (bit-identical).
    case GL_POSITION:
      l->position = transform_point(ctx.matrices.modelview.top(), plain4(p));
      break;
    case GL_SPOT_DIRECTION: {
      // Mesa analyses the modelview here (which decides how later products are computed).
      MesaMatrix& mv = ctx.matrices.modelview.top_matrix();
      mv.analyse();
      l->spot_direction = transform_direction(
          glm::vec3(plain_component(p[0]), plain_component(p[1]), plain_component(p[2])),
          mv.matrix());
      break;
    }
    case GL_SPOT_EXPONENT: {
      const float v = plain_component(p[0]);
      if (!(v >= 0.0f && v <= 128.0f)) return record_error(ctx, GL_INVALID_VALUE);
      l->spot_exponent = v;
      break;
    }
    case GL_SPOT_CUTOFF: {
      const float v = plain_component(p[0]);
      if (!((v >= 0.0f && v <= 90.0f) || v == 180.0f)) return record_error(ctx, GL_INVALID_VALUE);
      l->spot_cutoff = v;
      break;
    }
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION: {
      const float v = plain_component(p[0]);
      if (!(v >= 0.0f)) return record_error(ctx, GL_INVALID_VALUE);
      (pname == GL_CONSTANT_ATTENUATION ? l->constant_attenuation
       : pname == GL_LINEAR_ATTENUATION ? l->linear_attenuation
                                        : l->quadratic_attenuation) = v;
      break;
    }
    default:
      return record_error(ctx, GL_INVALID_ENUM);
  }
}

template <typename T>
void set_light_model(Context& ctx, GLenum pname, const T* p) {
  if (p == nullptr) return record_error(ctx, GL_INVALID_VALUE);
  rec::LightingState& s = ctx.lighting;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:
      s.model_ambient = color4(p);
      break;
    case GL_LIGHT_MODEL_TWO_SIDE:
      s.two_side = plain_component(p[0]) != 0;
      break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER:
      s.local_viewer = plain_component(p[0]) != 0;
      break;
    case GL_LIGHT_MODEL_COLOR_CONTROL: {
      const GLenum v = enum_component(p[0]);
      if (v != GL_SINGLE_COLOR && v != GL_SEPARATE_SPECULAR_COLOR)
        return record_error(ctx, GL_INVALID_ENUM);
      s.separate_specular = v == GL_SEPARATE_SPECULAR_COLOR;
      break;
    }
    default:
      return record_error(ctx, GL_INVALID_ENUM);
  }
}

// Whether GL_COLOR_MATERIAL currently tracks `component` (GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR or
// GL_EMISSION) of face `side` (0 front, 1 back).
bool tracked_by_color_material(const rec::LightingState& l, int side, GLenum component) {
  if (!l.color_material) return false;
  if (l.color_material_face == (side == 0 ? GL_BACK : GL_FRONT)) return false;
  return l.color_material_mode == component ||
         (l.color_material_mode == GL_AMBIENT_AND_DIFFUSE &&
          (component == GL_AMBIENT || component == GL_DIFFUSE));
}

template <typename T>
void set_material(Context& ctx, GLenum face, GLenum pname, const T* p) {
  if (p == nullptr) return record_error(ctx, GL_INVALID_VALUE);
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
    return record_error(ctx, GL_INVALID_ENUM);
  auto apply = [&](rec::Material& m) -> bool {
    const int side = &m == &ctx.lighting.material[0] ? 0 : 1;
    // While GL_COLOR_MATERIAL tracks a component, glMaterial leaves it alone (Mesa's
    // _mesa_Materialfv skips the tracked bits): the current colour keeps its place.
    const auto set_color = [&](glm::vec4& field, GLenum component) {
      if (!tracked_by_color_material(ctx.lighting, side, component)) field = color4(p);
    };
    switch (pname) {
      case GL_AMBIENT:
        set_color(m.ambient, GL_AMBIENT);
        return true;
      case GL_DIFFUSE:
        set_color(m.diffuse, GL_DIFFUSE);
        return true;
      case GL_SPECULAR:
        set_color(m.specular, GL_SPECULAR);
        return true;
      case GL_EMISSION:
        set_color(m.emission, GL_EMISSION);
        return true;
      case GL_AMBIENT_AND_DIFFUSE:
        set_color(m.ambient, GL_AMBIENT);
        set_color(m.diffuse, GL_DIFFUSE);
        return true;
      case GL_SHININESS: {
        const float v = plain_component(p[0]);
        if (!(v >= 0.0f && v <= 128.0f)) {
          record_error(ctx, GL_INVALID_VALUE);
          return false;
        }
        m.shininess = v;
        return true;
      }
      case GL_COLOR_INDEXES: {
        // Only read back: glpt renders RGBA (colour-index lighting is never used).
        float* indexes = ctx.color_index.material_indexes[side];
        for (int i = 0; i < 3; ++i) indexes[i] = plain_component(p[i]);
        return true;
      }
      default:
        record_error(ctx, GL_INVALID_ENUM);
        return false;
    }
  };
  flush_color_material(ctx);  // a glColor before it, inside glBegin/glEnd
  bool ok = true;
  if (face != GL_BACK) ok = apply(ctx.lighting.material[0]);
  if (ok && face != GL_FRONT) ok = apply(ctx.lighting.material[1]);
  if (!ok) return;
  // The fields set, for the front face (material_field_bit's numbering); GL_COLOR_INDEXES is not
  // drawn.
  const uint32_t front_fields = pname == GL_AMBIENT_AND_DIFFUSE ? 0b00011u
                                : pname == GL_AMBIENT           ? 0b00001u
                                : pname == GL_DIFFUSE           ? 0b00010u
                                : pname == GL_SPECULAR          ? 0b00100u
                                : pname == GL_EMISSION          ? 0b01000u
                                : pname == GL_SHININESS         ? 0b10000u
                                                                : 0u;
  static_assert(material_field_bit(1, 0) == 1u << 5);
  uint32_t fields = 0;
  if (face != GL_BACK) fields |= front_fields;
  if (face != GL_FRONT) fields |= front_fields << 5;
  material_set_inside_begin_end(ctx, fields);
}

// An RGBA colour as glGet*fv (unchanged) or glGet*iv (GL 1.5 6.1.2: linearly mapped, 1.0 to the
// most positive integer) returns it.
void put_color(const float* v, GLfloat* out) { std::copy(v, v + 4, out); }
void put_color(const float* v, GLint* out) {
  for (int i = 0; i < 4; ++i) out[i] = query::color_to_int(v[i]);
}

template <typename T>
void get_light(Context& ctx, GLenum light, GLenum pname, T* out) {
  rec::Light* l = light_of(ctx, light);
  if (!l) return;
  // As Mesa: other values truncate toward zero when read as integers.
  auto put = [&](const float* v, int n) {
    for (int i = 0; i < n; ++i) out[i] = static_cast<T>(v[i]);
  };
  switch (pname) {
    case GL_AMBIENT:
      put_color(&l->ambient.x, out);
      break;
    case GL_DIFFUSE:
      put_color(&l->diffuse.x, out);
      break;
    case GL_SPECULAR:
      put_color(&l->specular.x, out);
      break;
    case GL_POSITION:
      put(&l->position.x, 4);
      break;
    case GL_SPOT_DIRECTION:
      put(&l->spot_direction.x, 3);
      break;
    case GL_SPOT_EXPONENT:
      put(&l->spot_exponent, 1);
      break;
    case GL_SPOT_CUTOFF:
      put(&l->spot_cutoff, 1);
      break;
    case GL_CONSTANT_ATTENUATION:
      put(&l->constant_attenuation, 1);
      break;
    case GL_LINEAR_ATTENUATION:
      put(&l->linear_attenuation, 1);
      break;
    case GL_QUADRATIC_ATTENUATION:
      put(&l->quadratic_attenuation, 1);
      break;
    default:
      record_error(ctx, GL_INVALID_ENUM);
  }
}

template <typename T>
void get_material(Context& ctx, GLenum face, GLenum pname, T* out) {
  if (face != GL_FRONT && face != GL_BACK) return record_error(ctx, GL_INVALID_ENUM);
  const int side = face == GL_FRONT ? 0 : 1;
  const rec::Material& m = ctx.lighting.material[side];
  // As Mesa: other values round to the nearest integer when read as integers.
  auto put = [&](const float* v, int n) {
    for (int i = 0; i < n; ++i) {
      if constexpr (std::is_integral_v<T>) {
        out[i] = query::round_to_int(v[i]);
      } else {
        out[i] = v[i];
      }
    }
  };
  switch (pname) {
    case GL_AMBIENT:
      put_color(&m.ambient.x, out);
      break;
    case GL_DIFFUSE:
      put_color(&m.diffuse.x, out);
      break;
    case GL_SPECULAR:
      put_color(&m.specular.x, out);
      break;
    case GL_EMISSION:
      put_color(&m.emission.x, out);
      break;
    case GL_SHININESS:
      put(&m.shininess, 1);
      break;
    case GL_COLOR_INDEXES:
      put(ctx.color_index.material_indexes[side], 3);
      break;
    default:
      record_error(ctx, GL_INVALID_ENUM);
  }
}

}  // namespace

namespace {

// GL_COLOR_MATERIAL (GL 1.5 2.14.3): the tracked fields of `side`'s material take `color`.
void track_color(rec::Material& m, const rec::LightingState& l, int side, const glm::vec4& color) {
  if (!l.color_material) return;
  const bool tracked =
      side == 0 ? l.color_material_face != GL_BACK : l.color_material_face != GL_FRONT;
  if (!tracked) return;
  switch (l.color_material_mode) {
    case GL_EMISSION:
      m.emission = color;
      break;
    case GL_AMBIENT:
      m.ambient = color;
      break;
    case GL_DIFFUSE:
      m.diffuse = color;
      break;
    case GL_SPECULAR:
      m.specular = color;
      break;
    default:  // GL_AMBIENT_AND_DIFFUSE
      m.ambient = m.diffuse = color;
      break;
  }
}

}  // namespace

rec::Material with_color_material(rec::Material m, const rec::LightingState& l, int side,
                                  const glm::vec4& color) {
  track_color(m, l, side, color);
  return m;
}

// Called for every glColor (in immediate mode for every vertex): the materials are updated in
// place, not copied through with_color_material.
void apply_color_material(Context& ctx) {
  rec::LightingState& l = ctx.lighting;
  if (!l.color_material) return;
  for (int side = 0; side < 2; ++side) track_color(l.material[side], l, side, ctx.current.color);
}

namespace impl {

void glLightf(Context& ctx, GLenum light, GLenum pname, GLfloat param) {
  const GLfloat p[4] = {param, 0.0f, 0.0f, 0.0f};
  set_light(ctx, light, pname, p);
}
void glLighti(Context& ctx, GLenum light, GLenum pname, GLint param) {
  const GLint p[4] = {param, 0, 0, 0};
  set_light(ctx, light, pname, p);
}
void glLightfv(Context& ctx, GLenum light, GLenum pname, const GLfloat* params) {
  set_light(ctx, light, pname, params);
}
void glLightiv(Context& ctx, GLenum light, GLenum pname, const GLint* params) {
  set_light(ctx, light, pname, params);
}
void glLightModelf(Context& ctx, GLenum pname, GLfloat param) {
  const GLfloat p[4] = {param, 0.0f, 0.0f, 0.0f};
  set_light_model(ctx, pname, p);
}
void glLightModeli(Context& ctx, GLenum pname, GLint param) {
  const GLint p[4] = {param, 0, 0, 0};
  set_light_model(ctx, pname, p);
}
void glLightModelfv(Context& ctx, GLenum pname, const GLfloat* params) {
  set_light_model(ctx, pname, params);
}
void glLightModeliv(Context& ctx, GLenum pname, const GLint* params) {
  set_light_model(ctx, pname, params);
}
// Mesa's glMaterialf and glMateriali hand the value, converted to float, to glMaterialfv as its
// first component; the other three are whatever its stack holds (glpt: zero).
void glMaterialf(Context& ctx, GLenum face, GLenum pname, GLfloat param) {
  const GLfloat p[4] = {param, 0.0f, 0.0f, 0.0f};
  set_material(ctx, face, pname, p);
}
void glMateriali(Context& ctx, GLenum face, GLenum pname, GLint param) {
  const GLfloat p[4] = {static_cast<GLfloat>(param), 0.0f, 0.0f, 0.0f};
  set_material(ctx, face, pname, p);
}
void glMaterialfv(Context& ctx, GLenum face, GLenum pname, const GLfloat* params) {
  set_material(ctx, face, pname, params);
}
void glMaterialiv(Context& ctx, GLenum face, GLenum pname, const GLint* params) {
  set_material(ctx, face, pname, params);
}
void glGetLightfv(Context& ctx, GLenum light, GLenum pname, GLfloat* params) {
  if (params) get_light(ctx, light, pname, params);
}
void glGetLightiv(Context& ctx, GLenum light, GLenum pname, GLint* params) {
  if (params) get_light(ctx, light, pname, params);
}
void glGetMaterialfv(Context& ctx, GLenum face, GLenum pname, GLfloat* params) {
  if (params) get_material(ctx, face, pname, params);
}
void glGetMaterialiv(Context& ctx, GLenum face, GLenum pname, GLint* params) {
  if (params) get_material(ctx, face, pname, params);
}

void glColorMaterial(Context& ctx, GLenum face, GLenum mode) {
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
    return record_error(ctx, GL_INVALID_ENUM);
  if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
      mode != GL_AMBIENT_AND_DIFFUSE)
    return record_error(ctx, GL_INVALID_ENUM);
  ctx.lighting.color_material_face = face;
  ctx.lighting.color_material_mode = mode;
  // While enabled, the newly tracked components take the current colour at once (as Mesa).
  apply_color_material(ctx);
}

void glShadeModel(Context& ctx, GLenum mode) {
  if (mode != GL_FLAT && mode != GL_SMOOTH) return record_error(ctx, GL_INVALID_ENUM);
  ctx.raster.primitive.shade_model = mode;
}

}  // namespace impl
}  // namespace glpt
