// Colour-index state (GL 1.5 spec 3.10 fog index, 4.2.2 IndexMask, 4.2.3 ClearIndex). glpt
// renders in RGBA only; programs may still set these, and they read back as set.
#pragma once

#include "gl_shim/gl_types.h"

namespace glpt {

struct ColorIndexState {
  GLuint write_mask = ~0u;  // glIndexMask
  GLint clear_index = 0;    // glClearIndex, truncated to an integer as Mesa stores it
  float fog_index = 0.0f;   // glFog(GL_FOG_INDEX)
  // glMaterial(GL_COLOR_INDEXES): ambient, diffuse and specular indexes of the front and back
  // materials (GL 1.5 table 6.12; part of GL_LIGHTING_BIT).
  float material_indexes[2][3] = {{0, 1, 1}, {0, 1, 1}};
};

}  // namespace glpt
