#include "gl_shim/glx/fbconfigs.hpp"

#include <algorithm>
#include <cstdint>

#include "gl/glx_enums.h"

namespace glpt::glx {

GLXFBConfig encode(const FBConfig& c) {
  return reinterpret_cast<GLXFBConfig>((static_cast<uintptr_t>(c.visual) << 2) | (c.alpha ? 2 : 0) |
                                       (c.double_buffered ? 1 : 0));
}

bool decode(Display* dpy, GLXFBConfig handle, FBConfig* out) {
  if (handle == nullptr || dpy == nullptr) return false;
  const auto bits = reinterpret_cast<uintptr_t>(handle);
  XVisualInfo templ{};
  templ.visualid = static_cast<VisualID>(bits >> 2);
  int n = 0;
  XVisualInfo* vi = XGetVisualInfo(dpy, VisualIDMask, &templ, &n);
  if (vi == nullptr || n == 0) return false;
  const bool alpha = (bits & 2) != 0;
  const bool ok = vi->c_class == TrueColor && (vi->depth == 24 || (vi->depth == 32 && alpha));
  if (ok) *out = FBConfig{vi->visualid, vi->screen, vi->depth, (bits & 1) != 0, alpha};
  XFree(vi);
  return ok;
}

std::vector<FBConfig> configs_of_screen(Display* dpy, int screen) {
  std::vector<FBConfig> out;
  XVisualInfo templ{};
  templ.screen = screen;
  templ.c_class = TrueColor;
  int n = 0;
  XVisualInfo* vi = XGetVisualInfo(dpy, VisualScreenMask | VisualClassMask, &templ, &n);
  if (vi == nullptr) return out;
  // Double-buffered configs first: that is what GL programs want.
  for (bool db : {true, false})
    for (bool alpha : {true, false})
      for (int i = 0; i < n; ++i)
        if (vi[i].depth == 24 || (vi[i].depth == 32 && alpha))
          out.push_back(FBConfig{vi[i].visualid, screen, vi[i].depth, db, alpha});
  XFree(vi);
  return out;
}

bool config_attribute(const FBConfig& c, int attribute, int* value) {
  int v = 0;
  switch (attribute) {
    case GLX_USE_GL:
      v = 1;
      break;
    case GLX_BUFFER_SIZE:
      v = c.alpha ? 32 : 24;
      break;
    case GLX_LEVEL:
      v = 0;
      break;
    case GLX_RGBA:
      v = 1;
      break;
    case GLX_DOUBLEBUFFER:
      v = c.double_buffered;
      break;
    case GLX_STEREO:
      v = 0;
      break;
    case GLX_AUX_BUFFERS:
      v = 0;
      break;
    case GLX_RED_SIZE:
    case GLX_GREEN_SIZE:
    case GLX_BLUE_SIZE:
      v = 8;
      break;
    case GLX_ALPHA_SIZE:
      v = c.alpha ? 8 : 0;
      break;
    case GLX_DEPTH_SIZE:
      v = 24;
      break;
    case GLX_STENCIL_SIZE:
      v = 8;
      break;
    case GLX_ACCUM_RED_SIZE:
    case GLX_ACCUM_GREEN_SIZE:
    case GLX_ACCUM_BLUE_SIZE:
    case GLX_ACCUM_ALPHA_SIZE:
      v = 16;  // signed 16-bit components, as Mesa's accumulation buffer
      break;
    case GLX_CONFIG_CAVEAT:
      v = GLX_NONE;
      break;
    case GLX_X_VISUAL_TYPE:
      v = GLX_TRUE_COLOR;
      break;
    case GLX_TRANSPARENT_TYPE:
      v = GLX_NONE;
      break;
    case GLX_TRANSPARENT_INDEX_VALUE:
    case GLX_TRANSPARENT_RED_VALUE:
    case GLX_TRANSPARENT_GREEN_VALUE:
    case GLX_TRANSPARENT_BLUE_VALUE:
    case GLX_TRANSPARENT_ALPHA_VALUE:
      v = 0;
      break;
    case GLX_VISUAL_ID:
      v = static_cast<int>(c.visual);
      break;
    case GLX_FBCONFIG_ID:
      v = static_cast<int>(reinterpret_cast<uintptr_t>(encode(c)));
      break;
    case GLX_DRAWABLE_TYPE:
      v = GLX_WINDOW_BIT;
      break;
    case GLX_RENDER_TYPE:
      v = GLX_RGBA_BIT;
      break;
    case GLX_X_RENDERABLE:
      v = 1;
      break;
    case GLX_SCREEN:
      v = c.screen;
      break;
    case GLX_MAX_PBUFFER_WIDTH:
    case GLX_MAX_PBUFFER_HEIGHT:
    case GLX_MAX_PBUFFER_PIXELS:
      v = 0;
      break;
    case GLX_SAMPLE_BUFFERS:
    case GLX_SAMPLES:
      v = 0;
      break;
    case GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB:
      v = 0;
      break;
    default:
      return false;
  }
  *value = v;
  return true;
}

namespace {

// How a requested value compares with the config's (GLX 1.4 table 3.4).
bool value_matches(int attribute, int wanted, int have) {
  if (wanted == static_cast<int>(GLX_DONT_CARE)) return true;
  switch (attribute) {
    // Minimum criteria.
    case GLX_BUFFER_SIZE:
    case GLX_AUX_BUFFERS:
    case GLX_RED_SIZE:
    case GLX_GREEN_SIZE:
    case GLX_BLUE_SIZE:
    case GLX_ALPHA_SIZE:
    case GLX_DEPTH_SIZE:
    case GLX_STENCIL_SIZE:
    case GLX_ACCUM_RED_SIZE:
    case GLX_ACCUM_GREEN_SIZE:
    case GLX_ACCUM_BLUE_SIZE:
    case GLX_ACCUM_ALPHA_SIZE:
    case GLX_SAMPLE_BUFFERS:
    case GLX_SAMPLES:
      return have >= wanted;
    // Masks: every requested bit must be supported.
    case GLX_DRAWABLE_TYPE:
    case GLX_RENDER_TYPE:
      return (have & wanted) == wanted;
    // Ignored by matching.
    case GLX_TRANSPARENT_INDEX_VALUE:
    case GLX_TRANSPARENT_RED_VALUE:
    case GLX_TRANSPARENT_GREEN_VALUE:
    case GLX_TRANSPARENT_BLUE_VALUE:
    case GLX_TRANSPARENT_ALPHA_VALUE:
    case GLX_MAX_PBUFFER_WIDTH:
    case GLX_MAX_PBUFFER_HEIGHT:
    case GLX_MAX_PBUFFER_PIXELS:
    case GLX_VISUAL_ID:
    case GLX_SCREEN:
      return true;
    case GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB:
      return !wanted || have;
    // Exact match.
    default:
      return have == wanted;
  }
}

}  // namespace

void sort_for_choose(std::vector<FBConfig>& configs) {
  std::stable_sort(configs.begin(), configs.end(), [](const FBConfig& a, const FBConfig& b) {
    if (a.alpha != b.alpha) return !a.alpha;
    if (a.double_buffered != b.double_buffered) return !a.double_buffered;
    return a.visual < b.visual;
  });
}

bool config_matches(const FBConfig& c, const int* list) {
  if (list == nullptr) return true;
  for (int i = 0; list[i] != None; i += 2) {
    int have = 0;
    if (!config_attribute(c, list[i], &have)) return false;  // unknown attribute: no match
    if (list[i] == GLX_FBCONFIG_ID) {
      if (list[i + 1] != static_cast<int>(GLX_DONT_CARE) && list[i + 1] != have) return false;
      continue;
    }
    if (!value_matches(list[i], list[i + 1], have)) return false;
  }
  return true;
}

bool visual_list_matches(const FBConfig& c, const int* list) {
  bool rgba = false, double_buffered = false;
  if (list == nullptr) return false;
  for (int i = 0; list[i] != None;) {
    const int a = list[i];
    // Boolean tokens stand alone in glXChooseVisual's list.
    if (a == GLX_USE_GL) {
      ++i;
      continue;
    }
    if (a == GLX_RGBA) {
      rgba = true;
      ++i;
      continue;
    }
    if (a == GLX_DOUBLEBUFFER) {
      double_buffered = true;
      ++i;
      continue;
    }
    if (a == GLX_STEREO) return false;
    if (a == GLX_LEVEL) {
      if (list[i + 1] != 0) return false;
      i += 2;
      continue;
    }
    int have = 0;
    if (!config_attribute(c, a, &have) || !value_matches(a, list[i + 1], have)) return false;
    i += 2;
  }
  // Colour-index visuals (no GLX_RGBA) are not supported.
  return rgba && double_buffered == c.double_buffered;
}

}  // namespace glpt::glx
