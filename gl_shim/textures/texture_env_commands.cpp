// Per-unit texture state: glActiveTexture, glClientActiveTexture (GL 1.5 2.7, 3.8.15),
// glTexEnv* / glGetTexEnv* (3.8.13, 6.1.3) and glTexGen* / glGetTexGen* (2.11.4).
#include <algorithm>
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/mesa_matrix.hpp"
#include "gl_shim/state/query_values.hpp"
#include "gl_shim/state/value_conversions.hpp"

namespace glpt {
namespace {

bool valid_unit_enum(GLenum texture) {
  return texture >= GL_TEXTURE0 && texture < GL_TEXTURE0 + rec::kMaxTextureUnits;
}

// ---- texture environment -------------------------------------------------------------------

bool valid_env_mode(GLenum m) {
  switch (m) {
    case GL_MODULATE:
    case GL_DECAL:
    case GL_BLEND:
    case GL_REPLACE:
    case GL_ADD:
    case GL_COMBINE:
      return true;
    default:
      return false;
  }
}

bool valid_combine(GLenum f, bool rgb) {
  switch (f) {
    case GL_REPLACE:
    case GL_MODULATE:
    case GL_ADD:
    case GL_ADD_SIGNED:
    case GL_INTERPOLATE:
    case GL_SUBTRACT:
      return true;
    // ARB_texture_env_dot3 (GL 1.3) and its EXT ancestor, which Mesa also accepts.
    case GL_DOT3_RGB:
    case GL_DOT3_RGBA:
    case GL_DOT3_RGB_EXT:
    case GL_DOT3_RGBA_EXT:
      return rgb;
    default:
      return false;
  }
}

bool valid_source(GLenum s) {
  switch (s) {
    case GL_TEXTURE:
    case GL_CONSTANT:
    case GL_PRIMARY_COLOR:
    case GL_PREVIOUS:
      return true;
    default:  // GL 1.4 (ARB_texture_env_crossbar): GL_TEXTUREi of any unit
      return valid_unit_enum(s);
  }
}

bool valid_operand(GLenum o, bool rgb) {
  switch (o) {
    case GL_SRC_ALPHA:
    case GL_ONE_MINUS_SRC_ALPHA:
      return true;
    case GL_SRC_COLOR:
    case GL_ONE_MINUS_SRC_COLOR:
      return rgb;
    default:
      return false;
  }
}

// The field an enum-valued GL_TEXTURE_ENV parameter lives in, with its validation.
struct EnvEnumField {
  uint32_t* field = nullptr;
  bool (*valid)(GLenum) = nullptr;
};

EnvEnumField env_enum_field(rec::TexEnv& env, GLenum pname) {
  static constexpr auto mode = [](GLenum v) { return valid_env_mode(v); };
  static constexpr auto combine_rgb = [](GLenum v) { return valid_combine(v, true); };
  static constexpr auto combine_alpha = [](GLenum v) { return valid_combine(v, false); };
  static constexpr auto source = [](GLenum v) { return valid_source(v); };
  static constexpr auto operand_rgb = [](GLenum v) { return valid_operand(v, true); };
  static constexpr auto operand_alpha = [](GLenum v) { return valid_operand(v, false); };
  switch (pname) {
    case GL_TEXTURE_ENV_MODE:
      return {&env.mode, mode};
    case GL_COMBINE_RGB:
      return {&env.combine_rgb, combine_rgb};
    case GL_COMBINE_ALPHA:
      return {&env.combine_alpha, combine_alpha};
    case GL_SOURCE0_RGB:
    case GL_SOURCE1_RGB:
    case GL_SOURCE2_RGB:
      return {&env.source_rgb[pname - GL_SOURCE0_RGB], source};
    case GL_SOURCE0_ALPHA:
    case GL_SOURCE1_ALPHA:
    case GL_SOURCE2_ALPHA:
      return {&env.source_alpha[pname - GL_SOURCE0_ALPHA], source};
    case GL_OPERAND0_RGB:
    case GL_OPERAND1_RGB:
    case GL_OPERAND2_RGB:
      return {&env.operand_rgb[pname - GL_OPERAND0_RGB], operand_rgb};
    case GL_OPERAND0_ALPHA:
    case GL_OPERAND1_ALPHA:
    case GL_OPERAND2_ALPHA:
      return {&env.operand_alpha[pname - GL_OPERAND0_ALPHA], operand_alpha};
    default:
      return {};
  }
}

float* env_scale_field(rec::TexEnv& env, GLenum pname) {
  if (pname == GL_RGB_SCALE) return &env.rgb_scale;
  if (pname == GL_ALPHA_SCALE) return &env.alpha_scale;
  return nullptr;
}

// ARB_point_sprite: glTexEnv(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE / GL_FALSE) for the
// active unit. Mesa keeps the bits as point state; any other value is GL_INVALID_VALUE there.
void point_sprite_env(Context& ctx, GLenum pname, const ParamValues& p) {
  if (pname != GL_COORD_REPLACE) return record_error(ctx, GL_INVALID_ENUM);
  const GLint value = p.as_int_truncated(0);
  if (value != GL_TRUE && value != GL_FALSE) return record_error(ctx, GL_INVALID_VALUE);
  uint8_t& bits = ctx.raster.primitive.point_coord_replace;
  const auto bit = static_cast<uint8_t>(1u << ctx.textures.active);
  bits = value == GL_TRUE ? uint8_t(bits | bit) : uint8_t(bits & ~bit);
}

void tex_env(Context& ctx, GLenum target, GLenum pname, const ParamValues& p, bool vector) {
  if (target == GL_POINT_SPRITE) return point_sprite_env(ctx, pname, p);
  rec::TexEnv& env = ctx.textures.active_unit().env;
  if (target == GL_TEXTURE_FILTER_CONTROL) {
    if (pname != GL_TEXTURE_LOD_BIAS) return record_error(ctx, GL_INVALID_ENUM);
    env.lod_bias = p.as_float(0);
    return;
  }
  if (target != GL_TEXTURE_ENV) return record_error(ctx, GL_INVALID_ENUM);
  if (pname == GL_TEXTURE_ENV_COLOR) {
    // The scalar forms give (param, 0, 0, 0), without an error, as Mesa does.
    for (int c = 0; c < 4; ++c) {
      env.color[c] = c == 0 || vector ? std::clamp(p.as_color(c), 0.0f, 1.0f) : 0.0f;
    }
    return;
  }
  if (float* scale = env_scale_field(env, pname)) {
    const float s = p.as_float(0);
    if (s != 1.0f && s != 2.0f && s != 4.0f) return record_error(ctx, GL_INVALID_VALUE);
    *scale = s;
    return;
  }
  const EnvEnumField f = env_enum_field(env, pname);
  if (f.field == nullptr) return record_error(ctx, GL_INVALID_ENUM);
  const GLenum v = GLenum(p.as_int_truncated(0));
  if (!f.valid(v)) return record_error(ctx, GL_INVALID_ENUM);
  *f.field = v;
}

// Writes the value(s) of a glGetTexEnv query through `put(index, value, is_color)`; false for a
// bad target or pname (GL_INVALID_ENUM recorded).
template <typename Put>
bool get_tex_env(Context& ctx, GLenum target, GLenum pname, Put&& put) {
  rec::TexEnv& env = ctx.textures.active_unit().env;
  if (target == GL_TEXTURE_FILTER_CONTROL && pname == GL_TEXTURE_LOD_BIAS) {
    put(0, env.lod_bias, false);
    return true;
  }
  if (target == GL_POINT_SPRITE) {
    if (pname != GL_COORD_REPLACE) {
      record_error(ctx, GL_INVALID_ENUM);
      return false;
    }
    put(0, (ctx.raster.primitive.point_coord_replace >> ctx.textures.active) & 1u ? 1.0f : 0.0f,
        false);
    return true;
  }
  if (target != GL_TEXTURE_ENV) {
    record_error(ctx, GL_INVALID_ENUM);
    return false;
  }
  if (pname == GL_TEXTURE_ENV_COLOR) {
    for (int c = 0; c < 4; ++c) put(c, env.color[c], true);
    return true;
  }
  if (const float* scale = env_scale_field(env, pname)) {
    put(0, *scale, false);
    return true;
  }
  const EnvEnumField f = env_enum_field(env, pname);
  if (f.field == nullptr) {
    record_error(ctx, GL_INVALID_ENUM);
    return false;
  }
  put(0, float(*f.field), false);
  return true;
}

// ---- texture coordinate generation ---------------------------------------------------------

int texgen_coord(GLenum coord) {
  if (coord < GL_S || coord > GL_Q) return -1;
  return int(coord - GL_S);
}

bool valid_texgen_mode(int coord, GLenum mode) {
  switch (mode) {
    case GL_OBJECT_LINEAR:
    case GL_EYE_LINEAR:
      return true;
    case GL_SPHERE_MAP:
      return coord <= 1;  // S and T only
    case GL_REFLECTION_MAP:
    case GL_NORMAL_MAP:
      return coord <= 2;  // not Q
    default:
      return false;
  }
}

template <typename T>
void tex_gen(Context& ctx, GLenum coord, GLenum pname, const T* params, bool vector) {
  const int c = texgen_coord(coord);
  if (c < 0) return record_error(ctx, GL_INVALID_ENUM);
  if (params == nullptr) return;
  rec::TexGen& gen = ctx.textures.active_unit().texgen[size_t(c)];
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
      const double m = double(params[0]);
      const GLenum mode = std::isfinite(m) && std::fabs(m) < 4.0e9 ? GLenum(int64_t(m)) : 0u;
      if (!valid_texgen_mode(c, mode)) return record_error(ctx, GL_INVALID_ENUM);
      gen.mode = mode;
      return;
    }
    case GL_OBJECT_PLANE:
    case GL_EYE_PLANE: {
      // The scalar forms give the plane (param, 0, 0, 0), without an error, as Mesa does.
      const glm::vec4 plane =
          vector ? glm::vec4(float(params[0]), float(params[1]), float(params[2]), float(params[3]))
                 : glm::vec4(float(params[0]), 0.0f, 0.0f, 0.0f);
      if (pname == GL_OBJECT_PLANE) {
        gen.object_plane = plane;
      } else {
        // Stored in eye space: the plane times the inverse of the modelview current now,
        // computed as Mesa does (its inverse, its row-vector product).
        gen.eye_plane = transform_row_vector(plane, ctx.matrices.modelview.top_matrix().inverse());
      }
      return;
    }
    default:
      record_error(ctx, GL_INVALID_ENUM);
  }
}

