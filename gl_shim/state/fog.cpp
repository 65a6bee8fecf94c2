// glFog{f,i}{,v} (GL 1.5 spec 3.10). The live state is ctx.raster.fog (rec::FogState); the fog
// index (colour-index mode) is kept for queries only.
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/normalized_values.hpp"

namespace glpt {
namespace {

float clamp01(float v) { return v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v); }

// An enum passed as a float parameter, converted as Mesa does ((GLenum)(GLint) value).
GLenum enum_value(float v) {
  return std::isfinite(v) && std::fabs(v) < 2147483520.0f
             ? static_cast<GLenum>(static_cast<GLint>(v))
             : GLenum{0};
}

// `values`: 4 floats (the colour, already converted), only the first used for other pnames.
void set_fog(Context& ctx, GLenum pname, const float* values) {
  rec::FogState& fog = ctx.raster.fog;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum mode = enum_value(values[0]);
      if (mode != GL_LINEAR && mode != GL_EXP && mode != GL_EXP2)
        return record_error(ctx, GL_INVALID_ENUM);
      fog.mode = mode;
      return;
    }
    case GL_FOG_DENSITY:
      if (!(values[0] >= 0.0f)) return record_error(ctx, GL_INVALID_VALUE);
      fog.density = values[0];
      return;
    case GL_FOG_START:
      fog.start = values[0];
      return;
    case GL_FOG_END:
      fog.end = values[0];
      return;
    case GL_FOG_INDEX:
      ctx.color_index.fog_index = values[0];
      return;
    case GL_FOG_COLOR:
      fog.color = {clamp01(values[0]), clamp01(values[1]), clamp01(values[2]), clamp01(values[3])};
      return;
    case GL_FOG_COORDINATE_SOURCE: {
      const GLenum source = enum_value(values[0]);
      if (source != GL_FOG_COORDINATE && source != GL_FRAGMENT_DEPTH)
        return record_error(ctx, GL_INVALID_ENUM);
      fog.coord_source = source;
      return;
    }
    default:
      record_error(ctx, GL_INVALID_ENUM);
  }
}

// The scalar forms are the vector forms with (param, 0, 0, 0), as in Mesa: GL_FOG_COLOR is
// accepted there too.
void fog_floats(Context& ctx, GLenum pname, const GLfloat* params) {
  if (params == nullptr) return;  // undefined in GL; ignored
  float v[4] = {params[0], 0.0f, 0.0f, 0.0f};
  if (pname == GL_FOG_COLOR)
    for (int i = 1; i < 4; ++i) v[i] = params[i];
  set_fog(ctx, pname, v);
}

// Integer colours are normalized (table 2.9); other integer parameters convert directly.
void fog_ints(Context& ctx, GLenum pname, const GLint* params) {
  if (params == nullptr) return;
  float v[4] = {};
  if (pname == GL_FOG_COLOR) {
    for (int i = 0; i < 4; ++i) v[i] = normalized_component(params[i]);
  } else {
    v[0] = static_cast<float>(params[0]);
  }
  set_fog(ctx, pname, v);
}

}  // namespace

namespace impl {

void glFogf(Context& ctx, GLenum pname, GLfloat param) {
  const GLfloat p[4] = {param, 0.0f, 0.0f, 0.0f};
  fog_floats(ctx, pname, p);
}
void glFogfv(Context& ctx, GLenum pname, const GLfloat* params) { fog_floats(ctx, pname, params); }
// As in Mesa, the scalar integer form converts its value directly, even for GL_FOG_COLOR.
void glFogi(Context& ctx, GLenum pname, GLint param) {
  const GLfloat p[4] = {static_cast<float>(param), 0.0f, 0.0f, 0.0f};
  fog_floats(ctx, pname, p);
}
void glFogiv(Context& ctx, GLenum pname, const GLint* params) { fog_ints(ctx, pname, params); }

}  // namespace impl
}  // namespace glpt
