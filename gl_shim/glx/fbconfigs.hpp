// glpt's own framebuffer configuration model, for EGL and for X servers without GLX (GLX otherwise
// reports the server's configs, glx_configs.hpp): every TrueColor visual of depth 24 or 32 on a
// screen, double- or single-buffered, RGB8 with or without 8 alpha bits (depth-32 visuals always
// have alpha), 24-bit depth and 8-bit stencil. A config without alpha behaves as GL specifies for
// such a drawable (alpha reads 1, destination alpha is 1).
#pragma once

#include <vector>

#include "gl_shim/glx/glx_types.hpp"

namespace glpt::glx {

struct FBConfig {
  VisualID visual = 0;
  int screen = 0;
  int depth = 24;  // of the X visual
  bool double_buffered = true;
  bool alpha = true;  // 8 alpha bits; false: none
};

// The configs of `screen`, double-buffered ones first.
std::vector<FBConfig> configs_of_screen(Display* dpy, int screen);

}  // namespace glpt::glx
