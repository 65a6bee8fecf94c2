// Conversions between the float and integer forms of GL state values (GL 1.5 table 2.9, 6.1.2),
// as Mesa performs them.
#pragma once

#include <algorithm>
#include <cmath>

#include "gl_shim/gl_types.h"

namespace glpt {

// A signed integer colour component to [-1, 1]: (2c + 1) / (2^32 - 1) (Mesa's INT_TO_FLOAT).
inline float int_to_color(GLint v) { return float((2.0 * double(v) + 1.0) / 4294967295.0); }

// A colour (or another [0,1] value) for glGet*iv: trunc(c * (2^31 - 1)) (Mesa's FLOAT_TO_INT).
inline GLint color_to_int(float c) {
  return GLint(std::clamp(std::trunc(2147483647.0 * double(c)), -2147483648.0, 2147483647.0));
}

// A float state value for glGet*iv: rounded to nearest (Mesa's IROUND), saturated.
inline GLint float_to_int(float v) {
  if (std::isnan(v)) return 0;
  return GLint(std::clamp(std::round(double(v)), -2147483648.0, 2147483647.0));
}

// The parameters of a glFoo{f,i}[v] command, whichever form they came in (exactly one of `f`, `i`
// is set). Integer forms stay exact.
struct ParamValues {
  const GLfloat* f = nullptr;
  const GLint* i = nullptr;

  float as_float(int k) const { return f != nullptr ? f[k] : float(i[k]); }
  // Colours: integers map to [-1, 1].
  float as_color(int k) const { return f != nullptr ? f[k] : int_to_color(i[k]); }
  // Integer or enum state given as a float: rounded (Mesa's glTexParameterf) or truncated
  // (Mesa's glTexEnvf); out-of-range floats give a value no enum has.
  GLint as_int_rounded(int k) const { return f != nullptr ? saturate(std::round(f[k])) : i[k]; }
  GLint as_int_truncated(int k) const { return f != nullptr ? saturate(std::trunc(f[k])) : i[k]; }

 private:
  static GLint saturate(float v) {
    if (std::isnan(v)) return -1;
    return GLint(std::clamp(double(v), -2147483648.0, 2147483647.0));
  }
};

}  // namespace glpt
