// Point, line and polygon rasterization state (GL 1.5 spec 3.3-3.5): glPointSize,
// glPointParameter*, glLineWidth, glLineStipple, glPolygonMode, glPolygonOffset. The live state
// is ctx.raster.primitive (rec::PrimitiveState). Sizes are stored as given; the implementation's
// ranges (implementation_limits.hpp) apply when they are used.
#include <algorithm>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

// GL_INVALID_VALUE for "not greater than zero"; NaN is rejected too (it is not greater).
bool positive(float v) { return v > 0.0f; }
bool non_negative(float v) { return v >= 0.0f; }

// glPointParameter{f,i}v. `values` holds 3 values for GL_POINT_DISTANCE_ATTENUATION, 1 else.
// Like Mesa, the scalar forms accept GL_POINT_DISTANCE_ATTENUATION with (param, 0, 0).
void point_parameter(Context& ctx, GLenum pname, const float* values) {
  rec::PrimitiveState& p = ctx.raster.primitive;
  switch (pname) {
    case GL_POINT_SIZE_MIN:
    case GL_POINT_SIZE_MAX:
    case GL_POINT_FADE_THRESHOLD_SIZE:
      if (!non_negative(values[0])) return record_error(ctx, GL_INVALID_VALUE);
      (pname == GL_POINT_SIZE_MIN   ? p.point_size_min
       : pname == GL_POINT_SIZE_MAX ? p.point_size_max
                                    : p.point_fade_threshold) = values[0];
      return;
    case GL_POINT_DISTANCE_ATTENUATION:
      p.point_distance_attenuation = {values[0], values[1], values[2]};
      return;
    case GL_POINT_SPRITE_COORD_ORIGIN: {
      const GLenum origin = values[0] >= 0.0f && values[0] < 4.0e9f ? GLenum(values[0]) : 0u;
      if (origin != GL_LOWER_LEFT && origin != GL_UPPER_LEFT)
        return record_error(ctx, GL_INVALID_VALUE);  // as Mesa: a value, not an enum, error
      p.point_sprite_coord_origin = origin;
      return;
    }
    default:
      record_error(ctx, GL_INVALID_ENUM);
  }
}

template <typename T>
void point_parameter_vector(Context& ctx, GLenum pname, const T* params) {
  if (params == nullptr) return;  // undefined in GL; ignored
  float v[3] = {static_cast<float>(params[0]), 0.0f, 0.0f};
  if (pname == GL_POINT_DISTANCE_ATTENUATION) {
    v[1] = static_cast<float>(params[1]);
    v[2] = static_cast<float>(params[2]);
  }
  point_parameter(ctx, pname, v);
}

}  // namespace

namespace impl {

void glPointSize(Context& ctx, GLfloat size) {
  if (!positive(size)) return record_error(ctx, GL_INVALID_VALUE);
  ctx.raster.primitive.point_size = size;
}

void glPointParameterf(Context& ctx, GLenum pname, GLfloat param) {
  const float v[3] = {param, 0.0f, 0.0f};
  point_parameter(ctx, pname, v);
}
void glPointParameterfv(Context& ctx, GLenum pname, const GLfloat* params) {
  point_parameter_vector(ctx, pname, params);
}
void glPointParameteri(Context& ctx, GLenum pname, GLint param) {
  const float v[3] = {static_cast<float>(param), 0.0f, 0.0f};
  point_parameter(ctx, pname, v);
}
void glPointParameteriv(Context& ctx, GLenum pname, const GLint* params) {
  point_parameter_vector(ctx, pname, params);
}

void glLineWidth(Context& ctx, GLfloat width) {
  if (!positive(width)) return record_error(ctx, GL_INVALID_VALUE);
  ctx.raster.primitive.line_width = width;
}

void glLineStipple(Context& ctx, GLint factor, GLushort pattern) {
  ctx.raster.primitive.line_stipple_factor = std::clamp(factor, 1, 256);
  ctx.raster.primitive.line_stipple_pattern = pattern;
}

void glPolygonMode(Context& ctx, GLenum face, GLenum mode) {
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
    return record_error(ctx, GL_INVALID_ENUM);
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL)
    return record_error(ctx, GL_INVALID_ENUM);
  if (face != GL_BACK) ctx.raster.primitive.polygon_mode_front = mode;
  if (face != GL_FRONT) ctx.raster.primitive.polygon_mode_back = mode;
}

void glPolygonOffset(Context& ctx, GLfloat factor, GLfloat units) {
  ctx.raster.primitive.offset_factor = factor;
  ctx.raster.primitive.offset_units = units;
}

}  // namespace impl
}  // namespace glpt
