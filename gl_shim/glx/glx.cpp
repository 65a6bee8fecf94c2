// GLX 1.4 entry points (plus GLX_ARB_create_context(_profile), GLX_ARB_get_proc_address,
// GLX_EXT/MESA/SGI_swap_control, GLX_SGI_make_current_read): configs, contexts, make-current,
// swap, GLX windows, pixmaps and pbuffers, glXCopyContext and glXUseXFont. A GLX context wraps a
// glpt::Context and the targets of the drawables it drew to.
//
// Errors go through the program's Xlib error handler with the codes Mesa's libGL uses
// (glx_display.hpp); functions with a return value also return NULL/False/None as Mesa does.
#include <X11/Xatom.h>
#include <X11/Xlib-xcb.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>

#include "gl/gl_enums.h"
#include "gl/glx_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/glx/glx_api.hpp"
#include "gl_shim/glx/glx_display.hpp"
#include "gl_shim/glx/glx_types.hpp"
#include "gl_shim/glx/x11_window_target.hpp"
#include "gl_shim/state/attrib_stack.hpp"

struct __GLXcontextRec {
  explicit __GLXcontextRec(const __GLXcontextRec* share) : gl(share ? &share->gl : nullptr) {
    gl.window_system_context = this;
    gl.window_system = glpt::WindowSystem::kGlx;
  }
  glpt::Context gl;
  Display* display = nullptr;  // of creation, then of the last make-current
  const glpt::glx::Config* config = nullptr;
  int screen = 0;
  GLXDrawable drawable = None;
  GLXDrawable readable = None;
  // The X windows and pixmaps this context drew to lately (their targets are shared with the
  // other contexts drawing to them, DisplayState::window_targets), and when each was last made
  // current (a program that makes new windows now and then does not pile up connections).
  struct WindowEntry {
    std::shared_ptr<glpt::X11WindowTarget> target;
    uint64_t last_use = 0;
  };
  std::map<XID, WindowEntry> windows;
  uint64_t uses = 0;
  std::shared_ptr<glpt::HeadlessTarget> pbuffer;  // the current pbuffer, kept while bound
  bool bound = false;                             // current on `bound_thread`
  std::thread::id bound_thread;
  bool destroy_when_released = false;  // glXDestroyContext while current (GLX 1.4 3.3.7)
};

namespace {

using glpt::glx::Config;
using glpt::glx::DisplayState;
using glpt::glx::DrawableKind;
using glpt::glx::glx_entry;
using glpt::glx::glx_entry_void;
using glpt::glx::GlxDrawable;
using glpt::glx::kClientSide;

// Every live GLX context, so that a stale or foreign GLXContext is GLXBadContext, not a crash.
// Process-wide like the contexts themselves (a context may be made current on any thread).
std::mutex& contexts_mutex() {
  static std::mutex m;
  return m;
}
std::set<GLXContext>& live_contexts() {
  static std::set<GLXContext> contexts;
  return contexts;
}
bool is_live(GLXContext ctx) {
  std::lock_guard lock(contexts_mutex());
  return ctx != nullptr && live_contexts().count(ctx) != 0;
}
GLXContext current_glx() {
  glpt::Context* gl = glpt::current_context();
  if (gl == nullptr || gl->window_system != glpt::WindowSystem::kGlx) return nullptr;
  return static_cast<GLXContext>(gl->window_system_context);
}

void release_current() {
  GLXContext old = current_glx();
  glpt::set_current_context(nullptr);
  if (old == nullptr) return;
  glpt::flush_before_release(old->gl);
  old->gl.target = nullptr;  // a released context has no drawable (a pbuffer may go now)
  bool destroy_now = false;
  {
    std::lock_guard lock(contexts_mutex());
    old->bound = false;
    destroy_now = old->destroy_when_released;
    if (destroy_now) live_contexts().erase(old);
  }
  old->pbuffer.reset();
  if (destroy_now) delete old;
}

GLXContext create_context(Display* dpy, const Config* config, GLXContext share, int minor) {
  if (share != nullptr && !is_live(share)) {
    glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadContext, 0, minor);
    return nullptr;
  }
  auto ctx = std::make_unique<__GLXcontextRec>(share);
  ctx->display = dpy;
  ctx->config = config;
  ctx->screen = config->screen;
  std::lock_guard lock(contexts_mutex());
  live_contexts().insert(ctx.get());  // may throw: then the context is freed
  return ctx.release();
}

// The GLX drawable `id` names on `dpy`, if it is one glX*Create* made.
bool find_glx_drawable(DisplayState* state, XID id, GlxDrawable* out) {
  std::lock_guard lock(state->mutex);
  auto it = state->drawables.find(id);
  if (it == state->drawables.end()) return false;
  *out = it->second;
  return true;
}

// The target drawing to X window or pixmap `x`, shared by every context drawing to it, created
// on first use. nullptr (and GLXBadDrawable) when `x` is not a drawable of the display.
std::shared_ptr<glpt::X11WindowTarget> shared_window_target(Display* dpy, DisplayState* state,
                                                            XID x, const Config* config,
                                                            int minor) {
  {
    std::lock_guard lock(state->mutex);
    std::erase_if(state->window_targets, [](const auto& e) { return e.second.expired(); });
    auto it = state->window_targets.find(x);
    if (it != state->window_targets.end())
      if (std::shared_ptr<glpt::X11WindowTarget> target = it->second.lock()) return target;
  }
  // glpt's connection is about to ask the server about a window the program may have created
  // just now: its requests must have reached the server first (as Mesa's own requests on `dpy`
  // follow them), so a program needs no XSync of its own.
  XSync(dpy, False);
  std::string error;
  std::shared_ptr<glpt::X11WindowTarget> target = glpt::X11WindowTarget::create(
      DisplayString(dpy), static_cast<uint32_t>(x), glpt::glx::drawable_config(*config), &error);
  uint32_t w = 0, h = 0;
  if (!target || !target->query_size(&w, &h)) {
    if (!error.empty()) std::fprintf(stderr, "glpt: %s\n", error.c_str());
    glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadDrawable, x, minor);
    return nullptr;
  }
  std::lock_guard lock(state->mutex);
  state->window_targets[x] = target;
  return target;
}

