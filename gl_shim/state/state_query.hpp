// A glGet value before its conversion to the command's type (GL 1.5 6.1.2): shared by the query
// table in queries.cpp and the per-area tables it consults.
#pragma once

#include <initializer_list>

#include "gl_shim/gl_types.h"

namespace glpt {

class Context;

namespace query {

// How a value converts between the glGet variants (spec 6.1.2).
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

// Texturing and pixel-path state (gl_shim/textures/texture_queries.cpp); false for other pnames.
bool lookup_texture_and_pixel_state(const Context& ctx, GLenum pname, query::Value* out);

}  // namespace glpt
