// One state value as glGet* finds it, before conversion to the requested type (GL 1.5 spec
// 6.1.2). Shared by the lookups that answer glGet{Boolean,Integer,Float,Double}v: queries.cpp and
// the per-area lookups it consults (fixed_function_queries.cpp, ...).
#pragma once

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

}  // namespace query

// Rasterization, fog, per-fragment, current-attribute, clip and matrix state of GL 1.5 tables
// 6.5-6.34 and the related implementation limits (fixed_function_queries.cpp). False if
// `pname` is none of those.
bool lookup_fixed_function_state(const Context& ctx, GLenum pname, query::Value* out);

}  // namespace glpt
