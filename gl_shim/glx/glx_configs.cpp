#include "gl_shim/glx/glx_configs.hpp"

#include <sys/uio.h>
#include <xcb/xcb.h>
#include <xcb/xcbext.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "gl/glx_enums.h"
#include "gl_shim/glx/fbconfigs.hpp"

namespace glpt::glx {
namespace {

// Tokens of GLX extensions the registry header leaves out (glxext.h values).
constexpr int kVisualCaveatExt = 0x20;             // GLX_VISUAL_CAVEAT_EXT
constexpr int kOptimalPbufferWidthSgix = 0x8019;   // GLX_OPTIMAL_PBUFFER_WIDTH_SGIX
constexpr int kOptimalPbufferHeightSgix = 0x801A;  // GLX_OPTIMAL_PBUFFER_HEIGHT_SGIX
constexpr int kVisualSelectGroupSgix = 0x8028;     // GLX_VISUAL_SELECT_GROUP_SGIX
constexpr int kFloatComponentsNv = 0x20B0;         // GLX_FLOAT_COMPONENTS_NV
constexpr uint8_t kGetVisualConfigs = 14;          // X_GLXGetVisualConfigs
constexpr uint8_t kGetFBConfigs = 21;              // X_GLXGetFBConfigs
constexpr int kFixedVisualProps = 18;              // __GLX_MIN_CONFIG_PROPS

int glx_visual_type(int x_class) {
  static constexpr int kTypes[] = {GLX_STATIC_GRAY,  GLX_GRAY_SCALE, GLX_STATIC_COLOR,
                                   GLX_PSEUDO_COLOR, GLX_TRUE_COLOR, GLX_DIRECT_COLOR};
  return x_class >= 0 && x_class < 6 ? kTypes[x_class] : GLX_NONE;
}

// Applies one (tag, value) pair of a server reply or of a chooser's attribute list.
void apply_tag(Config& c, int tag, int value) {
  switch (tag) {
    case GLX_RGBA:
      c.render_type = value ? GLX_RGBA_BIT : GLX_COLOR_INDEX_BIT;
      break;
    case GLX_BUFFER_SIZE:
      c.buffer_size = value;
      break;
    case GLX_LEVEL:
      c.level = value;
      break;
    case GLX_DOUBLEBUFFER:
      c.double_buffer = value;
      break;
    case GLX_STEREO:
      c.stereo = value;
      break;
    case GLX_AUX_BUFFERS:
      c.aux_buffers = value;
      break;
    case GLX_RED_SIZE:
      c.red = value;
      break;
    case GLX_GREEN_SIZE:
      c.green = value;
      break;
    case GLX_BLUE_SIZE:
      c.blue = value;
      break;
    case GLX_ALPHA_SIZE:
      c.alpha = value;
      break;
    case GLX_DEPTH_SIZE:
      c.depth = value;
      break;
    case GLX_STENCIL_SIZE:
      c.stencil = value;
      break;
    case GLX_ACCUM_RED_SIZE:
      c.accum_red = value;
      break;
    case GLX_ACCUM_GREEN_SIZE:
      c.accum_green = value;
      break;
    case GLX_ACCUM_BLUE_SIZE:
      c.accum_blue = value;
      break;
    case GLX_ACCUM_ALPHA_SIZE:
      c.accum_alpha = value;
      break;
    case kVisualCaveatExt:
      c.caveat = value;
      break;  // == GLX_CONFIG_CAVEAT
    case GLX_X_VISUAL_TYPE:
      c.visual_type = value;
      break;
    case GLX_TRANSPARENT_TYPE:
      c.transparent_type = value;
      break;
    case GLX_TRANSPARENT_INDEX_VALUE:
      c.transparent_index = value;
      break;
    case GLX_TRANSPARENT_RED_VALUE:
      c.transparent_red = value;
      break;
    case GLX_TRANSPARENT_GREEN_VALUE:
      c.transparent_green = value;
      break;
    case GLX_TRANSPARENT_BLUE_VALUE:
      c.transparent_blue = value;
      break;
    case GLX_TRANSPARENT_ALPHA_VALUE:
      c.transparent_alpha = value;
      break;
    case GLX_VISUAL_ID:
      c.visual_id = value;
      break;
    case GLX_DRAWABLE_TYPE:
      c.drawable_type = value;
      break;
    case GLX_RENDER_TYPE:
      c.render_type = value;
      break;
    case GLX_X_RENDERABLE:
      c.x_renderable = value;
      break;
    case GLX_FBCONFIG_ID:
      c.fbconfig_id = value;
      break;
    case GLX_MAX_PBUFFER_WIDTH:
      c.max_pbuffer_width = value;
      break;
    case GLX_MAX_PBUFFER_HEIGHT:
      c.max_pbuffer_height = value;
      break;
    case GLX_MAX_PBUFFER_PIXELS:
      c.max_pbuffer_pixels = value;
      break;
    case kOptimalPbufferWidthSgix:
      c.optimal_pbuffer_width = value;
      break;
    case kOptimalPbufferHeightSgix:
      c.optimal_pbuffer_height = value;
      break;
    case kVisualSelectGroupSgix:
      c.visual_select_group = value;
      break;
    case GLX_SAMPLE_BUFFERS:
      c.sample_buffers = value;
      break;
    case GLX_SAMPLES:
      c.samples = value;
      break;
    case GLX_BIND_TO_TEXTURE_RGB_EXT:
      c.bind_to_texture_rgb = value;
      break;
    case GLX_BIND_TO_TEXTURE_RGBA_EXT:
      c.bind_to_texture_rgba = value;
      break;
    case GLX_BIND_TO_MIPMAP_TEXTURE_EXT:
      c.bind_to_mipmap_texture = value;
      break;
    case GLX_BIND_TO_TEXTURE_TARGETS_EXT:
      c.bind_to_texture_targets = value;
      break;
    case GLX_Y_INVERTED_EXT:
      c.y_inverted = value;
      break;
    case GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB:
      c.srgb_capable = value;
      break;
    case kFloatComponentsNv:
      c.float_components = value;
      break;
    default:
      break;  // unknown tags are skipped with their value, as Mesa does
  }
}

// What glpt's renderer can draw into: RGBA8 or RGB8 colour, single-sampled, linear, fixed point;
// stencil only with a 24-bit depth buffer (packed depth/stencil). That is also the set Mesa's
// llvmpipe keeps of Xvfb's configs (it has no stencil-only or 16/8 buffers).
bool renderable(const Config& c) {
  return (c.stencil == 0 || c.depth == 24) && (c.render_type & GLX_RGBA_BIT) != 0 && c.red == 8 &&
         c.green == 8 && c.blue == 8 && (c.alpha == 0 || c.alpha == 8) && c.sample_buffers == 0 &&
         c.float_components == 0 && c.srgb_capable == 0 && c.level == 0 && c.stereo == 0;
}

// One GLX request with a 4-byte screen argument; the reply (caller frees) or nullptr.
uint8_t* glx_screen_request(xcb_connection_t* c, uint8_t opcode, int screen) {
  static xcb_extension_t glx_extension = {"GLX", 0};
  const xcb_query_extension_reply_t* ext = xcb_get_extension_data(c, &glx_extension);
  if (ext == nullptr || !ext->present) return nullptr;
  struct {
    uint8_t major, minor;
    uint16_t length;
    uint32_t screen;
  } request{};
  request.screen = static_cast<uint32_t>(screen);
  iovec parts[3] = {};  // xcb_send_request uses the two before the request itself
  parts[2].iov_base = &request;
  parts[2].iov_len = sizeof(request);
  xcb_protocol_request_t info = {1, &glx_extension, opcode, 0};
  const unsigned sequence = xcb_send_request(c, XCB_REQUEST_CHECKED, parts + 2, &info);
  xcb_generic_error_t* error = nullptr;
  auto* reply = static_cast<uint8_t*>(xcb_wait_for_reply(c, sequence, &error));
  free(error);
  return reply;
}

uint32_t word(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

}  // namespace

bool query_server_configs(void* connection, int screen, ScreenConfigs* out) {
  auto* c = static_cast<xcb_connection_t*>(connection);
  *out = {};
  uint8_t* visuals = glx_screen_request(c, kGetVisualConfigs, screen);
  if (visuals == nullptr) return false;
  const uint32_t reply_words = word(visuals + 4);
  const uint32_t count = word(visuals + 8), props = word(visuals + 12);
  if (props >= kFixedVisualProps && uint64_t{count} * props <= reply_words) {
    const uint8_t* p = visuals + 32;
    for (uint32_t i = 0; i < count; ++i, p += props * 4) {
      Config v;
      v.screen = screen;
      v.drawable_type = GLX_WINDOW_BIT | GLX_PIXMAP_BIT;  // implied by a visual (as Mesa)
      int fixed[kFixedVisualProps];
      for (int k = 0; k < kFixedVisualProps; ++k) fixed[k] = static_cast<int>(word(p + 4 * k));
      v.visual_id = fixed[0];
      v.visual_type = glx_visual_type(fixed[1]);
      v.render_type = fixed[2] ? GLX_RGBA_BIT : GLX_COLOR_INDEX_BIT;
      v.red = fixed[3], v.green = fixed[4], v.blue = fixed[5], v.alpha = fixed[6];
      v.accum_red = fixed[7], v.accum_green = fixed[8], v.accum_blue = fixed[9],
      v.accum_alpha = fixed[10];
      v.double_buffer = fixed[11], v.stereo = fixed[12], v.buffer_size = fixed[13];
      v.depth = fixed[14], v.stencil = fixed[15], v.aux_buffers = fixed[16], v.level = fixed[17];
      for (uint32_t k = kFixedVisualProps; k + 1 < props; k += 2)
        apply_tag(v, static_cast<int>(word(p + 4 * k)), static_cast<int>(word(p + 4 * k + 4)));
      if (renderable(v)) out->visuals.push_back(v);
    }
  }
  free(visuals);
  uint8_t* fbconfigs = glx_screen_request(c, kGetFBConfigs, screen);
  if (fbconfigs != nullptr) {
    const uint32_t words = word(fbconfigs + 4);
    const uint32_t n = word(fbconfigs + 8), attribs = word(fbconfigs + 12);
    if (uint64_t{n} * attribs * 2 <= words) {
      const uint8_t* p = fbconfigs + 32;
      for (uint32_t i = 0; i < n; ++i, p += attribs * 8) {
        Config f;
        f.screen = screen;
        f.render_type = 0;
        for (uint32_t k = 0; k < attribs; ++k)
          apply_tag(f, static_cast<int>(word(p + 8 * k)), static_cast<int>(word(p + 8 * k + 4)));
        if (renderable(f)) out->fbconfigs.push_back(f);
      }
    }
    free(fbconfigs);
  }
  return !out->visuals.empty() || !out->fbconfigs.empty();
}

ScreenConfigs synthesized_configs(Display* dpy, int screen) {
  ScreenConfigs out;
  int id = 1;
  for (const FBConfig& fb : configs_of_screen(dpy, screen)) {
    Config c;
    c.screen = screen;
    c.fbconfig_id = id++;
    c.visual_id = static_cast<int>(fb.visual);
    c.visual_type = GLX_TRUE_COLOR;
    c.double_buffer = fb.double_buffered;
    c.red = c.green = c.blue = 8;
    c.alpha = fb.alpha ? 8 : 0;
    c.buffer_size = fb.alpha ? 32 : 24;
    c.depth = 24;
    c.stencil = 8;
    c.drawable_type = GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT;
    c.x_renderable = 1;
    c.max_pbuffer_width = c.max_pbuffer_height = 8192;
    c.max_pbuffer_pixels = 8192 * 8192;
    out.fbconfigs.push_back(c);
    // One visual config per X visual: the first (double-buffered, alpha) config of it.
    bool seen = false;
    for (const Config& v : out.visuals) seen = seen || v.visual_id == c.visual_id;
    if (!seen) out.visuals.push_back(c);
  }
  return out;
}

bool config_attribute(const Config& c, int attribute, int* value) {
  int v = 0;
  switch (attribute) {
    case GLX_USE_GL:
      v = 1;
      break;
    case GLX_BUFFER_SIZE:
      v = c.buffer_size;
      break;
    case GLX_RGBA:
      v = (c.render_type & GLX_COLOR_INDEX_BIT) == 0;
      break;
    case GLX_RED_SIZE:
      v = c.red;
      break;
    case GLX_GREEN_SIZE:
      v = c.green;
      break;
    case GLX_BLUE_SIZE:
      v = c.blue;
      break;
    case GLX_ALPHA_SIZE:
      v = c.alpha;
      break;
    case GLX_DOUBLEBUFFER:
      v = c.double_buffer;
      break;
    case GLX_STEREO:
      v = c.stereo;
      break;
    case GLX_AUX_BUFFERS:
      v = c.aux_buffers;
      break;
    case GLX_DEPTH_SIZE:
      v = c.depth;
      break;
    case GLX_STENCIL_SIZE:
      v = c.stencil;
      break;
    case GLX_ACCUM_RED_SIZE:
      v = c.accum_red;
      break;
    case GLX_ACCUM_GREEN_SIZE:
      v = c.accum_green;
      break;
    case GLX_ACCUM_BLUE_SIZE:
      v = c.accum_blue;
      break;
    case GLX_ACCUM_ALPHA_SIZE:
      v = c.accum_alpha;
      break;
    case GLX_LEVEL:
      v = c.level;
      break;
    case GLX_TRANSPARENT_TYPE:
      v = c.transparent_type;
      break;
    case GLX_TRANSPARENT_RED_VALUE:
      v = c.transparent_red;
      break;
    case GLX_TRANSPARENT_GREEN_VALUE:
      v = c.transparent_green;
      break;
    case GLX_TRANSPARENT_BLUE_VALUE:
      v = c.transparent_blue;
      break;
    case GLX_TRANSPARENT_ALPHA_VALUE:
      v = c.transparent_alpha;
      break;
    case GLX_TRANSPARENT_INDEX_VALUE:
      v = c.transparent_index;
      break;
    case GLX_X_VISUAL_TYPE:
      v = c.visual_type;
      break;
    case GLX_CONFIG_CAVEAT:
      v = c.caveat;
      break;
    case GLX_VISUAL_ID:
      v = c.visual_id;
      break;
    case GLX_DRAWABLE_TYPE:
      v = c.drawable_type;
      break;
    case GLX_RENDER_TYPE:
      v = c.render_type;
      break;
    case GLX_X_RENDERABLE:
      v = c.x_renderable;
      break;
    case GLX_FBCONFIG_ID:
      v = c.fbconfig_id;
      break;
    // Mesa answers its own pbuffer limit, whatever the server said (glxconfig.c).
    case GLX_MAX_PBUFFER_WIDTH:
    case GLX_MAX_PBUFFER_HEIGHT:
      v = 4096;
      break;
    case GLX_MAX_PBUFFER_PIXELS:
      v = c.max_pbuffer_pixels;
      break;
    case kOptimalPbufferWidthSgix:
      v = c.optimal_pbuffer_width;
      break;
    case kOptimalPbufferHeightSgix:
      v = c.optimal_pbuffer_height;
      break;
    case GLX_SAMPLE_BUFFERS:
      v = c.sample_buffers;
      break;
    case GLX_SAMPLES:
      v = c.samples;
      break;
    case GLX_BIND_TO_TEXTURE_RGB_EXT:
      v = c.bind_to_texture_rgb;
      break;
    case GLX_BIND_TO_TEXTURE_RGBA_EXT:
      v = c.bind_to_texture_rgba;
      break;
    case GLX_BIND_TO_MIPMAP_TEXTURE_EXT:
      v = c.bind_to_mipmap_texture == 1;
      break;
    case GLX_BIND_TO_TEXTURE_TARGETS_EXT:
      v = c.bind_to_texture_targets;
      break;
    case GLX_Y_INVERTED_EXT:
      v = c.y_inverted;
      break;
    case GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB:
      v = c.srgb_capable;
      break;
    case kFloatComponentsNv:
      v = c.float_components;
      break;
    default:
      return false;  // GLX_VISUAL_SELECT_GROUP_SGIX is not for programs either
  }
  *value = v;
  return true;
}

Config chooser_template(const int* list, bool fbconfig_style) {
  // Table 3.4's defaults, as Mesa's init_fbconfig_for_chooser.
  Config t;
  t.render_type = 0;
  t.caveat = kDontCare;
  t.visual_id = kDontCare;
  t.visual_type = kDontCare;
  t.drawable_type = GLX_WINDOW_BIT;
  t.transparent_type = GLX_NONE;
  t.srgb_capable = kDontCare;
  t.fbconfig_id = kDontCare;
  t.x_renderable = kDontCare;
  if (fbconfig_style) {
    t.double_buffer = kDontCare;
    t.render_type = GLX_RGBA_BIT;
  }
  for (int i = 0; list != nullptr && list[i] != None;) {
    const int tag = list[i];
    // glXChooseVisual's boolean attributes stand alone in its list.
    const bool boolean = !fbconfig_style && (tag == GLX_RGBA || tag == GLX_DOUBLEBUFFER ||
                                             tag == GLX_STEREO || tag == GLX_USE_GL);
    if (boolean) {
      if (tag != GLX_USE_GL) apply_tag(t, tag, 1);
      i += 1;
      continue;
    }
    if (tag != GLX_USE_GL) apply_tag(t, tag, list[i + 1]);
    i += 2;
  }
  return t;
}

bool compatible(const Config& a, const Config& b) {
  const auto dont_care_or_equal = [](int want, int have) {
    return want == kDontCare || want == have;
  };
  const auto minimum = [](int want, int have) { return want == kDontCare || want <= have; };
  const auto mask = [](int want, int have) { return want == kDontCare || (want & ~have) == 0; };
  if (!dont_care_or_equal(a.double_buffer, b.double_buffer) ||
      !dont_care_or_equal(a.visual_type, b.visual_type) ||
      !dont_care_or_equal(a.caveat, b.caveat) ||
      !dont_care_or_equal(a.x_renderable, b.x_renderable) ||
      !dont_care_or_equal(a.fbconfig_id, b.fbconfig_id))
    return false;
  const int minimums[][2] = {{a.buffer_size, b.buffer_size},
                             {a.aux_buffers, b.aux_buffers},
                             {a.red, b.red},
                             {a.green, b.green},
                             {a.blue, b.blue},
                             {a.alpha, b.alpha},
                             {a.depth, b.depth},
                             {a.stencil, b.stencil},
                             {a.accum_red, b.accum_red},
                             {a.accum_green, b.accum_green},
                             {a.accum_blue, b.accum_blue},
                             {a.accum_alpha, b.accum_alpha},
                             {a.sample_buffers, b.sample_buffers},
                             {a.max_pbuffer_width, b.max_pbuffer_width},
                             {a.max_pbuffer_height, b.max_pbuffer_height},
                             {a.max_pbuffer_pixels, b.max_pbuffer_pixels},
                             {a.samples, b.samples}};
  for (const auto& m : minimums)
    if (!minimum(m[0], m[1])) return false;
  if (!dont_care_or_equal(a.stereo, b.stereo) || a.level != b.level ||
      !mask(a.drawable_type, b.drawable_type) || !mask(a.render_type, b.render_type) ||
      !dont_care_or_equal(a.srgb_capable, b.srgb_capable) ||
      !dont_care_or_equal(a.float_components, b.float_components))
    return false;
  // A transparent type of 0 from the program means "don't care" (Mesa's workaround for old
  // drivers); GLX_NONE also accepts a server's 0.
  if (a.transparent_type != kDontCare && a.transparent_type != 0) {
    if (a.transparent_type == GLX_NONE) {
      if (b.transparent_type != GLX_NONE && b.transparent_type != 0) return false;
    } else if (a.transparent_type != b.transparent_type) {
      return false;
    }
    if (a.transparent_type == GLX_TRANSPARENT_RGB) {
      if (!dont_care_or_equal(a.transparent_red, b.transparent_red) ||
          !dont_care_or_equal(a.transparent_green, b.transparent_green) ||
          !dont_care_or_equal(a.transparent_blue, b.transparent_blue) ||
          !dont_care_or_equal(a.transparent_alpha, b.transparent_alpha))
        return false;
    } else if (a.transparent_type == GLX_TRANSPARENT_INDEX) {
      if (!dont_care_or_equal(a.transparent_index, b.transparent_index)) return false;
    }
  }
  return true;
}

int compare(const Config& a, const Config& b) {
  // The order of GLX 1.4 3.3.3; Mesa compares colour sizes one by one, preferring larger ones but
  // a zero size first ("larger or zero"), where the spec sums the requested components.
  const auto larger_or_zero = [](int x, int y) {
    if (x == y) return 0;
    if (x == 0) return -1;
    if (y == 0) return 1;
    return y - x;
  };
  if (a.visual_select_group != b.visual_select_group)
    return a.visual_select_group - b.visual_select_group;
  if (a.caveat != b.caveat) return a.caveat - b.caveat;
  for (int d : {larger_or_zero(a.red, b.red), larger_or_zero(a.green, b.green),
                larger_or_zero(a.blue, b.blue), larger_or_zero(a.alpha, b.alpha)})
    if (d != 0) return d;
  if (a.buffer_size != b.buffer_size) return a.buffer_size - b.buffer_size;
  if (a.double_buffer != b.double_buffer) return a.double_buffer ? 1 : -1;  // single first
  if (a.aux_buffers != b.aux_buffers) return a.aux_buffers - b.aux_buffers;
  if (a.sample_buffers != b.sample_buffers) return a.sample_buffers - b.sample_buffers;
  if (a.samples != b.samples) return a.samples - b.samples;
  if (int d = larger_or_zero(a.depth, b.depth)) return d;
  if (a.stencil != b.stencil) return a.stencil - b.stencil;
  for (int d :
       {larger_or_zero(a.accum_red, b.accum_red), larger_or_zero(a.accum_green, b.accum_green),
        larger_or_zero(a.accum_blue, b.accum_blue), larger_or_zero(a.accum_alpha, b.accum_alpha)})
    if (d != 0) return d;
  if (a.visual_type != b.visual_type) return a.visual_type - b.visual_type;
  if (a.max_pbuffer_width != b.max_pbuffer_width) return b.max_pbuffer_width - a.max_pbuffer_width;
  if (a.max_pbuffer_height != b.max_pbuffer_height)
    return b.max_pbuffer_height - a.max_pbuffer_height;
  return b.max_pbuffer_pixels - a.max_pbuffer_pixels;
}

rec::DrawableConfig drawable_config(const Config& c) {
  rec::DrawableConfig d;
  d.double_buffered = c.double_buffer != 0;
  d.has_alpha = c.alpha > 0;
  d.depth_bits = static_cast<uint32_t>(c.depth);
  d.stencil_bits = static_cast<uint32_t>(c.stencil);
  d.accum_bits = static_cast<uint32_t>(c.accum_red);
  return d;
}

}  // namespace glpt::glx
