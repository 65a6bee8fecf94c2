// Framebuffer-related state: viewport, clear values, pixel storage (GL 1.5 spec 2.11.1, 4.2, 4.3).
#pragma once

#include <glm/glm.hpp>

#include "gl_shim/gl_types.h"

namespace glpt {

struct PixelStoreModes {
  GLint row_length = 0, skip_rows = 0, skip_pixels = 0, alignment = 4;
  GLint image_height = 0, skip_images = 0;
  bool swap_bytes = false, lsb_first = false;
};

struct FramebufferState {
  GLint viewport_x = 0, viewport_y = 0;
  GLsizei viewport_width = 0, viewport_height = 0;
  bool viewport_initialized = false;  // set to the drawable size on first make-current
  glm::vec4 clear_color{0.0f};
  GLdouble clear_depth = 1.0;
  GLint clear_stencil = 0;
  glm::vec4 clear_accum{0.0f};  // glClearAccum, clamped to [-1, 1]
  // glSampleCoverage (GL 1.5 4.1.3). glpt's drawables have no multisample buffer, so these only
  // read back.
  float sample_coverage_value = 1.0f;  // clamped to [0, 1]
  bool sample_coverage_invert = false;
  GLdouble depth_near = 0.0, depth_far = 1.0;
  PixelStoreModes pack, unpack;
};

}  // namespace glpt