// The target of X window or pixmap `x` for `ctx`, remembered among the context's recent ones.
glpt::WindowTarget* window_target(Display* dpy, GLXContext ctx, XID x, const Config* config,
                                  int minor) {
  auto it = ctx->windows.find(x);
  if (it != ctx->windows.end()) {
    it->second.last_use = ++ctx->uses;
    return it->second.target.get();
  }
  DisplayState* state = DisplayState::of(dpy);
  std::shared_ptr<glpt::X11WindowTarget> target =
      state ? shared_window_target(dpy, state, x, config, minor) : nullptr;
  if (!target) return nullptr;
  // Keep the few most recently used (the current one is never the oldest: it was just used).
  constexpr size_t kMaxCachedWindows = 4;
  if (ctx->windows.size() >= kMaxCachedWindows) {
    auto oldest = ctx->windows.begin();
    for (auto e = ctx->windows.begin(); e != ctx->windows.end(); ++e)
      if (e->second.last_use < oldest->second.last_use) oldest = e;
    if (ctx->gl.target == oldest->second.target.get()) ctx->gl.target = nullptr;
    ctx->windows.erase(oldest);
  }
  auto& entry = ctx->windows[x];
  entry.target = std::move(target);
  entry.last_use = ++ctx->uses;
  return entry.target.get();
}

bool make_current(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx, int minor) {
  DisplayState* state = DisplayState::of(dpy);
  if (state == nullptr) return false;
  XFlush(dpy);
  // GLX 1.4 3.3.7: a NULL context with drawables, or a context without both, is BadMatch.
  if (ctx == nullptr) {
    if (draw != None || read != None) {
      glpt::glx::send_x_error(dpy, BadMatch, draw != None ? draw : read, minor);
      return false;
    }
    release_current();
    return true;
  }
  if (!is_live(ctx)) {
    glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadContext, 0, minor);
    return false;
  }
  if (draw == None || read == None) {
    glpt::glx::send_x_error(dpy, BadMatch, None, minor);
    return false;
  }
  // Claimed for this thread before its targets are touched: a context current on another
  // thread is BadAccess (GLX 1.4 3.3.7).
  bool was_bound = false, busy = false;
  {
    std::lock_guard lock(contexts_mutex());
    busy = ctx->bound && ctx->bound_thread != std::this_thread::get_id();
    if (!busy) {
      was_bound = ctx->bound;
      ctx->bound = true;
      ctx->bound_thread = std::this_thread::get_id();
    }
  }
  if (busy) {
    glpt::glx::send_x_error(dpy, BadAccess, 0, minor);
    return false;
  }
  // The claim is given up again unless the context becomes current (a failure below, or an
  // exception such as an allocation failure on the way).
  struct Claim {
    GLXContext ctx;
    bool was_bound;
    bool kept = false;
    ~Claim() {
      if (kept || was_bound) return;
      std::lock_guard lock(contexts_mutex());
      ctx->bound = false;
    }
  } claim{ctx, was_bound};
  // The read drawable must be a drawable too; glpt reads from the draw drawable's buffers.
  GlxDrawable read_info;
  if (read != draw && !find_glx_drawable(state, read, &read_info)) {
    uint32_t w = 0, h = 0;
    glpt::WindowTarget* t = window_target(dpy, ctx, read, ctx->config, minor);
    if (t == nullptr || !t->query_size(&w, &h)) return false;
  }
  GlxDrawable info;
  glpt::WindowTarget* target = nullptr;
  std::shared_ptr<glpt::HeadlessTarget> pbuffer;
  if (find_glx_drawable(state, draw, &info)) {
    if (info.kind == DrawableKind::kPbuffer) {
      pbuffer = info.pbuffer;
      target = pbuffer.get();
    } else {
      target = window_target(dpy, ctx, info.x_drawable, info.config, minor);
    }
  } else {
    target = window_target(dpy, ctx, draw, ctx->config, minor);
  }
  if (target == nullptr) return false;
  GLXContext old = current_glx();
  if (old != ctx) release_current();
  ctx->display = dpy;
  ctx->drawable = draw;
  ctx->readable = read;
  ctx->pbuffer = std::move(pbuffer);
  glpt::bind_target_and_make_current(ctx->gl, target);
  claim.kept = true;
  return true;
}

// Whether the current context's drawable has a back buffer to swap.
bool current_target_double_buffered(GLXContext ctx) {
  return ctx->gl.target != nullptr && ctx->gl.target->config().double_buffered;
}

const Config* fbconfig(Display* dpy, GLXFBConfig config, int minor) {
  DisplayState* state = DisplayState::of(dpy);
  const Config* c = state ? state->validate(config) : nullptr;
  if (c == nullptr && dpy != nullptr)
    glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadFBConfig, 0, minor);
  return c;
}

XVisualInfo* visual_info(Display* dpy, int screen, int visual_id) {
  if (visual_id == 0) return nullptr;
  XVisualInfo templ{};
  templ.visualid = static_cast<VisualID>(visual_id);
  templ.screen = screen;
  int n = 0;
  return XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &templ, &n);
}

GLXFBConfig* config_list(const std::vector<const Config*>& configs, int* nelements) {
  if (configs.empty()) return nullptr;
  // Freed by the program with XFree, which is free().
  auto* out = static_cast<GLXFBConfig*>(std::malloc(sizeof(GLXFBConfig) * configs.size()));
  if (out == nullptr) return nullptr;
  for (size_t i = 0; i < configs.size(); ++i)
    out[i] = reinterpret_cast<GLXFBConfig>(const_cast<Config*>(configs[i]));
  *nelements = static_cast<int>(configs.size());
  return out;
}

// A new XID for a GLX drawable, from the program's connection's ID range as Mesa's are.
XID new_glx_drawable(Display* dpy, DisplayState* state, GlxDrawable drawable) {
  const XID id = glpt::glx::allocate_xid(dpy);
  std::lock_guard lock(state->mutex);
  state->drawables[id] = std::move(drawable);
  return id;
}

// glXCreateWindow / glXCreatePixmap: a GLX drawable over X drawable `x` for `config`, which must
// support `kind` (`type_bit`); an absent `x` is `missing_error`.
XID create_glx_drawable(Display* dpy, GLXFBConfig config, XID x, DrawableKind kind, int type_bit,
                        int missing_error, int minor) {
  const Config* c = fbconfig(dpy, config, minor);
  if (c == nullptr) return None;
  if (x == None) {
    glpt::glx::send_x_error(dpy, missing_error, x, minor);
    return None;
  }
  if ((c->drawable_type & type_bit) == 0) {
    glpt::glx::send_x_error(dpy, BadMatch, x, minor);
    return None;
  }
  GlxDrawable d;
  d.kind = kind;
  d.config = c;
  d.x_drawable = x;
  return new_glx_drawable(dpy, DisplayState::of(dpy), d);
}

