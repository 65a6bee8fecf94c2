// Integer colour and normal components to float (GL 1.5 spec table 2.9: unsigned [0, 2^b - 1]
// maps to [0, 1], signed [-2^(b-1), 2^(b-1) - 1] maps to [-1, 1] as (2c + 1) / (2^b - 1)),
// evaluated exactly as Mesa evaluates it (main/macros.h UBYTE_TO_FLOAT ... INT_TO_FLOAT): partly
// in float and with a multiplied reciprocal, which rounds differently from an exact division in
// about half of the 8- and 16-bit values. Checked against OSMesa for every 8- and 16-bit value.
// Used wherever GL converts integer colours: glColor*, glSecondaryColor*, glNormal*, glLighti*,
// glMateriali*, glFogiv(GL_FOG_COLOR).
#pragma once

#include <array>

#include "gl_shim/gl_types.h"

namespace glpt {

inline float normalized_component(GLbyte v) {
  return (2.0f * static_cast<float>(v) + 1.0f) * (1.0f / 255.0f);
}
// c / 255.0f for every c, as a table (glColor*ub is called per vertex): compile-time float
// division rounds as the run-time one does.
inline constexpr std::array<float, 256> kUnsignedByteComponents = [] {
  std::array<float, 256> table{};
  for (int c = 0; c < 256; ++c) table[size_t(c)] = static_cast<float>(c) / 255.0f;
  return table;
}();
inline float normalized_component(GLubyte v) { return kUnsignedByteComponents[v]; }
inline float normalized_component(GLshort v) {
  return (2.0f * static_cast<float>(v) + 1.0f) * (1.0f / 65535.0f);
}
inline float normalized_component(GLushort v) { return static_cast<float>(v) * (1.0f / 65535.0f); }
// 32-bit values: the integer is first rounded to float (Mesa computes 2.0F * i + 1.0F), then
// scaled in double.
inline float normalized_component(GLint v) {
  return static_cast<float>(static_cast<double>(2.0f * static_cast<float>(v) + 1.0f) *
                            (1.0 / 4294967294.0));
}
inline float normalized_component(GLuint v) {
  return static_cast<float>(static_cast<double>(v) * (1.0 / 4294967295.0));
}
inline float normalized_component(GLfloat v) { return v; }
inline float normalized_component(GLdouble v) { return static_cast<float>(v); }

}  // namespace glpt
