// One state value as glGet* finds it, before conversion to the requested type (GL 1.5 spec
// 6.1.2). Shared by the lookups that answer glGet{Boolean,Integer,Float,Double}v: queries.cpp and
// the per-area lookups it consults (fixed_function_queries.cpp, ...).
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

namespace query {

// How a value converts between the glGet variants (spec 6.1.2): integers and enums as they are,
// floats rounded to the nearest integer, colours (and normals, depth values) mapped linearly
// from [-1, 1] to the whole integer range, booleans as 0/1.
enum class Kind { kInt, kFloat, kColor, kBool };

struct Value {
  Kind kind = Kind::kInt;
  int count = 0;
  double v[16] = {};
};

inline Value ints(std::initializer_list<double> l) {
  Value r;
  r.kind = Kind::kInt;
  for (double d : l) r.v[r.count++] = d;
  return r;
}
inline Value floats(const float* p, int n, Kind kind = Kind::kFloat) {
  Value r;
  r.kind = kind;
  r.count = n;
  for (int i = 0; i < n; ++i) r.v[i] = p[i];
  return r;
}
inline Value boolean(bool b) {
  Value r;
  r.kind = Kind::kBool;
  r.count = 1;
  r.v[0] = b ? 1 : 0;
  return r;
}

// A colour component, normal coordinate or depth value as an integer: Mesa's mapping,
// (2^31 - 1) * c truncated toward zero, so integer queries read what they read on Mesa. (The
// spec's -1.0 is the most negative integer, -2^31; Mesa's is -(2^31 - 1), and glpt's state is
// compared query for query with Mesa's.) Values beyond [-1, 1] saturate where Mesa's conversion
// overflows; NaN is 0.
inline GLint color_to_int(double c) {
  if (std::isnan(c)) return 0;
  if (c <= -1.0) return -2147483647;
  if (c >= 1.0) return 2147483647;
  return static_cast<GLint>(2147483647.0 * c);
}

// Any other value: rounded to the nearest integer (halfway cases away from zero), saturating.
inline GLint round_to_int(double v) {
  if (std::isnan(v)) return 0;
  return static_cast<GLint>(std::clamp(std::round(v), -2147483648.0, 2147483647.0));
}

}  // namespace query

// Rasterization, fog, per-fragment, current-attribute, clip and matrix state of GL 1.5 tables
// 6.5-6.34 and the related implementation limits (fixed_function_queries.cpp). False if
// `pname` is none of those.
bool lookup_fixed_function_state(const Context& ctx, GLenum pname, query::Value* out);

// Vertex arrays, buffer bindings, attribute stacks and hints (GL 1.5 tables 6.6-6.8, 6.27, 6.31;
// arrays/array_queries.cpp). False if `pname` is none of those.
bool lookup_array_state(const Context& ctx, GLenum pname, query::Value* out);

// Texture bindings and limits, pixel store modes of 3-D images, pixel transfer, pixel maps and
// zoom (gl_shim/textures/texture_queries.cpp). False if `pname` is none of those.
bool lookup_texture_and_pixel_state(const Context& ctx, GLenum pname, query::Value* out);

// Render mode, name stack, selection and feedback buffers (GL 1.5 table 6.31;
// gl_shim/render_modes/render_mode_commands.cpp). False if `pname` is none of those.
bool lookup_render_mode_state(const Context& ctx, GLenum pname, query::Value* out);

// The evaluator grids of GL 1.5 table 6.25 (gl_shim/evaluators/evaluator_commands.cpp). False if
// `pname` is none of those.
bool lookup_evaluator_state(const Context& ctx, GLenum pname, query::Value* out);

}  // namespace glpt