bool destroy_glx_drawable(Display* dpy, XID id, DrawableKind kind, int error, int minor) {
  DisplayState* state = DisplayState::of(dpy);
  if (state == nullptr) return false;
  XID x_drawable = None;
  bool found = false;
  {
    std::lock_guard lock(state->mutex);
    auto it = state->drawables.find(id);
    if (it != state->drawables.end() && it->second.kind == kind) {
      x_drawable = it->second.x_drawable;
      state->drawables.erase(it);  // a current pbuffer lives on in its context until released
      state->swap_intervals.erase(id);
      found = true;
    }
  }
  // A GLX window dies with its X window (server-side in Mesa's GLX): destroying it afterwards
  // is GLXBadWindow, as there.
  uint32_t w = 0, h = 0;
  if (found && kind == DrawableKind::kWindow) {
    XSync(dpy, False);  // the program's XDestroyWindow first
    found = state->geometry(x_drawable, &w, &h);
  }
  if (found) return true;
  glpt::glx::send_glx_error(dpy, error, id, minor);
  return false;
}

constexpr const char kGlxExtensions[] =
    "GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address "
    "GLX_EXT_swap_control GLX_EXT_visual_info GLX_EXT_visual_rating GLX_MESA_swap_control "
    "GLX_SGI_make_current_read GLX_SGI_swap_control";

struct GlxProc {
  const char* name;
  __GLXextFuncPtr entry;
};
const GlxProc* glx_proc_table(size_t* count);

// The size of an X drawable (asked over glpt's own connection) or of a pbuffer.
bool drawable_size(DisplayState* state, GLXDrawable draw, uint32_t* w, uint32_t* h) {
  GlxDrawable info;
  if (find_glx_drawable(state, draw, &info)) {
    if (info.kind == DrawableKind::kPbuffer) return info.pbuffer->query_size(w, h);
    draw = info.x_drawable;
  }
  return state->geometry(draw, w, h);
}

}  // namespace