template <typename T>
void get_tex_gen(Context& ctx, GLenum coord, GLenum pname, T* params) {
  const int c = texgen_coord(coord);
  if (c < 0) return record_error(ctx, GL_INVALID_ENUM);
  const rec::TexGen& gen = ctx.textures.active_unit().texgen[size_t(c)];
  const glm::vec4* plane = nullptr;
  switch (pname) {
    case GL_TEXTURE_GEN_MODE:
      if (params != nullptr) params[0] = T(gen.mode);
      return;
    case GL_OBJECT_PLANE:
      plane = &gen.object_plane;
      break;
    case GL_EYE_PLANE:
      plane = &gen.eye_plane;
      break;
    default:
      return record_error(ctx, GL_INVALID_ENUM);
  }
  if (params == nullptr) return;
  for (int k = 0; k < 4; ++k) {
    if constexpr (std::is_same_v<T, GLint>) {
      // Truncated, as Mesa does.
      params[k] = GLint(std::clamp(std::trunc(double((*plane)[k])), -2147483648.0, 2147483647.0));
    } else {
      params[k] = T((*plane)[k]);
    }
  }
}

}  // namespace

namespace impl {

void glActiveTexture(Context& ctx, GLenum texture) {
  if (!valid_unit_enum(texture)) return record_error(ctx, GL_INVALID_ENUM);
  ctx.textures.active = texture - GL_TEXTURE0;
}

void glClientActiveTexture(Context& ctx, GLenum texture) {
  if (!valid_unit_enum(texture)) return record_error(ctx, GL_INVALID_ENUM);
  ctx.textures.client_active = texture - GL_TEXTURE0;
}

void glTexEnvf(Context& ctx, GLenum target, GLenum pname, GLfloat param) {
  tex_env(ctx, target, pname, ParamValues{&param, nullptr}, false);
}
void glTexEnvi(Context& ctx, GLenum target, GLenum pname, GLint param) {
  tex_env(ctx, target, pname, ParamValues{nullptr, &param}, false);
}
void glTexEnvfv(Context& ctx, GLenum target, GLenum pname, const GLfloat* params) {
  if (params == nullptr) return;
  tex_env(ctx, target, pname, ParamValues{params, nullptr}, true);
}
void glTexEnviv(Context& ctx, GLenum target, GLenum pname, const GLint* params) {
  if (params == nullptr) return;
  tex_env(ctx, target, pname, ParamValues{nullptr, params}, true);
}

void glGetTexEnvfv(Context& ctx, GLenum target, GLenum pname, GLfloat* params) {
  float out[4];
  int n = 0;
  if (!get_tex_env(ctx, target, pname, [&](int k, float v, bool) { out[k] = v, n = k + 1; }))
    return;
  if (params != nullptr) std::copy(out, out + n, params);
}

void glGetTexEnviv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  GLint out[4];
  int n = 0;
  const bool ok = get_tex_env(ctx, target, pname, [&](int k, float v, bool color) {
    out[k] = color ? query::color_to_int(v) : GLint(std::lround(v));
    n = k + 1;
  });
  if (ok && params != nullptr) std::copy(out, out + n, params);
}

