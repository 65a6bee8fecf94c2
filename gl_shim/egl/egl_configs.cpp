#include "gl_shim/egl/egl_configs.hpp"

#include <algorithm>
#include <optional>

namespace glpt::egl {

namespace {

constexpr EGLint kTrueColor = 4;  // X11's TrueColor visual class (EGL_NATIVE_VISUAL_TYPE)

std::vector<Config> numbered(std::vector<Config> configs) {
  for (size_t i = 0; i < configs.size(); ++i) configs[i].id = static_cast<EGLint>(i + 1);
  return configs;
}

}  // namespace

std::vector<Config> configs_of_x11_screen(Display* dpy, int screen) {
  std::vector<Config> out;
  for (const glx::FBConfig& fb : glx::configs_of_screen(dpy, screen))
    if (fb.double_buffered) out.push_back(Config{fb, 0, true});
  return numbered(std::move(out));
}

std::vector<Config> surfaceless_configs() {
  std::vector<Config> out;
  for (bool alpha : {true, false}) {
    glx::FBConfig fb;
    fb.visual = 0;
    fb.depth = 0;
    fb.alpha = alpha;
    out.push_back(Config{fb, 0, false});
  }
  return numbered(std::move(out));
}

bool config_attribute(const Config& c, EGLint attribute, EGLint* value) {
  EGLint v = 0;
  switch (attribute) {
    case EGL_BUFFER_SIZE:
      v = c.fb.alpha ? 32 : 24;
      break;
    case EGL_RED_SIZE:
    case EGL_GREEN_SIZE:
    case EGL_BLUE_SIZE:
      v = 8;
      break;
    case EGL_ALPHA_SIZE:
      v = c.fb.alpha ? 8 : 0;
      break;
    case EGL_LUMINANCE_SIZE:
    case EGL_ALPHA_MASK_SIZE:
    case EGL_LEVEL:
    case EGL_SAMPLES:
    case EGL_SAMPLE_BUFFERS:
    case EGL_TRANSPARENT_RED_VALUE:
    case EGL_TRANSPARENT_GREEN_VALUE:
    case EGL_TRANSPARENT_BLUE_VALUE:
    case EGL_MIN_SWAP_INTERVAL:
      v = 0;
      break;
    case EGL_MAX_SWAP_INTERVAL:
      v = 1;
      break;
    case EGL_DEPTH_SIZE:
      v = 24;
      break;
    case EGL_STENCIL_SIZE:
      v = 8;
      break;
    case EGL_BIND_TO_TEXTURE_RGB:
    case EGL_BIND_TO_TEXTURE_RGBA:
      v = EGL_FALSE;
      break;
    case EGL_COLOR_BUFFER_TYPE:
      v = EGL_RGB_BUFFER;
      break;
    case EGL_CONFIG_CAVEAT:
    case EGL_TRANSPARENT_TYPE:
      v = EGL_NONE;
      break;
    case EGL_CONFIG_ID:
      v = c.id;
      break;
    case EGL_CONFORMANT:
      v = EGL_OPENGL_BIT;
      break;
    case EGL_RENDERABLE_TYPE:
      // Contexts are OpenGL 1.5 only (eglBindAPI refuses OpenGL ES). The OpenGL ES 1.x bit is
      // still set because eglChooseConfig's default asks for it: programs that omit
      // EGL_RENDERABLE_TYPE, or that name EGL_OPENGL_ES_BIT and then bind EGL_OPENGL_API (the
      // xscreensaver 6.06 GL hacks Debian ships do), find configs as they do on Mesa, whose
      // configs support every API.
      v = EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT;
      break;
    case EGL_MAX_PBUFFER_WIDTH:
    case EGL_MAX_PBUFFER_HEIGHT:
      v = kMaxPbufferSize;
      break;
    case EGL_MAX_PBUFFER_PIXELS:
      v = kMaxPbufferSize * kMaxPbufferSize;
      break;
    case EGL_NATIVE_RENDERABLE:
      v = c.window ? EGL_TRUE : EGL_FALSE;
      break;
    case EGL_NATIVE_VISUAL_ID:
      v = static_cast<EGLint>(c.fb.visual);
      break;
    case EGL_NATIVE_VISUAL_TYPE:
      v = c.window ? kTrueColor : EGL_NONE;
      break;
    case EGL_SURFACE_TYPE:
      v = c.window ? (EGL_WINDOW_BIT | EGL_PBUFFER_BIT) : EGL_PBUFFER_BIT;
      break;
    default:
      return false;
  }
  *value = v;
  return true;
}

namespace {

// How eglChooseConfig compares an attribute (EGL 1.5 table 3.4).
enum class Criterion { kAtLeast, kExact, kMask, kIgnored, kSpecial };

struct AttributeRule {
  EGLint attribute;
  EGLint default_value;
  Criterion criterion;
};

constexpr AttributeRule kRules[] = {
    {EGL_BUFFER_SIZE, 0, Criterion::kAtLeast},
    {EGL_RED_SIZE, 0, Criterion::kAtLeast},
    {EGL_GREEN_SIZE, 0, Criterion::kAtLeast},
    {EGL_BLUE_SIZE, 0, Criterion::kAtLeast},
    {EGL_LUMINANCE_SIZE, 0, Criterion::kAtLeast},
    {EGL_ALPHA_SIZE, 0, Criterion::kAtLeast},
    {EGL_ALPHA_MASK_SIZE, 0, Criterion::kAtLeast},
    {EGL_BIND_TO_TEXTURE_RGB, EGL_DONT_CARE, Criterion::kExact},
    {EGL_BIND_TO_TEXTURE_RGBA, EGL_DONT_CARE, Criterion::kExact},
    {EGL_COLOR_BUFFER_TYPE, EGL_RGB_BUFFER, Criterion::kExact},
    {EGL_CONFIG_CAVEAT, EGL_DONT_CARE, Criterion::kExact},
    {EGL_CONFIG_ID, EGL_DONT_CARE, Criterion::kExact},
    {EGL_CONFORMANT, 0, Criterion::kMask},
    {EGL_DEPTH_SIZE, 0, Criterion::kAtLeast},
    {EGL_LEVEL, 0, Criterion::kExact},
    {EGL_MATCH_NATIVE_PIXMAP, EGL_NONE, Criterion::kSpecial},
    {EGL_MAX_PBUFFER_WIDTH, 0, Criterion::kIgnored},
    {EGL_MAX_PBUFFER_HEIGHT, 0, Criterion::kIgnored},
    {EGL_MAX_PBUFFER_PIXELS, 0, Criterion::kIgnored},
    {EGL_MAX_SWAP_INTERVAL, EGL_DONT_CARE, Criterion::kExact},
    {EGL_MIN_SWAP_INTERVAL, EGL_DONT_CARE, Criterion::kExact},
    {EGL_NATIVE_RENDERABLE, EGL_DONT_CARE, Criterion::kExact},
    {EGL_NATIVE_VISUAL_ID, 0, Criterion::kIgnored},
    {EGL_NATIVE_VISUAL_TYPE, EGL_DONT_CARE, Criterion::kExact},
    {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, Criterion::kMask},
    {EGL_SAMPLE_BUFFERS, 0, Criterion::kAtLeast},
    {EGL_SAMPLES, 0, Criterion::kAtLeast},
    {EGL_STENCIL_SIZE, 0, Criterion::kAtLeast},
    {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, Criterion::kMask},
    {EGL_TRANSPARENT_TYPE, EGL_NONE, Criterion::kExact},
    {EGL_TRANSPARENT_RED_VALUE, EGL_DONT_CARE, Criterion::kExact},
    {EGL_TRANSPARENT_GREEN_VALUE, EGL_DONT_CARE, Criterion::kExact},
    {EGL_TRANSPARENT_BLUE_VALUE, EGL_DONT_CARE, Criterion::kExact},
};
constexpr size_t kRuleCount = sizeof(kRules) / sizeof(kRules[0]);

std::optional<size_t> rule_index(EGLint attribute) {
  for (size_t i = 0; i < kRuleCount; ++i)
    if (kRules[i].attribute == attribute) return i;
  return std::nullopt;
}

// Values eglChooseConfig rejects with EGL_BAD_ATTRIBUTE (as Mesa's _eglValidateConfig does for
// matching): negative sizes, non-boolean booleans, unknown enums and mask bits.
bool value_is_valid(EGLint attribute, EGLint value) {
  if (value == EGL_DONT_CARE) return attribute != EGL_LEVEL;
  switch (attribute) {
    case EGL_BIND_TO_TEXTURE_RGB:
    case EGL_BIND_TO_TEXTURE_RGBA:
    case EGL_NATIVE_RENDERABLE:
      return value == EGL_TRUE || value == EGL_FALSE;
    case EGL_COLOR_BUFFER_TYPE:
      return value == EGL_RGB_BUFFER || value == EGL_LUMINANCE_BUFFER;
    case EGL_CONFIG_CAVEAT:
      return value == EGL_NONE || value == EGL_SLOW_CONFIG || value == EGL_NON_CONFORMANT_CONFIG;
    case EGL_TRANSPARENT_TYPE:
      return value == EGL_NONE || value == EGL_TRANSPARENT_RGB;
    case EGL_CONFORMANT:
    case EGL_RENDERABLE_TYPE:
      return (value & ~(EGL_OPENGL_ES_BIT | EGL_OPENVG_BIT | EGL_OPENGL_ES2_BIT | EGL_OPENGL_BIT |
                        EGL_OPENGL_ES3_BIT)) == 0;
    case EGL_SURFACE_TYPE:
      return (value & ~(EGL_PBUFFER_BIT | EGL_PIXMAP_BIT | EGL_WINDOW_BIT |
                        EGL_VG_COLORSPACE_LINEAR_BIT | EGL_VG_ALPHA_FORMAT_PRE_BIT |
                        EGL_MULTISAMPLE_RESOLVE_BOX_BIT | EGL_SWAP_BEHAVIOR_PRESERVED_BIT)) == 0;
    case EGL_MATCH_NATIVE_PIXMAP:
    case EGL_NATIVE_VISUAL_ID:
    case EGL_NATIVE_VISUAL_TYPE:
      return true;
    default:
      return value >= 0;  // sizes, counts, levels, intervals, ids, transparent values
  }
}

bool matches(const Config& c, const EGLint* wanted, const bool* given) {
  // EGL_CONFIG_ID alone decides when it is given (EGL 1.5 3.4.1.2).
  const size_t id_index = *rule_index(EGL_CONFIG_ID);
  if (given[id_index] && wanted[id_index] != EGL_DONT_CARE) return wanted[id_index] == c.id;
  for (size_t i = 0; i < kRuleCount; ++i) {
    const AttributeRule& rule = kRules[i];
    const EGLint w = wanted[i];
    if (rule.criterion == Criterion::kIgnored) continue;
    if (rule.criterion == Criterion::kSpecial) {
      if (w != EGL_NONE) return false;  // pixmap surfaces are not supported
      continue;
    }
    if (w == EGL_DONT_CARE) continue;
    // Transparent values count only where EGL_TRANSPARENT_RGB is asked for, which no config has.
    if (rule.attribute == EGL_TRANSPARENT_RED_VALUE ||
        rule.attribute == EGL_TRANSPARENT_GREEN_VALUE ||
        rule.attribute == EGL_TRANSPARENT_BLUE_VALUE)
      continue;
    EGLint have = 0;
    config_attribute(c, rule.attribute, &have);
    switch (rule.criterion) {
      case Criterion::kAtLeast:
        if (have < w) return false;
        break;
      case Criterion::kExact:
        if (have != w) return false;
        break;
      case Criterion::kMask:
        if ((have & w) != w) return false;
        break;
      default:
        break;
    }
  }
  return true;
}

}  // namespace

EGLint choose_configs(const std::vector<Config>& configs, const EGLint* list,
                      std::vector<const Config*>* out) {
  out->clear();
  EGLint wanted[kRuleCount];
  bool given[kRuleCount] = {};
  for (size_t i = 0; i < kRuleCount; ++i) wanted[i] = kRules[i].default_value;
  for (size_t i = 0; list != nullptr && list[i] != EGL_NONE; i += 2) {
    const std::optional<size_t> r = rule_index(list[i]);
    if (!r || !value_is_valid(list[i], list[i + 1])) return EGL_BAD_ATTRIBUTE;
    wanted[*r] = list[i + 1];  // a repeated attribute: the last one counts (as Mesa)
    given[*r] = true;
  }
  for (const Config& c : configs)
    if (matches(c, wanted, given)) out->push_back(&c);

  // Sorting (EGL 1.5 3.4.1.2): caveat and buffer type are the same for every glpt config;
  // then more colour bits among the components asked for (a nonzero, not DONT_CARE size), then
  // a smaller EGL_BUFFER_SIZE; samples, depth, stencil and alpha mask are equal; then
  // EGL_CONFIG_ID.
  auto requested = [&](EGLint attribute) {
    const EGLint w = wanted[*rule_index(attribute)];
    return w != EGL_DONT_CARE && w > 0;
  };
  const bool count_alpha = requested(EGL_ALPHA_SIZE);
  auto color_bits = [&](const Config* c) {
    int bits = 0;
    if (requested(EGL_RED_SIZE)) bits += 8;
    if (requested(EGL_GREEN_SIZE)) bits += 8;
    if (requested(EGL_BLUE_SIZE)) bits += 8;
    if (count_alpha && c->fb.alpha) bits += 8;
    return bits;
  };
  std::stable_sort(out->begin(), out->end(), [&](const Config* a, const Config* b) {
    const int bits_a = color_bits(a), bits_b = color_bits(b);
    if (bits_a != bits_b) return bits_a > bits_b;
    EGLint size_a = 0, size_b = 0;
    config_attribute(*a, EGL_BUFFER_SIZE, &size_a);
    config_attribute(*b, EGL_BUFFER_SIZE, &size_b);
    if (size_a != size_b) return size_a < size_b;
    return a->id < b->id;
  });
  return EGL_SUCCESS;
}

rec::DrawableConfig drawable_config(const Config& c, bool double_buffered) {
  rec::DrawableConfig d;
  d.double_buffered = double_buffered;
  d.has_alpha = c.fb.alpha;
  return d;
}

}  // namespace glpt::egl