// Each entry point that can allocate runs through glx_entry (glx_display.hpp): no exception
// crosses the C ABI. Those that only return constants or read the current context
// (glXQueryVersion, glX*String, glXGetCurrent*, glXWaitX) cannot fail; glXMakeCurrentReadSGI,
// glXQueryServerString and glXGetProcAddress forward to guarded ones.
extern "C" {

GLPT_EXPORT XVisualInfo* glXChooseVisual(Display* dpy, int screen, int* attrib_list) {
  return glx_entry(dpy, kClientSide, static_cast<XVisualInfo*>(nullptr), [&]() -> XVisualInfo* {
    DisplayState* state = DisplayState::of(dpy);
    const glpt::glx::ScreenConfigs* configs = state ? state->screen(screen) : nullptr;
    if (configs == nullptr) return nullptr;
    // The best visual config (Mesa: the first of the best, in the server's order).
    const Config wanted = glpt::glx::chooser_template(attrib_list, /*fbconfig_style=*/false);
    const Config* best = nullptr;
    for (const Config& c : configs->visuals)
      if (glpt::glx::compatible(wanted, c) && (best == nullptr || glpt::glx::compare(c, *best) < 0))
        best = &c;
    return best ? visual_info(dpy, screen, best->visual_id) : nullptr;
  });
}

GLPT_EXPORT int glXGetConfig(Display* dpy, XVisualInfo* vis, int attrib, int* value) {
  return glx_entry(dpy, kClientSide, int{GLX_BAD_VALUE}, [&]() -> int {
    DisplayState* state = DisplayState::of(dpy);
    if (state == nullptr) return GLX_NO_EXTENSION;
    if (vis == nullptr || value == nullptr) return GLX_BAD_VALUE;
    if (state->screen(vis->screen) == nullptr) return GLX_BAD_SCREEN;
    const Config* c = state->visual_config(vis->screen, vis->visualid);
    if (c == nullptr) {
      // A visual without GLX: only GLX_USE_GL may be asked (it is False), as in Mesa.
      if (attrib != GLX_USE_GL) return GLX_BAD_VISUAL;
      *value = 0;
      return Success;
    }
    return glpt::glx::config_attribute(*c, attrib, value) ? Success : GLX_BAD_ATTRIBUTE;
  });
}

GLPT_EXPORT GLXFBConfig* glXGetFBConfigs(Display* dpy, int screen, int* nelements) {
  return glx_entry(dpy, kClientSide, static_cast<GLXFBConfig*>(nullptr), [&]() -> GLXFBConfig* {
    if (nelements) *nelements = 0;
    DisplayState* state = DisplayState::of(dpy);
    const glpt::glx::ScreenConfigs* configs = state ? state->screen(screen) : nullptr;
    if (configs == nullptr || nelements == nullptr) return nullptr;
    std::vector<const Config*> all;
    for (const Config& c : configs->fbconfigs) all.push_back(&c);
    return config_list(all, nelements);
  });
}

GLPT_EXPORT GLXFBConfig* glXChooseFBConfig(Display* dpy, int screen, const int* attrib_list,
                                           int* nelements) {
  return glx_entry(dpy, kClientSide, static_cast<GLXFBConfig*>(nullptr), [&]() -> GLXFBConfig* {
    if (nelements) *nelements = 0;
    DisplayState* state = DisplayState::of(dpy);
    const glpt::glx::ScreenConfigs* configs = state ? state->screen(screen) : nullptr;
    if (configs == nullptr || nelements == nullptr) return nullptr;
    std::vector<const Config*> chosen;
    for (const Config& c : configs->fbconfigs) chosen.push_back(&c);
    // Mesa returns every config, unsorted, for a NULL list.
    if (attrib_list != nullptr) {
      const Config wanted = glpt::glx::chooser_template(attrib_list, /*fbconfig_style=*/true);
      std::erase_if(chosen, [&](const Config* c) { return !glpt::glx::compatible(wanted, *c); });
      std::stable_sort(chosen.begin(), chosen.end(), [](const Config* a, const Config* b) {
        return glpt::glx::compare(*a, *b) < 0;
      });
    }
    return config_list(chosen, nelements);
  });
}

GLPT_EXPORT int glXGetFBConfigAttrib(Display* dpy, GLXFBConfig config, int attribute, int* value) {
  return glx_entry(dpy, kClientSide, int{GLX_BAD_VALUE}, [&]() -> int {
    DisplayState* state = DisplayState::of(dpy);
    const Config* c = state ? state->validate(config) : nullptr;
    if (c == nullptr) return 9;  // GLXBadFBConfig's code, returned as Mesa does
    if (value == nullptr) return GLX_BAD_VALUE;
    return glpt::glx::config_attribute(*c, attribute, value) ? Success : GLX_BAD_ATTRIBUTE;
  });
}

GLPT_EXPORT XVisualInfo* glXGetVisualFromFBConfig(Display* dpy, GLXFBConfig config) {
  return glx_entry(dpy, kClientSide, static_cast<XVisualInfo*>(nullptr), [&]() -> XVisualInfo* {
    DisplayState* state = DisplayState::of(dpy);
    const Config* c = state ? state->validate(config) : nullptr;
    return c ? visual_info(dpy, c->screen, c->visual_id) : nullptr;
  });
}

GLPT_EXPORT GLXContext glXCreateContext(Display* dpy, XVisualInfo* vis, GLXContext share_list,
                                        Bool direct) {
  return glx_entry(
      dpy, glpt::glx::kXGlxCreateContext, static_cast<GLXContext>(nullptr), [&]() -> GLXContext {
        (void)direct;
        DisplayState* state = DisplayState::of(dpy);
        if (state == nullptr) return nullptr;
        const Config* config = vis ? state->visual_config(vis->screen, vis->visualid) : nullptr;
        if (config == nullptr) {
          glpt::glx::send_x_error(dpy, BadValue, vis ? vis->visualid : 0,
                                  glpt::glx::kXGlxCreateContext);
          return nullptr;
        }
        return create_context(dpy, config, share_list, glpt::glx::kXGlxCreateContext);
      });
}

GLPT_EXPORT GLXContext glXCreateNewContext(Display* dpy, GLXFBConfig config, int render_type,
                                           GLXContext share_list, Bool direct) {
  return glx_entry(dpy, glpt::glx::kXGlxCreateNewContext, static_cast<GLXContext>(nullptr),
                   [&]() -> GLXContext {
                     (void)direct;
                     const Config* c = fbconfig(dpy, config, glpt::glx::kXGlxCreateNewContext);
                     if (c == nullptr) return nullptr;
                     if (render_type != GLX_RGBA_TYPE) {
                       // Colour index included (glpt's configs are RGBA only): BadValue, as Mesa
                       // reports it.
                       glpt::glx::send_x_error(dpy, BadValue, static_cast<XID>(render_type),
                                               glpt::glx::kXGlxCreateNewContext);
                       return nullptr;
                     }
                     return create_context(dpy, c, share_list, glpt::glx::kXGlxCreateNewContext);
                   });
}

GLPT_EXPORT GLXContext glXCreateContextAttribsARB(Display* dpy, GLXFBConfig config,
                                                  GLXContext share_context, Bool direct,
                                                  const int* attrib_list) {
  return glx_entry(
      dpy, glpt::glx::kXGlxCreateContextAttribsArb, static_cast<GLXContext>(nullptr),
      [&]() -> GLXContext {
        (void)direct;
        constexpr int kMinor = glpt::glx::kXGlxCreateContextAttribsArb;
        const Config* c = fbconfig(dpy, config, kMinor);
        if (c == nullptr) return nullptr;
        int major = 1, minor = 0, render_type = GLX_RGBA_TYPE, flags = 0;
        int profile = GLX_CONTEXT_CORE_PROFILE_BIT_ARB;
        constexpr int kAllFlags = GLX_CONTEXT_DEBUG_BIT_ARB |
                                  GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB |
                                  0x4 /* GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB */;
        for (int i = 0; attrib_list && attrib_list[i] != None; i += 2) {
          const int value = attrib_list[i + 1];
          switch (attrib_list[i]) {
            case GLX_CONTEXT_MAJOR_VERSION_ARB:
              major = value;
              break;
            case GLX_CONTEXT_MINOR_VERSION_ARB:
              minor = value;
              break;
            case GLX_CONTEXT_PROFILE_MASK_ARB:
              profile = value;
              break;
            case GLX_RENDER_TYPE:
              render_type = value;
              break;
            case GLX_CONTEXT_FLAGS_ARB:
              flags = value;
              break;
            default:
              // GLX_ARB_create_context: an attribute it does not define is BadValue.
              glpt::glx::send_x_error(dpy, BadValue, static_cast<XID>(attrib_list[i]), 0);
              return nullptr;
          }
        }
        // The errors below are Mesa's choices, reported as Mesa does (minor code 0: found on the
        // client side). GLX_ARB_create_context: unknown flag bits are BadValue; a version GL never
        // defined or forward-compatibility before 3.0 is BadMatch. GLX_ARB_create_context_profile:
        // no profile bit, an unknown one or both is GLXBadProfileARB, whatever the version (as Mesa
        // checks it). Colour index (no such configs) and unknown render types are BadValue.
        const int profile_bits =
            GLX_CONTEXT_CORE_PROFILE_BIT_ARB | GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
        if ((flags & ~kAllFlags) != 0 || render_type != GLX_RGBA_TYPE) {
          glpt::glx::send_x_error(dpy, BadValue, 0, 0);
          return nullptr;
        }
        const bool defined =
            (major == 1 && minor >= 0 && minor <= 5) || (major == 2 && minor >= 0 && minor <= 1) ||
            (major == 3 && minor >= 0 && minor <= 3) || (major == 4 && minor >= 0 && minor <= 6);
        if (!defined || ((flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB) && major < 3)) {
          glpt::glx::send_x_error(dpy, BadMatch, 0, 0);
          return nullptr;
        }
        if (profile == 0 || (profile & ~profile_bits) != 0 || profile == profile_bits) {
          glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadProfileArb, 0, 0);
          return nullptr;
        }
        // glpt is an OpenGL 1.5 implementation: later versions are configs it cannot serve.
        if (major > 1) {
          glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadFBConfig, 0, kMinor);
          return nullptr;
        }
        return create_context(dpy, c, share_context, kMinor);
      });
}