void glTexGeni(Context& ctx, GLenum coord, GLenum pname, GLint param) {
  tex_gen(ctx, coord, pname, &param, false);
}
void glTexGenf(Context& ctx, GLenum coord, GLenum pname, GLfloat param) {
  tex_gen(ctx, coord, pname, &param, false);
}
void glTexGend(Context& ctx, GLenum coord, GLenum pname, GLdouble param) {
  tex_gen(ctx, coord, pname, &param, false);
}
void glTexGeniv(Context& ctx, GLenum coord, GLenum pname, const GLint* params) {
  tex_gen(ctx, coord, pname, params, true);
}
void glTexGenfv(Context& ctx, GLenum coord, GLenum pname, const GLfloat* params) {
  tex_gen(ctx, coord, pname, params, true);
}
void glTexGendv(Context& ctx, GLenum coord, GLenum pname, const GLdouble* params) {
  tex_gen(ctx, coord, pname, params, true);
}

void glGetTexGeniv(Context& ctx, GLenum coord, GLenum pname, GLint* params) {
  get_tex_gen(ctx, coord, pname, params);
}
void glGetTexGenfv(Context& ctx, GLenum coord, GLenum pname, GLfloat* params) {
  get_tex_gen(ctx, coord, pname, params);
}
void glGetTexGendv(Context& ctx, GLenum coord, GLenum pname, GLdouble* params) {
  get_tex_gen(ctx, coord, pname, params);
}

}  // namespace impl
}  // namespace glpt
