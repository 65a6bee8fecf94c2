// The parameters of state-setting commands that come as floats or integers (glTexParameter,
// glTexEnv, ...), converted as Mesa converts them. (The other direction, for glGet*iv, is in
// query_values.hpp.)
#pragma once

#include <algorithm>
#include <cmath>

#include "gl_shim/gl_types.h"
#include "gl_shim/state/normalized_values.hpp"

namespace glpt {

// The parameters of a glFoo{f,i}[v] command, whichever form they came in (exactly one of `f`, `i`
// is set). Integer forms stay exact.
struct ParamValues {
  const GLfloat* f = nullptr;
  const GLint* i = nullptr;

  float as_float(int k) const { return f != nullptr ? f[k] : float(i[k]); }
  // Colours: integers map to [-1, 1].
  float as_color(int k) const { return f != nullptr ? f[k] : normalized_component(i[k]); }
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