GLPT_EXPORT void glXDestroyContext(Display* dpy, GLXContext ctx) {
  glx_entry_void(dpy, glpt::glx::kXGlxDestroyContext, [&] {
    if (ctx == nullptr) return;
    bool live = false, destroy_now = false;
    {
      std::lock_guard lock(contexts_mutex());
      live = live_contexts().count(ctx) != 0;
      if (live && ctx->bound) {
        ctx->destroy_when_released = true;  // GLX 1.4 3.3.7: once no thread has it current
      } else if (live) {
        live_contexts().erase(ctx);
        destroy_now = true;
      }
    }
    if (!live && dpy != nullptr)
      glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadContext, 0, glpt::glx::kXGlxDestroyContext);
    if (destroy_now) delete ctx;
  });
}

GLPT_EXPORT Bool glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext ctx) {
  return glx_entry(dpy, glpt::glx::kXGlxMakeCurrent, Bool{False}, [&]() -> Bool {
    return make_current(dpy, drawable, drawable, ctx, glpt::glx::kXGlxMakeCurrent) ? True : False;
  });
}

GLPT_EXPORT Bool glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read,
                                       GLXContext ctx) {
  return glx_entry(dpy, glpt::glx::kXGlxMakeContextCurrent, Bool{False}, [&]() -> Bool {
    return make_current(dpy, draw, read, ctx, glpt::glx::kXGlxMakeContextCurrent) ? True : False;
  });
}

GLPT_EXPORT Bool glXMakeCurrentReadSGI(Display* dpy, GLXDrawable draw, GLXDrawable read,
                                       GLXContext ctx) {
  return glXMakeContextCurrent(dpy, draw, read, ctx);
}

namespace {

// The drawable's size asked on the program's connection (so after its requests); false if the
// drawable is gone or not a drawable (the error is consumed here).
bool size_after_program_requests(Display* dpy, GLXDrawable drawable, uint32_t* width,
                                 uint32_t* height) {
  return glpt::glx::drawable_geometry(XGetXCBConnection(dpy), drawable, width, height);
}

}  // namespace

GLPT_EXPORT void glXSwapBuffers(Display* dpy, GLXDrawable drawable) {
  glpt::glx::gl_work_entry([&] {
    if (dpy == nullptr) return;
    // The program's X requests (a resize, its own drawing) are done before glpt's connection
    // draws, and the frame has the window's size after them: Mesa's swap makes its requests on
    // `dpy`, after the program's. One round trip there does both (the size asked through `dpy`'s
    // XCB connection, whose errors come back here, not to the program's error handler).
    uint32_t width = 0, height = 0;
    const bool sized =
        drawable != None && size_after_program_requests(dpy, drawable, &width, &height);
    if (!sized) XSync(dpy, False);
    if (drawable == None) {
      glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadDrawable, drawable,
                                glpt::glx::kXGlxSwapBuffers);
      return;
    }
    GLXContext ctx = current_glx();
    // Swapping a drawable that is not current here has no GL work of this thread to show.
    if (ctx == nullptr || ctx->drawable != drawable) return;
    GlxDrawable info;
    if (find_glx_drawable(DisplayState::of(dpy), drawable, &info) &&
        info.kind == DrawableKind::kPixmap)
      return;  // GLX 1.4 3.3.10: no effect on a pixmap
    if (sized && ctx->gl.target != nullptr) ctx->gl.target->assume_size(width, height);
    // A single-buffered window has nothing to swap; what was drawn is flushed to it, as Mesa's
    // swap flushes the context.
    glpt::end_frame(ctx->gl, /*swap=*/current_target_double_buffered(ctx));
  });
}

GLPT_EXPORT const char* glXQueryExtensionsString(Display* dpy, int screen) {
  (void)dpy;
  (void)screen;
  return kGlxExtensions;
}

GLPT_EXPORT const char* glXGetClientString(Display* dpy, int name) {
  (void)dpy;
  switch (name) {
    case GLX_VENDOR:
      return "glpt";
    case GLX_VERSION:
      return "1.4";
    case GLX_EXTENSIONS:
      return kGlxExtensions;
    default:
      return nullptr;
  }
}

GLPT_EXPORT const char* glXQueryServerString(Display* dpy, int screen, int name) {
  (void)screen;
  return glXGetClientString(dpy, name);
}

GLPT_EXPORT Bool glXQueryExtension(Display* dpy, int* error_base, int* event_base) {
  return glx_entry(dpy, kClientSide, Bool{False}, [&]() -> Bool {
    DisplayState* state = DisplayState::of(dpy);
    if (state == nullptr) return False;
    if (error_base) *error_base = state->glx_error_base();
    if (event_base) *event_base = state->glx_event_base();
    return True;
  });
}

GLPT_EXPORT Bool glXQueryVersion(Display* dpy, int* major, int* minor) {
  if (dpy == nullptr) return False;
  if (major) *major = 1;
  if (minor) *minor = 4;
  return True;
}

GLPT_EXPORT Bool glXIsDirect(Display* dpy, GLXContext ctx) {
  return glx_entry(dpy, glpt::glx::kXGlxIsDirect, Bool{False}, [&]() -> Bool {
    if (!is_live(ctx)) {
      if (dpy && ctx) glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadContext, 0, 6);
      return False;
    }
    return True;
  });
}

GLPT_EXPORT GLXContext glXGetCurrentContext(void) { return current_glx(); }

GLPT_EXPORT GLXDrawable glXGetCurrentDrawable(void) {
  GLXContext ctx = current_glx();
  return ctx ? ctx->drawable : None;
}

GLPT_EXPORT GLXDrawable glXGetCurrentReadDrawable(void) {
  GLXContext ctx = current_glx();
  return ctx ? ctx->readable : None;
}

GLPT_EXPORT GLXDrawable glXGetCurrentReadDrawableSGI(void) { return glXGetCurrentReadDrawable(); }

GLPT_EXPORT Display* glXGetCurrentDisplay(void) {
  GLXContext ctx = current_glx();
  return ctx ? ctx->display : nullptr;
}

GLPT_EXPORT int glXQueryContext(Display* dpy, GLXContext ctx, int attribute, int* value) {
  return glx_entry(dpy, kClientSide, int{GLX_BAD_CONTEXT}, [&]() -> int {
    (void)dpy;
    if (!is_live(ctx) || value == nullptr) return GLX_BAD_CONTEXT;
    switch (attribute) {
      case GLX_FBCONFIG_ID:
        *value = ctx->config->fbconfig_id;
        return Success;
      case GLX_RENDER_TYPE:
        *value = GLX_RGBA_TYPE;
        return Success;
      case GLX_SCREEN:
        *value = ctx->screen;
        return Success;
      case 0x800B:  // GLX_VISUAL_ID_EXT
        *value = ctx->config->visual_id;
        return Success;
      case 0x800A:  // GLX_SHARE_CONTEXT_EXT: contexts have no server XID
        *value = 0;
        return Success;
      default:
        return GLX_BAD_ATTRIBUTE;
    }
  });
}

