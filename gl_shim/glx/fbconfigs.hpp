// The framebuffer configurations glpt offers: every TrueColor visual of depth 24 or 32 on a
// screen, double- or single-buffered, RGB8 with or without 8 alpha bits (depth-32 visuals always
// have alpha), 24-bit depth and 8-bit stencil. A config without alpha behaves as GL specifies for
// such a drawable (alpha reads 1, destination alpha is 1).
//
// A GLXFBConfig handle encodes (visual id, alpha, double-buffered): configs need no registry,
// and a handle stays valid for the life of the display.
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

GLXFBConfig encode(const FBConfig& c);
bool decode(Display* dpy, GLXFBConfig handle, FBConfig* out);
std::vector<FBConfig> configs_of_screen(Display* dpy, int screen);

// The value of a GLX attribute for a config; false for an unknown attribute.
bool config_attribute(const FBConfig& c, int attribute, int* value);

// glXChooseFBConfig's order (GLX 1.4 section 3.3.3, as Mesa's fbconfig_compare): no alpha before
// alpha (Mesa prefers a zero component, then larger ones), then single- before double-buffered,
// then by visual. Stable, so equal configs keep their enumeration order.
void sort_for_choose(std::vector<FBConfig>& configs);

// GLX 1.4 section 3.3.3 matching of an attribute list (pairs, None-terminated) against a config.
bool config_matches(const FBConfig& c, const int* attrib_list);

// glXChooseVisual's older list format (boolean tokens without values), as FBConfig matching.
bool visual_list_matches(const FBConfig& c, const int* attrib_list);

}  // namespace glpt::glx
