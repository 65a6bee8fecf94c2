// GLX framebuffer configurations as the program sees them: the X server's own GLX visual configs
// and FBConfigs (GLXGetVisualConfigs / GLXGetFBConfigs requests), so that visual ids, attributes
// and the order of the lists are those Mesa's libGL reports on the same server. Only configs glpt
// can render are kept (RGBA, 8 bits per colour channel, 0 or 8 alpha bits, no multisampling, no
// float or sRGB buffers). A server without GLX gets the synthesized model of fbconfigs.hpp.
//
// Matching and sorting follow GLX 1.4 section 3.3.3 as Mesa's src/glx/glxcmds.c implements it
// (its choices where the spec leaves room: which attributes are minimums, "larger or zero"
// colour ordering, unknown attributes in a list ignored).
#pragma once

#include <vector>

#include "gl_shim/glx/glx_types.hpp"
#include "rt_core/record/frame_record.hpp"

namespace glpt::glx {

// GLX_DONT_CARE as a signed attribute value.
inline constexpr int kDontCare = -1;

// One configuration: the fields of GLX 1.4 table 3.1 (and the extensions Mesa reports).
struct Config {
  int fbconfig_id = kDontCare;
  int visual_id = 0;  // 0: no X visual (pbuffers only)
  int visual_type = kDontCare;
  int screen = 0;
  int rgba = 1;
  int buffer_size = 0, level = 0, double_buffer = 0, stereo = 0, aux_buffers = 0;
  int red = 0, green = 0, blue = 0, alpha = 0;
  int depth = 0, stencil = 0;
  int accum_red = 0, accum_green = 0, accum_blue = 0, accum_alpha = 0;
  int caveat = 0x8000;  // GLX_NONE
  int transparent_type = 0x8000;
  int transparent_index = kDontCare, transparent_red = kDontCare, transparent_green = kDontCare,
      transparent_blue = kDontCare, transparent_alpha = kDontCare;
  int drawable_type = 0x7;  // window, pixmap, pbuffer
  int render_type = 0x1;    // GLX_RGBA_BIT
  int x_renderable = kDontCare;
  int max_pbuffer_width = 0, max_pbuffer_height = 0, max_pbuffer_pixels = 0;
  int optimal_pbuffer_width = 0, optimal_pbuffer_height = 0;
  int visual_select_group = 0;
  int sample_buffers = 0, samples = 0;
  int bind_to_texture_rgb = kDontCare, bind_to_texture_rgba = kDontCare,
      bind_to_mipmap_texture = kDontCare, bind_to_texture_targets = kDontCare;
  int y_inverted = kDontCare;
  int srgb_capable = 0;
  int float_components = 0;
};

struct ScreenConfigs {
  std::vector<Config> visuals;    // glXChooseVisual / glXGetConfig, one per GLX-capable visual
  std::vector<Config> fbconfigs;  // glXGetFBConfigs, in the server's order
};

// Asks the server's GLX extension for `screen`'s configs over `connection` (an xcb_connection_t).
// False when the server has no GLX (then the caller synthesizes them).
bool query_server_configs(void* xcb_connection, int screen, ScreenConfigs* out);

// The synthesized configs for a server without GLX (fbconfigs.hpp's model: every TrueColor visual
// of depth 24/32, double and single-buffered, with and without alpha, 24-bit depth, 8 stencil).
ScreenConfigs synthesized_configs(Display* dpy, int screen);

// glXGetConfig / glXGetFBConfigAttrib (Mesa's glx_config_get): false for an attribute GLX does
// not define for configs (GLX_BAD_ATTRIBUTE).
bool config_attribute(const Config& c, int attribute, int* value);

// The template an attribute list describes, with glXChooseFBConfig's defaults (`fbconfig_style`:
// every attribute has a value) or glXChooseVisual's (boolean attributes stand alone).
Config chooser_template(const int* attrib_list, bool fbconfig_style);
// Whether `c` satisfies the template (GLX 1.4 table 3.4's match criteria).
bool compatible(const Config& wanted, const Config& c);
// < 0 when `a` sorts before `b` (GLX 1.4 3.3.3's order as Mesa's fbconfig_compare).
int compare(const Config& a, const Config& b);

// The buffers a drawable of config `c` has. A pixmap of a double-buffered config has a back buffer
// too (Mesa's choice): drawn to by default, shown only after glDrawBuffer(GL_FRONT) drawing, as
// glXSwapBuffers does nothing to a pixmap.
rec::DrawableConfig drawable_config(const Config& c);

}  // namespace glpt::glx