GLPT_EXPORT GLXWindow glXCreateWindow(Display* dpy, GLXFBConfig config, Window win,
                                      const int* attrib_list) {
  return glx_entry(dpy, glpt::glx::kXGlxCreateWindow, GLXWindow{None}, [&]() -> GLXWindow {
    (void)attrib_list;  // GLX 1.4 defines no attributes for windows
    return create_glx_drawable(dpy, config, win, DrawableKind::kWindow, GLX_WINDOW_BIT, BadWindow,
                               glpt::glx::kXGlxCreateWindow);
  });
}

GLPT_EXPORT void glXDestroyWindow(Display* dpy, GLXWindow win) {
  glx_entry_void(dpy, glpt::glx::kXGlxDestroyWindow, [&] {
    destroy_glx_drawable(dpy, win, DrawableKind::kWindow, glpt::glx::kGlxBadWindow,
                         glpt::glx::kXGlxDestroyWindow);
  });
}

GLPT_EXPORT GLXPixmap glXCreatePixmap(Display* dpy, GLXFBConfig config, Pixmap pixmap,
                                      const int* attrib_list) {
  return glx_entry(dpy, glpt::glx::kXGlxCreatePixmap, GLXPixmap{None}, [&]() -> GLXPixmap {
    (void)attrib_list;  // GLX 1.4 defines no attributes for pixmaps
    return create_glx_drawable(dpy, config, pixmap, DrawableKind::kPixmap, GLX_PIXMAP_BIT,
                               BadPixmap, glpt::glx::kXGlxCreatePixmap);
  });
}

GLPT_EXPORT void glXDestroyPixmap(Display* dpy, GLXPixmap pixmap) {
  glx_entry_void(dpy, glpt::glx::kXGlxDestroyPixmap, [&] {
    destroy_glx_drawable(dpy, pixmap, DrawableKind::kPixmap, glpt::glx::kGlxBadPixmap,
                         glpt::glx::kXGlxDestroyPixmap);
  });
}

GLPT_EXPORT GLXPixmap glXCreateGLXPixmap(Display* dpy, XVisualInfo* vis, Pixmap pixmap) {
  return glx_entry(dpy, glpt::glx::kXGlxCreateGLXPixmap, GLXPixmap{None}, [&]() -> GLXPixmap {
    DisplayState* state = DisplayState::of(dpy);
    if (state == nullptr) return None;
    const Config* c = vis ? state->visual_config(vis->screen, vis->visualid) : nullptr;
    if (c == nullptr) {
      glpt::glx::send_x_error(dpy, BadValue, vis ? vis->visualid : 0,
                              glpt::glx::kXGlxCreateGLXPixmap);
      return None;
    }
    if (pixmap == None) {
      glpt::glx::send_x_error(dpy, BadPixmap, pixmap, glpt::glx::kXGlxCreateGLXPixmap);
      return None;
    }
    GlxDrawable d;
    d.kind = DrawableKind::kPixmap;
    d.config = c;
    d.x_drawable = pixmap;
    return new_glx_drawable(dpy, state, d);
  });
}

GLPT_EXPORT void glXDestroyGLXPixmap(Display* dpy, GLXPixmap pixmap) {
  glx_entry_void(dpy, glpt::glx::kXGlxDestroyGLXPixmap, [&] {
    destroy_glx_drawable(dpy, pixmap, DrawableKind::kPixmap, glpt::glx::kGlxBadPixmap,
                         glpt::glx::kXGlxDestroyGLXPixmap);
  });
}

GLPT_EXPORT GLXPbuffer glXCreatePbuffer(Display* dpy, GLXFBConfig config, const int* attrib_list) {
  return glx_entry(dpy, glpt::glx::kXGlxCreatePbuffer, GLXPbuffer{None}, [&]() -> GLXPbuffer {
    constexpr int kMinor = glpt::glx::kXGlxCreatePbuffer;
    const Config* c = fbconfig(dpy, config, kMinor);
    if (c == nullptr) return None;
    if ((c->drawable_type & GLX_PBUFFER_BIT) == 0) {
      glpt::glx::send_x_error(dpy, BadMatch, 0, kMinor);
      return None;
    }
    int width = 0, height = 0;
    GlxDrawable d;
    d.kind = DrawableKind::kPbuffer;
    d.config = c;
    for (int i = 0; attrib_list && attrib_list[i] != None; i += 2) {
      const int value = attrib_list[i + 1];
      switch (attrib_list[i]) {
        case GLX_PBUFFER_WIDTH:
          width = value;
          break;
        case GLX_PBUFFER_HEIGHT:
          height = value;
          break;
        case GLX_PRESERVED_CONTENTS:  // contents are always preserved
          break;
        case GLX_LARGEST_PBUFFER:
          d.largest_pbuffer = value != 0;
          break;
        default:
          glpt::glx::send_x_error(dpy, BadValue, static_cast<XID>(attrib_list[i]), kMinor);
          return None;
      }
    }
    int max_size = 0;
    glpt::glx::config_attribute(*c, GLX_MAX_PBUFFER_WIDTH, &max_size);
    if (width < 0 || height < 0) {
      glpt::glx::send_x_error(dpy, BadValue, 0, kMinor);
      return None;
    }
    if (width > max_size || height > max_size) {
      if (!d.largest_pbuffer) {
        glpt::glx::send_x_error(dpy, BadAlloc, 0, kMinor);
        return None;
      }
      width = std::min(width, max_size);
      height = std::min(height, max_size);
    }
    d.pbuffer = std::make_shared<glpt::HeadlessTarget>(static_cast<uint32_t>(width),
                                                       static_cast<uint32_t>(height),
                                                       glpt::glx::drawable_config(*c));
    return new_glx_drawable(dpy, DisplayState::of(dpy), d);
  });
}

