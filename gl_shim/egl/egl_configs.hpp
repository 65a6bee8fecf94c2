// EGL configs (EGL 1.5 section 3.4) over glpt's framebuffer configuration model
// (gl_shim/glx/fbconfigs.hpp): every TrueColor visual of depth 24 or 32 with and without 8 alpha
// bits (depth-32 visuals always with alpha), 24-bit depth, 8-bit stencil, OpenGL contexts only
// (EGL_RENDERABLE_TYPE also names OpenGL ES 1.x, see config_attribute). EGL has no
// double-buffered attribute on configs: a window surface chooses its render buffer itself, so
// each visual appears once per alpha choice. A surfaceless display (EGL_MESA_platform_surfaceless)
// has the same two buffer layouts without a visual, for pbuffers only.
#pragma once

#include <EGL/egl.h>

#include <vector>

#include "gl_shim/glx/fbconfigs.hpp"
#include "rt_core/record/frame_record.hpp"

namespace glpt::egl {

struct Config {
  glx::FBConfig fb;     // visual 0 on a surfaceless display
  EGLint id = 0;        // EGL_CONFIG_ID: 1-based position in the display's list
  bool window = false;  // window surfaces (and a native visual) available
};

// The largest pbuffer glpt creates (EGL_MAX_PBUFFER_WIDTH/HEIGHT).
inline constexpr EGLint kMaxPbufferSize = 8192;

std::vector<Config> configs_of_x11_screen(Display* dpy, int screen);
std::vector<Config> surfaceless_configs();

// eglGetConfigAttrib's value; false for an attribute EGL does not define for configs.
bool config_attribute(const Config& c, EGLint attribute, EGLint* value);

// eglChooseConfig (EGL 1.5 3.4.1.2): the configs matching `attrib_list` (EGL_NONE-terminated
// pairs, may be null), best first. Returns EGL_SUCCESS, or EGL_BAD_ATTRIBUTE for an unknown
// attribute or an invalid value (then `out` is empty).
EGLint choose_configs(const std::vector<Config>& configs, const EGLint* attrib_list,
                      std::vector<const Config*>* out);

// The buffers a surface of config `c` has.
rec::DrawableConfig drawable_config(const Config& c, bool double_buffered);

}  // namespace glpt::egl
