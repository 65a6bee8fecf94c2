// The current raster position (GL 1.5 2.13, GL 1.4 2.13 "WindowPos"): where glBitmap,
// glDrawPixels and glCopyPixels draw, with the colour, secondary colour, texture coordinates and
// distance their fragments take. glRasterPos* and glWindowPos* (raster_position.cpp) set it; it
// lives in Context::raster_position.
#pragma once

#include <glm/glm.hpp>

#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;

// GL's initial raster position (GL 1.5 table 6.9): (0, 0, 0, 1), valid, white, texture
// coordinates (0, 0, 0, 1), distance 0.
inline rec::RasterPosition initial_raster_position() {
  rec::RasterPosition p;
  p.window = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  p.valid = true;
  p.distance = 0.0f;
  p.color = glm::vec4(1.0f);
  p.secondary_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  p.tex_coord.fill(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  return p;
}

// glRasterPos4f: `object` through the modelview and projection, clipped, through the viewport;
// the raster colour lit when lighting is on. Mesa's arithmetic (src/mesa/main/rastpos.c).
void set_raster_position(Context& ctx, const glm::vec4& object);

// glWindowPos3f: window coordinates directly (z through the depth range), current colours.
void set_window_position(Context& ctx, float x, float y, float z);

}  // namespace glpt