GLPT_EXPORT void glXDestroyPbuffer(Display* dpy, GLXPbuffer pbuf) {
  glx_entry_void(dpy, glpt::glx::kXGlxDestroyPbuffer, [&] {
    destroy_glx_drawable(dpy, pbuf, DrawableKind::kPbuffer, glpt::glx::kGlxBadPbuffer,
                         glpt::glx::kXGlxDestroyPbuffer);
  });
}

GLPT_EXPORT void glXSelectEvent(Display* dpy, GLXDrawable draw, unsigned long event_mask) {
  glx_entry_void(dpy, glpt::glx::kXGlxChangeDrawableAttributes, [&] {
    DisplayState* state = DisplayState::of(dpy);
    if (state == nullptr) return;
    std::lock_guard lock(state->mutex);
    auto it = state->drawables.find(draw);
    if (it == state->drawables.end()) {
      glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadDrawable, draw, 0);
      return;
    }
    it->second.event_mask = event_mask;
  });
}

GLPT_EXPORT void glXGetSelectedEvent(Display* dpy, GLXDrawable draw, unsigned long* event_mask) {
  glx_entry_void(dpy, glpt::glx::kXGlxGetDrawableAttributes, [&] {
    DisplayState* state = DisplayState::of(dpy);
    if (state == nullptr || event_mask == nullptr) return;
    std::lock_guard lock(state->mutex);
    auto it = state->drawables.find(draw);
    if (it == state->drawables.end()) {
      glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadDrawable, draw, 0);
      return;
    }
    *event_mask = it->second.event_mask;
  });
}

GLPT_EXPORT void glXQueryDrawable(Display* dpy, GLXDrawable draw, int attribute,
                                  unsigned int* value) {
  glx_entry_void(dpy, glpt::glx::kXGlxGetDrawableAttributes, [&] {
    constexpr int kMinor = glpt::glx::kXGlxGetDrawableAttributes;
    DisplayState* state = DisplayState::of(dpy);
    if (state == nullptr || value == nullptr) return;
    if (draw == None) {
      glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadDrawable, draw, kMinor);
      return;
    }
    XSync(dpy, False);  // Mesa asks on `dpy`, after the program's own requests
    GlxDrawable info;
    const bool glx_drawable = find_glx_drawable(state, draw, &info);
    GLXContext ctx = current_glx();
    const Config* config = glx_drawable                     ? info.config
                           : (ctx && ctx->drawable == draw) ? ctx->config
                                                            : nullptr;
    switch (attribute) {
      case GLX_WIDTH:
      case GLX_HEIGHT: {
        uint32_t w = 0, h = 0;
        if (!drawable_size(state, draw, &w, &h)) {
          glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadDrawable, draw, kMinor);
          return;
        }
        *value = attribute == GLX_WIDTH ? w : h;
        return;
      }
      case GLX_PRESERVED_CONTENTS:
        // A pbuffer's contents are always kept (its buffers are the context's own), so it says
        // True whatever was asked, as Mesa on Xvfb does.
        *value = glx_drawable && info.kind == DrawableKind::kPbuffer ? 1 : 0;
        return;
      case GLX_LARGEST_PBUFFER:
        *value = glx_drawable && info.kind == DrawableKind::kPbuffer ? info.largest_pbuffer : 0;
        return;
      case GLX_FBCONFIG_ID:
        // A plain X window answers the FBConfig of its visual (a context made from a visual has
        // the visual's config, which has no FBConfig id), as Mesa does.
        if (config != nullptr && !glx_drawable && config->fbconfig_id == glpt::glx::kDontCare)
          config = state->fbconfig_for_visual(config->screen, config->visual_id);
        *value = config ? static_cast<unsigned>(config->fbconfig_id) : 0;
        return;
      case GLX_EVENT_MASK:
        *value = glx_drawable ? static_cast<unsigned>(info.event_mask) : 0;
        return;
      case GLX_SWAP_INTERVAL_EXT: {
        std::lock_guard lock(state->mutex);
        auto it = state->swap_intervals.find(draw);
        *value = it == state->swap_intervals.end() ? 1u : static_cast<unsigned>(it->second);
        return;
      }
      case GLX_MAX_SWAP_INTERVAL_EXT:
        *value = INT_MAX;
        return;
      default:
        glpt::glx::send_x_error(dpy, BadValue, static_cast<XID>(attribute), kMinor);
        return;
    }
  });
}

// glXWaitGL: what GL drew, and the frames swapped, reach the window before later X rendering,
// as glFinish makes it (a swapped frame may still be on its way: GLPT_PRESENT=later). glXWaitX: the
// program's X requests are done (Mesa: XSync).
GLPT_EXPORT void glXWaitGL(void) {
  glpt::glx::gl_work_entry([&] {
    if (current_glx() != nullptr) glpt::impl::glFinish(*glpt::current_context());
  });
}

GLPT_EXPORT void glXWaitX(void) {
  GLXContext ctx = current_glx();
  if (ctx != nullptr && ctx->display != nullptr) XSync(ctx->display, False);
}

// glXCopyContext (GLX 1.4 3.3.7): the attribute groups of `mask` go from `src` to `dst` as if
// glPushAttrib(mask) on `src` were popped on `dst`.
GLPT_EXPORT void glXCopyContext(Display* dpy, GLXContext src, GLXContext dst, unsigned long mask) {
  glx_entry_void(dpy, glpt::glx::kXGlxCopyContext, [&] {
    constexpr int kMinor = glpt::glx::kXGlxCopyContext;
    if (dpy == nullptr) return;
    if (!is_live(src) || !is_live(dst)) {
      glpt::glx::send_glx_error(dpy, glpt::glx::kGlxBadContext, 0, kMinor);
      return;
    }
    bool dst_bound = false;
    {
      std::lock_guard lock(contexts_mutex());
      dst_bound = dst->bound;
    }
    if (dst_bound) {
      glpt::glx::send_x_error(dpy, BadAccess, 0, kMinor);  // the destination may not be current
      return;
    }
    if (src == dst || src->screen != dst->screen) {
      glpt::glx::send_x_error(dpy, BadMatch, 0, kMinor);
      return;
    }
    glpt::copy_attrib_groups(src->gl, dst->gl, static_cast<GLbitfield>(mask));
  });
}

