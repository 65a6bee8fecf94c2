// The framebuffer configurations glpt offers: every TrueColor visual of depth 24 or 32 on a
// screen, double- or single-buffered, RGBA8 with 24-bit depth and 8-bit stencil (the path
// tracer makes its own images, so these only describe what the program may assume).
//
// A GLXFBConfig handle encodes (visual id, double-buffered): configs need no registry, and a
// handle stays valid for the life of the display.
#pragma once

#include <vector>

#include "gl_shim/glx/glx_types.hpp"

namespace glpt::glx {

struct FBConfig {
  VisualID visual = 0;
  int screen = 0;
  int depth = 24;  // of the X visual
  bool double_buffered = true;
};

GLXFBConfig encode(const FBConfig& c);
bool decode(Display* dpy, GLXFBConfig handle, FBConfig* out);
std::vector<FBConfig> configs_of_screen(Display* dpy, int screen);

// The value of a GLX attribute for a config; false for an unknown attribute.
bool config_attribute(const FBConfig& c, int attribute, int* value);

// GLX 1.4 section 3.3.3 matching of an attribute list (pairs, None-terminated) against a config.
bool config_matches(const FBConfig& c, const int* attrib_list);

// glXChooseVisual's older list format (boolean tokens without values), as FBConfig matching.
bool visual_list_matches(const FBConfig& c, const int* attrib_list);

}  // namespace glpt::glx