// GLX_EXT_swap_control, GLX_MESA_swap_control, GLX_SGI_swap_control: intervals are remembered
// per drawable and answered; glpt presents each swap at once (no vsync to wait for).
GLPT_EXPORT void glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval) {
  glx_entry_void(dpy, glpt::glx::kXGlxVendorPrivate, [&] {
    DisplayState* state = DisplayState::of(dpy);
    if (state == nullptr) return;
    if (drawable == None) {
      glpt::glx::send_x_error(dpy, BadWindow, drawable, 0);
      return;
    }
    if (interval < 0) {  // no GLX_EXT_swap_control_tear
      glpt::glx::send_x_error(dpy, BadValue, static_cast<XID>(interval), 0);
      return;
    }
    std::lock_guard lock(state->mutex);
    state->swap_intervals[drawable] = interval;
  });
}

GLPT_EXPORT int glXSwapIntervalMESA(unsigned int interval) {
  return glx_entry(nullptr, kClientSide, int{GLX_BAD_CONTEXT}, [&]() -> int {
    if (interval > INT_MAX) return GLX_BAD_VALUE;
    GLXContext ctx = current_glx();
    if (ctx == nullptr) return GLX_BAD_CONTEXT;
    DisplayState* state = DisplayState::of(ctx->display);
    std::lock_guard lock(state->mutex);
    state->swap_intervals[ctx->drawable] = static_cast<int>(interval);
    return 0;
  });
}

GLPT_EXPORT int glXGetSwapIntervalMESA(void) {
  return glx_entry(nullptr, kClientSide, 0, [&]() -> int {
    GLXContext ctx = current_glx();
    if (ctx == nullptr) return 0;
    DisplayState* state = DisplayState::of(ctx->display);
    std::lock_guard lock(state->mutex);
    auto it = state->swap_intervals.find(ctx->drawable);
    return it == state->swap_intervals.end() ? 1 : it->second;
  });
}

GLPT_EXPORT int glXSwapIntervalSGI(int interval) {
  return glx_entry(nullptr, kClientSide, int{GLX_BAD_CONTEXT}, [&]() -> int {
    GLXContext ctx = current_glx();
    if (ctx == nullptr) return GLX_BAD_CONTEXT;
    if (interval <= 0) return GLX_BAD_VALUE;
    DisplayState* state = DisplayState::of(ctx->display);
    std::lock_guard lock(state->mutex);
    state->swap_intervals[ctx->drawable] = interval;
    return 0;
  });
}

GLPT_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name) {
  return glx_entry(nullptr, kClientSide, __GLXextFuncPtr{nullptr}, [&]() -> __GLXextFuncPtr {
    if (name == nullptr) return nullptr;
    const char* n = reinterpret_cast<const char*>(name);
    if (std::strncmp(n, "glX", 3) == 0) {
      size_t count = 0;
      const GlxProc* table = glx_proc_table(&count);
      for (size_t i = 0; i < count; ++i)
        if (std::strcmp(table[i].name, n) == 0) return table[i].entry;
      return nullptr;
    }
    return glpt::lookup_gl_proc(n);
  });
}

GLPT_EXPORT __GLXextFuncPtr glXGetProcAddress(const GLubyte* name) {
  return glXGetProcAddressARB(name);
}

}  // extern "C"

namespace {

#define GLPT_GLX_PROC(name) \
  { #name, reinterpret_cast < __GLXextFuncPtr>(&name) }
const GlxProc* glx_proc_table(size_t* count) {
  static const GlxProc table[] = {
      GLPT_GLX_PROC(glXChooseVisual),
      GLPT_GLX_PROC(glXGetConfig),
      GLPT_GLX_PROC(glXGetFBConfigs),
      GLPT_GLX_PROC(glXChooseFBConfig),
      GLPT_GLX_PROC(glXGetFBConfigAttrib),
      GLPT_GLX_PROC(glXGetVisualFromFBConfig),
      GLPT_GLX_PROC(glXCreateContext),
      GLPT_GLX_PROC(glXCreateNewContext),
      GLPT_GLX_PROC(glXCreateContextAttribsARB),
      GLPT_GLX_PROC(glXDestroyContext),
      GLPT_GLX_PROC(glXMakeCurrent),
      GLPT_GLX_PROC(glXMakeContextCurrent),
      GLPT_GLX_PROC(glXMakeCurrentReadSGI),
      GLPT_GLX_PROC(glXSwapBuffers),
      GLPT_GLX_PROC(glXQueryExtensionsString),
      GLPT_GLX_PROC(glXGetClientString),
      GLPT_GLX_PROC(glXQueryServerString),
      GLPT_GLX_PROC(glXQueryExtension),
      GLPT_GLX_PROC(glXQueryVersion),
      GLPT_GLX_PROC(glXIsDirect),
      GLPT_GLX_PROC(glXGetCurrentContext),
      GLPT_GLX_PROC(glXGetCurrentDrawable),
      GLPT_GLX_PROC(glXGetCurrentReadDrawable),
      GLPT_GLX_PROC(glXGetCurrentReadDrawableSGI),
      GLPT_GLX_PROC(glXGetCurrentDisplay),
      GLPT_GLX_PROC(glXQueryContext),
      GLPT_GLX_PROC(glXCreateWindow),
      GLPT_GLX_PROC(glXDestroyWindow),
      GLPT_GLX_PROC(glXCreatePixmap),
      GLPT_GLX_PROC(glXDestroyPixmap),
      GLPT_GLX_PROC(glXCreateGLXPixmap),
      GLPT_GLX_PROC(glXDestroyGLXPixmap),
      GLPT_GLX_PROC(glXCreatePbuffer),
      GLPT_GLX_PROC(glXDestroyPbuffer),
      GLPT_GLX_PROC(glXSelectEvent),
      GLPT_GLX_PROC(glXGetSelectedEvent),
      GLPT_GLX_PROC(glXQueryDrawable),
      GLPT_GLX_PROC(glXWaitGL),
      GLPT_GLX_PROC(glXWaitX),
      GLPT_GLX_PROC(glXCopyContext),
      GLPT_GLX_PROC(glXUseXFont),
      GLPT_GLX_PROC(glXSwapIntervalEXT),
      GLPT_GLX_PROC(glXSwapIntervalMESA),
      GLPT_GLX_PROC(glXGetSwapIntervalMESA),
      GLPT_GLX_PROC(glXSwapIntervalSGI),
      GLPT_GLX_PROC(glXGetProcAddressARB),
      GLPT_GLX_PROC(glXGetProcAddress),
  };
  *count = sizeof(table) / sizeof(table[0]);
  return table;
}
#undef GLPT_GLX_PROC

}  // namespace
