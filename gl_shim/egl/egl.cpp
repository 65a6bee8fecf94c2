// EGL 1.5 for desktop OpenGL (EGL_OPENGL_API only): displays on X11 (EGL_KHR_platform_x11) and
// surfaceless (EGL_MESA_platform_surfaceless), configs (egl_configs.hpp), contexts wrapping a
// glpt::Context, window surfaces presenting through X11WindowTarget (as GLX) and pbuffers on a
// HeadlessTarget. Exported by libGL.so.1; glpt's libEGL.so.1 is a filter on it.
//
// EGL's own state: the displays (EGL display handles live as long as the process), the objects
// created on them, and per thread the last error and the bound API. One mutex guards the
// objects; the current context is glpt's own (glpt::current_context).
#define EGL_EGLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "gl_shim/c_abi_guard.hpp"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/egl/egl_configs.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/glx/x11_window_target.hpp"
#include "gl_shim/process_owner.hpp"

extern "C" GLPT_EXPORT void glFlush(void);

namespace {

struct EglDisplay;
struct EglSurface;

struct EglContext {
  EglContext(EglDisplay* d, const glpt::egl::Config& c, const EglContext* share, EGLint major,
             EGLint minor)
      : display(d), config(c), gl(share ? &share->gl : nullptr), major(major), minor(minor) {
    gl.window_system_context = this;
    gl.window_system = glpt::WindowSystem::kEgl;
  }
  EglDisplay* display;
  glpt::egl::Config config;
  glpt::Context gl;
  EGLint major, minor;
  bool live = true;      // false once destroyed (or its display terminated)
  bool current = false;  // current to some thread
  EglSurface* draw = nullptr;
  EglSurface* read = nullptr;
};

struct EglSurface {
  EglDisplay* display = nullptr;
  glpt::egl::Config config;
  EGLint type = EGL_WINDOW_BIT;  // or EGL_PBUFFER_BIT
  EGLint render_buffer = EGL_BACK_BUFFER;
  uint32_t window = 0;
  std::unique_ptr<glpt::X11WindowTarget> window_target;
  std::unique_ptr<glpt::HeadlessTarget> pbuffer_target;
  EGLint width = 0, height = 0;  // of a pbuffer
  bool largest_pbuffer = false;
  EGLint swap_interval = 1;
  bool live = true;
  int bindings = 0;  // contexts it is current to (as draw or read surface)

  glpt::WindowTarget* target() {
    if (window_target) return window_target.get();
    return pbuffer_target.get();
  }
};

struct EglDisplay {
  EGLenum platform = EGL_PLATFORM_X11_KHR;
  Display* native = nullptr;  // the program's, or null: the default display
  Display* opened = nullptr;  // opened by glpt for the default display, never closed
  int screen = 0;
  bool initialized = false;
  std::vector<glpt::egl::Config> configs;
  std::vector<std::unique_ptr<EglContext>> contexts;
  std::vector<std::unique_ptr<EglSurface>> surfaces;

  Display* x11() const { return native ? native : opened; }
};

// ---- EGL's process and thread state ------------------------------------------------------------

std::mutex& objects_mutex() {
  static std::mutex m;
  return m;
}

// Every display, destroyed at exit, but not by a forked child exiting without exec
// (process_owner.hpp): the child leaks them.
class DisplayRegistry {
 public:
  ~DisplayRegistry() {
    if (owner_.is_this_process()) return;
    for (auto& d : all) static_cast<void>(d.release());
  }
  std::vector<std::unique_ptr<EglDisplay>> all;

 private:
  glpt::ProcessOwner owner_;
};

std::vector<std::unique_ptr<EglDisplay>>& displays() {
  static DisplayRegistry registry;
  return registry.all;
}

thread_local EGLint t_error = EGL_SUCCESS;
// The EGL context this thread made current (glXMakeCurrent may have replaced it since).
thread_local EglContext* t_bound = nullptr;
// EGL 1.5 3.7: the initial API is OpenGL ES where supported, else EGL_NONE.
thread_local EGLenum t_api = EGL_NONE;

template <typename T>
T fail(EGLint error, T result) {
  t_error = error;
  return result;
}

EGLBoolean succeed() {
  t_error = EGL_SUCCESS;
  return EGL_TRUE;
}

// An entry point's body: an exception (allocation failure) becomes EGL_BAD_ALLOC and the
// function's `failure` value instead of crossing the C ABI (c_abi_guard.hpp).
template <typename Result, typename Body>
Result egl_entry(Result failure, Body&& body) noexcept {
  return glpt::guard_c_abi(
      failure, [] { t_error = EGL_BAD_ALLOC; }, std::forward<Body>(body));
}

EglContext* current_egl() {
  glpt::Context* gl = glpt::current_context();
  if (gl == nullptr || gl->window_system != glpt::WindowSystem::kEgl) return nullptr;
  return static_cast<EglContext*>(gl->window_system_context);
}

EglDisplay* find_display(EGLDisplay handle) {
  for (auto& d : displays())
    if (d.get() == handle) return d.get();
  return nullptr;
}

// The display for a handle, which must be initialized. Sets the error otherwise.
EglDisplay* initialized_display(EGLDisplay handle) {
  EglDisplay* d = find_display(handle);
  if (d == nullptr) return fail<EglDisplay*>(EGL_BAD_DISPLAY, nullptr);
  if (!d->initialized) return fail<EglDisplay*>(EGL_NOT_INITIALIZED, nullptr);
  return d;
}

// EGLConfig handles are the 1-based config id: nothing to dereference for a stale pointer.
const glpt::egl::Config* find_config(EglDisplay* d, EGLConfig handle) {
  const auto id = reinterpret_cast<uintptr_t>(handle);
  if (id == 0 || id > d->configs.size()) return nullptr;
  return &d->configs[id - 1];
}

EGLConfig config_handle(const glpt::egl::Config& c) {
  return reinterpret_cast<EGLConfig>(static_cast<uintptr_t>(c.id));
}

EglContext* find_context(EglDisplay* d, EGLContext handle) {
  for (auto& c : d->contexts)
    if (c.get() == handle && c->live) return c.get();
  return nullptr;
}

EglSurface* find_surface(EglDisplay* d, EGLSurface handle) {
  for (auto& s : d->surfaces)
    if (s.get() == handle && s->live) return s.get();
  return nullptr;
}

// Frees destroyed objects nothing is current to any more.
void collect(EglDisplay* d) {
  std::erase_if(d->surfaces, [](const auto& s) { return !s->live && s->bindings == 0; });
  std::erase_if(d->contexts, [](const auto& c) { return !c->live && !c->current; });
}

// Makes nothing current on this thread, releasing the EGL context that was.
void release_current_locked() {
  if (current_egl() != nullptr) glpt::set_current_context(nullptr);
  EglContext* old = t_bound;
  t_bound = nullptr;
  if (old == nullptr) return;
  glpt::flush_before_release(old->gl);
  old->gl.target = nullptr;  // a released context has no surface (it may be destroyed now)
  old->current = false;
  for (EglSurface* s : {old->draw, old->read})
    if (s) --s->bindings;
  old->draw = old->read = nullptr;
  collect(old->display);
}

// Renders what this thread's current context has recorded before a call takes the process-wide
// lock to release it: a path-traced frame takes seconds, and no other thread's EGL call may wait
// for it. Only this thread records into its current context, so nothing is added between this
// and the release (whose own flush then finds nothing to render).
void flush_current_outside_lock() {
  if (EglContext* old = t_bound; old != nullptr) glpt::flush_before_release(old->gl);
}

EglDisplay* get_display(EGLenum platform, void* native, int screen) {
  std::lock_guard lock(objects_mutex());
  for (auto& d : displays())
    if (d->platform == platform && d->native == native && d->screen == screen) return d.get();
  auto d = std::make_unique<EglDisplay>();
  d->platform = platform;
  d->native = static_cast<Display*>(native);
  d->screen = screen;
  displays().push_back(std::move(d));
  return displays().back().get();
}

// EGLint and EGLAttrib attribute lists read alike.
template <typename Attrib>
std::vector<EGLAttrib> widen(const Attrib* list) {
  std::vector<EGLAttrib> out;
  for (size_t i = 0; list != nullptr && list[i] != EGL_NONE; i += 2) {
    out.push_back(static_cast<EGLAttrib>(list[i]));
    out.push_back(static_cast<EGLAttrib>(list[i + 1]));
  }
  out.push_back(EGL_NONE);
  return out;
}

EGLDisplay platform_display(EGLenum platform, void* native, const EGLAttrib* attribs) {
  int screen = 0;
  switch (platform) {
    case EGL_PLATFORM_X11_KHR:
      for (size_t i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
        if (attribs[i] != EGL_PLATFORM_X11_SCREEN_KHR)
          return fail<EGLDisplay>(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
        screen = static_cast<int>(attribs[i + 1]);
      }
      if (native != nullptr && (screen < 0 || screen >= ScreenCount(static_cast<Display*>(native))))
        return fail<EGLDisplay>(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
      break;
    case EGL_PLATFORM_SURFACELESS_MESA:
      // EGL_MESA_platform_surfaceless: the native display must be EGL_DEFAULT_DISPLAY.
      if (native != nullptr) return fail<EGLDisplay>(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
      if (attribs && attribs[0] != EGL_NONE)
        return fail<EGLDisplay>(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
      break;
    default:
      return fail<EGLDisplay>(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  }
  t_error = EGL_SUCCESS;
  return get_display(platform, native, screen);
}

// ---- surfaces ----------------------------------------------------------------------------------

EGLSurface create_window_surface(EGLDisplay dpy, EGLConfig config, uint32_t window,
                                 const EGLAttrib* attribs) {
  std::lock_guard lock(objects_mutex());
  EglDisplay* d = initialized_display(dpy);
  if (d == nullptr) return EGL_NO_SURFACE;
  const glpt::egl::Config* c = find_config(d, config);
  if (c == nullptr) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  EGLint render_buffer = EGL_BACK_BUFFER;
  for (size_t i = 0; attribs && attribs[i] != EGL_NONE; i += 2) {
    const EGLAttrib v = attribs[i + 1];
    switch (attribs[i]) {
      case EGL_RENDER_BUFFER:
        if (v != EGL_BACK_BUFFER && v != EGL_SINGLE_BUFFER)
          return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
        render_buffer = static_cast<EGLint>(v);
        break;
      case EGL_GL_COLORSPACE:
        if (v == EGL_GL_COLORSPACE_SRGB) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
        if (v != EGL_GL_COLORSPACE_LINEAR) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
        break;
      case EGL_VG_ALPHA_FORMAT:
      case EGL_VG_COLORSPACE:
        break;  // OpenVG's, without effect on OpenGL
      default:
        return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
    }
  }
  if (!c->window) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
  if (window == 0) return fail(EGL_BAD_NATIVE_WINDOW, EGL_NO_SURFACE);
  for (auto& s : d->surfaces)  // EGL 1.5 3.5.1: one surface per window
    if (s->live && s->type == EGL_WINDOW_BIT && s->window == window)
      return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
  std::string error;
  const bool double_buffered = render_buffer == EGL_BACK_BUFFER;
  auto target = glpt::X11WindowTarget::create(
      DisplayString(d->x11()), window, glpt::egl::drawable_config(*c, double_buffered), &error);
  if (!target) {
    std::fprintf(stderr, "glpt: %s\n", error.c_str());
    return fail(EGL_BAD_NATIVE_WINDOW, EGL_NO_SURFACE);
  }
  // A window has a geometry and is double-buffered when asked (the target makes a pixmap
  // single-buffered): anything else is not a window.
  uint32_t w = 0, h = 0;
  if (!target->query_size(&w, &h) || target->config().double_buffered != double_buffered)
    return fail(EGL_BAD_NATIVE_WINDOW, EGL_NO_SURFACE);
  auto s = std::make_unique<EglSurface>();
  s->display = d;
  s->config = *c;
  s->type = EGL_WINDOW_BIT;
  s->render_buffer = render_buffer;
  s->window = window;
  s->window_target = std::move(target);
  d->surfaces.push_back(std::move(s));
  t_error = EGL_SUCCESS;
  return d->surfaces.back().get();
}

// What an unsupported feature answers: the display's error if it is invalid or uninitialized,
// else `error`.
template <typename T>
T unsupported(EGLDisplay dpy, EGLint error, T none) {
  std::lock_guard lock(objects_mutex());
  if (initialized_display(dpy) == nullptr) return none;
  return fail(error, none);
}

// The GL 1.x commands that end a frame on a single-buffered surface.
void flush_current() { glFlush(); }

}  // namespace

// ---- entry points ------------------------------------------------------------------------------

extern "C" {

// Every entry point but this one (it reads a thread-local and cannot fail) runs through
// egl_entry: no exception crosses the C ABI.
GLPT_EXPORT EGLint eglGetError(void) {
  const EGLint e = t_error;
  t_error = EGL_SUCCESS;
  return e;
}

GLPT_EXPORT EGLDisplay eglGetDisplay(EGLNativeDisplayType display_id) {
  return egl_entry(EGL_NO_DISPLAY, [&]() -> EGLDisplay {
    // A native display is an X11 Display* (the only native platform glpt has).
    return platform_display(EGL_PLATFORM_X11_KHR, display_id, nullptr);
  });
}

GLPT_EXPORT EGLDisplay eglGetPlatformDisplay(EGLenum platform, void* native_display,
                                             const EGLAttrib* attrib_list) {
  return egl_entry(EGL_NO_DISPLAY, [&]() -> EGLDisplay {
    return platform_display(platform, native_display, attrib_list);
  });
}

GLPT_EXPORT EGLDisplay eglGetPlatformDisplayEXT(EGLenum platform, void* native_display,
                                                const EGLint* attrib_list) {
  return egl_entry(EGL_NO_DISPLAY, [&]() -> EGLDisplay {
    const std::vector<EGLAttrib> attribs = widen(attrib_list);
    return platform_display(platform, native_display, attribs.data());
  });
}

GLPT_EXPORT EGLBoolean eglInitialize(EGLDisplay dpy, EGLint* major, EGLint* minor) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = find_display(dpy);
    if (d == nullptr) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
    if (!d->initialized) {
      if (d->platform == EGL_PLATFORM_X11_KHR) {
        if (d->x11() == nullptr) d->opened = XOpenDisplay(nullptr);
        if (d->x11() == nullptr) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
        d->configs = glpt::egl::configs_of_x11_screen(d->x11(), d->screen);
      } else {
        d->configs = glpt::egl::surfaceless_configs();
      }
      if (d->configs.empty()) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
      d->initialized = true;
    }
    if (major) *major = 1;
    if (minor) *minor = 5;
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglTerminate(EGLDisplay dpy) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = find_display(dpy);
    if (d == nullptr) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
    // EGL 1.5 3.2: handles become invalid; what is current somewhere lives until released.
    for (auto& c : d->contexts) c->live = false;
    for (auto& s : d->surfaces) s->live = false;
    collect(d);
    d->initialized = false;
    return succeed();
  });
}

GLPT_EXPORT const char* eglQueryString(EGLDisplay dpy, EGLint name) {
  return egl_entry(static_cast<const char*>(nullptr), [&]() -> const char* {
    static constexpr char kClientExtensions[] =
        "EGL_EXT_client_extensions EGL_EXT_platform_base EGL_KHR_platform_x11 EGL_EXT_platform_x11 "
        "EGL_MESA_platform_surfaceless";
    static constexpr char kDisplayExtensions[] =
        "EGL_KHR_create_context EGL_KHR_get_all_proc_addresses EGL_KHR_surfaceless_context";
    std::lock_guard lock(objects_mutex());
    if (dpy == EGL_NO_DISPLAY) {
      // EGL 1.5 3.3 and EGL_EXT_client_extensions: the version and client extensions only.
      if (name == EGL_EXTENSIONS) return t_error = EGL_SUCCESS, kClientExtensions;
      if (name == EGL_VERSION) return t_error = EGL_SUCCESS, "1.5";
      return fail<const char*>(EGL_BAD_DISPLAY, nullptr);
    }
    if (initialized_display(dpy) == nullptr) return nullptr;
    const char* value = nullptr;
    switch (name) {
      case EGL_CLIENT_APIS:
        value = "OpenGL";
        break;
      case EGL_EXTENSIONS:
        value = kDisplayExtensions;
        break;
      case EGL_VENDOR:
        value = "glpt";
        break;
      case EGL_VERSION:
        value = "1.5 glpt";
        break;
      default:
        return fail<const char*>(EGL_BAD_PARAMETER, nullptr);
    }
    t_error = EGL_SUCCESS;
    return value;
  });
}

GLPT_EXPORT EGLBoolean eglGetConfigs(EGLDisplay dpy, EGLConfig* configs, EGLint config_size,
                                     EGLint* num_config) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    if (num_config == nullptr) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    EGLint n = static_cast<EGLint>(d->configs.size());
    if (configs != nullptr) {
      n = std::clamp(config_size, 0, n);
      for (EGLint i = 0; i < n; ++i) configs[i] = config_handle(d->configs[i]);
    }
    *num_config = n;
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglChooseConfig(EGLDisplay dpy, const EGLint* attrib_list,
                                       EGLConfig* configs, EGLint config_size, EGLint* num_config) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    if (num_config == nullptr) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    std::vector<const glpt::egl::Config*> chosen;
    const EGLint error = glpt::egl::choose_configs(d->configs, attrib_list, &chosen);
    if (error != EGL_SUCCESS) return fail(error, EGL_FALSE);
    EGLint n = static_cast<EGLint>(chosen.size());
    if (configs != nullptr) {
      n = std::clamp(config_size, 0, n);
      for (EGLint i = 0; i < n; ++i) configs[i] = config_handle(*chosen[i]);
    }
    *num_config = n;
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglGetConfigAttrib(EGLDisplay dpy, EGLConfig config, EGLint attribute,
                                          EGLint* value) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    const glpt::egl::Config* c = find_config(d, config);
    if (c == nullptr) return fail(EGL_BAD_CONFIG, EGL_FALSE);
    if (value == nullptr) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    if (!glpt::egl::config_attribute(*c, attribute, value))
      return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglBindAPI(EGLenum api) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    // OpenGL only: OpenGL ES and OpenVG are not supported (EGL 1.5 3.7).
    if (api != EGL_OPENGL_API) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    t_api = api;
    return succeed();
  });
}

GLPT_EXPORT EGLenum eglQueryAPI(void) {
  return egl_entry(EGLenum{EGL_NONE}, [&]() -> EGLenum {
    t_error = EGL_SUCCESS;
    return t_api;
  });
}

GLPT_EXPORT EGLContext eglCreateContext(EGLDisplay dpy, EGLConfig config, EGLContext share_context,
                                        const EGLint* attrib_list) {
  return egl_entry(EGL_NO_CONTEXT, [&]() -> EGLContext {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_NO_CONTEXT;
    if (t_api != EGL_OPENGL_API) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
    const glpt::egl::Config* c = find_config(d, config);
    if (c == nullptr) return fail(EGL_BAD_CONFIG, EGL_NO_CONTEXT);
    const EglContext* share = nullptr;
    if (share_context != EGL_NO_CONTEXT) {
      share = find_context(d, share_context);
      if (share == nullptr) return fail(EGL_BAD_CONTEXT, EGL_NO_CONTEXT);
    }
    EGLint major = 1, minor = 0, flags = 0;
    for (size_t i = 0; attrib_list && attrib_list[i] != EGL_NONE; i += 2) {
      const EGLint v = attrib_list[i + 1];
      switch (attrib_list[i]) {
        case EGL_CONTEXT_MAJOR_VERSION:
          major = v;
          break;
        case EGL_CONTEXT_MINOR_VERSION:
          minor = v;
          break;
        case EGL_CONTEXT_OPENGL_PROFILE_MASK:
          // Profiles start with OpenGL 3.2; the bits must still be valid (as Mesa checks).
          if (v &
              ~(EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT | EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT))
            return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
          break;
        case EGL_CONTEXT_FLAGS_KHR:
          if (v &
              ~(EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR | EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR |
                EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR))
            return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
          flags = v;
          break;
        case EGL_CONTEXT_OPENGL_DEBUG:
        case EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE:
        case EGL_CONTEXT_OPENGL_ROBUST_ACCESS:
          if (v != EGL_TRUE && v != EGL_FALSE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
          if (attrib_list[i] == EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE && v)
            flags |= EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR;
          if (attrib_list[i] == EGL_CONTEXT_OPENGL_ROBUST_ACCESS && v)
            flags |= EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR;
          break;
        case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY:
          if (v != EGL_NO_RESET_NOTIFICATION && v != EGL_LOSE_CONTEXT_ON_RESET)
            return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
          break;
        default:
          return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
      }
    }
    // glpt is OpenGL 1.5; forward-compatible contexts exist from 3.0 on and robust access is not
    // offered (EGL_KHR_create_context: EGL_BAD_MATCH).
    if (major < 1 || minor < 0 || major > 1 || minor > 5)
      return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
    if (flags &
        (EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR | EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR))
      return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
    d->contexts.push_back(std::make_unique<EglContext>(d, *c, share, major, minor));
    t_error = EGL_SUCCESS;
    return d->contexts.back().get();
  });
}

GLPT_EXPORT EGLBoolean eglDestroyContext(EGLDisplay dpy, EGLContext ctx) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    EglContext* c = find_context(d, ctx);
    if (c == nullptr) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
    c->live = false;  // freed now, or when it stops being current (EGL 1.5 3.7.2)
    collect(d);
    return succeed();
  });
}

GLPT_EXPORT EGLSurface eglCreateWindowSurface(EGLDisplay dpy, EGLConfig config,
                                              EGLNativeWindowType win, const EGLint* attrib_list) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    const std::vector<EGLAttrib> attribs = widen(attrib_list);
    return create_window_surface(dpy, config, static_cast<uint32_t>(win), attribs.data());
  });
}

// EGL_KHR_platform_x11: the native window is a pointer to the X Window.
GLPT_EXPORT EGLSurface eglCreatePlatformWindowSurface(EGLDisplay dpy, EGLConfig config,
                                                      void* native_window,
                                                      const EGLAttrib* attrib_list) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    const uint32_t window =
        native_window ? static_cast<uint32_t>(*static_cast<const Window*>(native_window)) : 0;
    return create_window_surface(dpy, config, window, attrib_list);
  });
}

GLPT_EXPORT EGLSurface eglCreatePlatformWindowSurfaceEXT(EGLDisplay dpy, EGLConfig config,
                                                         void* native_window,
                                                         const EGLint* attrib_list) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    const std::vector<EGLAttrib> attribs = widen(attrib_list);
    return eglCreatePlatformWindowSurface(dpy, config, native_window, attribs.data());
  });
}

GLPT_EXPORT EGLSurface eglCreatePbufferSurface(EGLDisplay dpy, EGLConfig config,
                                               const EGLint* attrib_list) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_NO_SURFACE;
    const glpt::egl::Config* c = find_config(d, config);
    if (c == nullptr) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
    EGLint width = 0, height = 0;
    bool largest = false;
    for (size_t i = 0; attrib_list && attrib_list[i] != EGL_NONE; i += 2) {
      const EGLint v = attrib_list[i + 1];
      switch (attrib_list[i]) {
        case EGL_WIDTH:
          width = v;
          break;
        case EGL_HEIGHT:
          height = v;
          break;
        case EGL_LARGEST_PBUFFER:
          largest = v != EGL_FALSE;
          break;
        case EGL_TEXTURE_FORMAT:
        case EGL_TEXTURE_TARGET:
          // No config binds to textures (EGL_BIND_TO_TEXTURE_RGB/RGBA are false).
          if (v == EGL_TEXTURE_RGB || v == EGL_TEXTURE_RGBA || v == EGL_TEXTURE_2D)
            return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
          if (v != EGL_NO_TEXTURE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
          break;
        case EGL_MIPMAP_TEXTURE:
          break;
        case EGL_GL_COLORSPACE:
          if (v == EGL_GL_COLORSPACE_SRGB) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
          if (v != EGL_GL_COLORSPACE_LINEAR) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
          break;
        case EGL_VG_ALPHA_FORMAT:
        case EGL_VG_COLORSPACE:
          break;
        default:
          return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
      }
    }
    if (width < 0 || height < 0) return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
    if (width > glpt::egl::kMaxPbufferSize || height > glpt::egl::kMaxPbufferSize) {
      if (!largest) return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
      width = std::min(width, glpt::egl::kMaxPbufferSize);
      height = std::min(height, glpt::egl::kMaxPbufferSize);
    }
    auto s = std::make_unique<EglSurface>();
    s->display = d;
    s->config = *c;
    s->type = EGL_PBUFFER_BIT;
    s->width = width;
    s->height = height;
    s->largest_pbuffer = largest;
    // A pbuffer renders to its back buffer (EGL 1.5 3.5.2), which eglSwapBuffers never shows.
    s->pbuffer_target = std::make_unique<glpt::HeadlessTarget>(
        static_cast<uint32_t>(width), static_cast<uint32_t>(height),
        glpt::egl::drawable_config(*c, /*double_buffered=*/true));
    d->surfaces.push_back(std::move(s));
    t_error = EGL_SUCCESS;
    return d->surfaces.back().get();
  });
}

// Pixmap surfaces and client-buffer pbuffers are not offered: no config has EGL_PIXMAP_BIT.
GLPT_EXPORT EGLSurface eglCreatePixmapSurface(EGLDisplay dpy, EGLConfig config,
                                              EGLNativePixmapType pixmap,
                                              const EGLint* attrib_list) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    (void)pixmap;
    (void)attrib_list;
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_NO_SURFACE;
    if (find_config(d, config) == nullptr) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
    return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
  });
}

GLPT_EXPORT EGLSurface eglCreatePlatformPixmapSurface(EGLDisplay dpy, EGLConfig config,
                                                      void* native_pixmap,
                                                      const EGLAttrib* attrib_list) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    (void)native_pixmap;
    (void)attrib_list;
    return eglCreatePixmapSurface(dpy, config, 0, nullptr);
  });
}

GLPT_EXPORT EGLSurface eglCreatePbufferFromClientBuffer(EGLDisplay dpy, EGLenum buftype,
                                                        EGLClientBuffer buffer, EGLConfig config,
                                                        const EGLint* attrib_list) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    (void)buftype;
    (void)buffer;
    (void)config;
    (void)attrib_list;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGL_NO_SURFACE);  // no client buffer type is known
  });
}

GLPT_EXPORT EGLBoolean eglDestroySurface(EGLDisplay dpy, EGLSurface surface) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    EglSurface* s = find_surface(d, surface);
    if (s == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    s->live = false;  // freed now, or once no context has it current (EGL 1.5 3.5.5)
    collect(d);
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglQuerySurface(EGLDisplay dpy, EGLSurface surface, EGLint attribute,
                                       EGLint* value) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    EglSurface* s = find_surface(d, surface);
    if (s == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    if (value == nullptr) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    const bool pbuffer = s->type == EGL_PBUFFER_BIT;
    switch (attribute) {
      case EGL_CONFIG_ID:
        *value = s->config.id;
        break;
      case EGL_WIDTH:
      case EGL_HEIGHT: {
        uint32_t w = 0, h = 0;
        if (s->target()->query_size(&w, &h))
          *value = static_cast<EGLint>(attribute == EGL_WIDTH ? w : h);
        else
          *value = 0;  // the window is gone
        break;
      }
      case EGL_LARGEST_PBUFFER:
        if (pbuffer) *value = s->largest_pbuffer;  // windows leave *value alone (EGL 1.5 3.5.6)
        break;
      case EGL_TEXTURE_FORMAT:
      case EGL_TEXTURE_TARGET:
        if (pbuffer) *value = EGL_NO_TEXTURE;
        break;
      case EGL_MIPMAP_TEXTURE:
      case EGL_MIPMAP_LEVEL:
        if (pbuffer) *value = 0;
        break;
      case EGL_RENDER_BUFFER:
        *value = s->render_buffer;
        break;
      case EGL_SWAP_BEHAVIOR:
        *value = EGL_BUFFER_DESTROYED;
        break;
      case EGL_MULTISAMPLE_RESOLVE:
        *value = EGL_MULTISAMPLE_RESOLVE_DEFAULT;
        break;
      case EGL_HORIZONTAL_RESOLUTION:
      case EGL_VERTICAL_RESOLUTION:
      case EGL_PIXEL_ASPECT_RATIO:
        *value = EGL_UNKNOWN;
        break;
      case EGL_GL_COLORSPACE:
        *value = EGL_GL_COLORSPACE_LINEAR;
        break;
      case EGL_VG_ALPHA_FORMAT:
        *value = EGL_VG_ALPHA_FORMAT_NONPRE;
        break;
      case EGL_VG_COLORSPACE:
        *value = EGL_VG_COLORSPACE_sRGB;
        break;
      default:
        return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
    }
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglSurfaceAttrib(EGLDisplay dpy, EGLSurface surface, EGLint attribute,
                                        EGLint value) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    if (find_surface(d, surface) == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    switch (attribute) {
      case EGL_MIPMAP_LEVEL:
        return succeed();
      case EGL_SWAP_BEHAVIOR:
        // No config has EGL_SWAP_BEHAVIOR_PRESERVED_BIT.
        if (value == EGL_BUFFER_DESTROYED) return succeed();
        return fail(value == EGL_BUFFER_PRESERVED ? EGL_BAD_MATCH : EGL_BAD_PARAMETER, EGL_FALSE);
      case EGL_MULTISAMPLE_RESOLVE:
        if (value == EGL_MULTISAMPLE_RESOLVE_DEFAULT) return succeed();
        return fail(value == EGL_MULTISAMPLE_RESOLVE_BOX ? EGL_BAD_MATCH : EGL_BAD_PARAMETER,
                    EGL_FALSE);
      default:
        return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
    }
  });
}

GLPT_EXPORT EGLBoolean eglBindTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    (void)buffer;
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    if (find_surface(d, surface) == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    return fail(EGL_BAD_MATCH, EGL_FALSE);  // no surface has a texture format
  });
}

GLPT_EXPORT EGLBoolean eglReleaseTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  return egl_entry(EGLBoolean{EGL_FALSE},
                   [&]() -> EGLBoolean { return eglBindTexImage(dpy, surface, buffer); });
}

GLPT_EXPORT EGLBoolean eglMakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read,
                                      EGLContext ctx) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    flush_current_outside_lock();
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = find_display(dpy);
    if (d == nullptr) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
    const bool releasing = ctx == EGL_NO_CONTEXT;
    if (releasing && (draw != EGL_NO_SURFACE || read != EGL_NO_SURFACE))
      return fail(EGL_BAD_MATCH, EGL_FALSE);
    // Releasing works on an uninitialized display too (as Mesa's eglMakeCurrent).
    if (!d->initialized && !releasing) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
    if (releasing) {
      release_current_locked();
      return succeed();
    }
    EglContext* c = find_context(d, ctx);
    if (c == nullptr) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
    if ((draw == EGL_NO_SURFACE) != (read == EGL_NO_SURFACE)) return fail(EGL_BAD_MATCH, EGL_FALSE);
    EglSurface* ds = nullptr;
    EglSurface* rs = nullptr;
    if (draw != EGL_NO_SURFACE) {
      ds = find_surface(d, draw);
      rs = find_surface(d, read);
      if (ds == nullptr || rs == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
      // Mesa requires the context's own config on both surfaces.
      if (ds->config.id != c->config.id || rs->config.id != c->config.id)
        return fail(EGL_BAD_MATCH, EGL_FALSE);
    }
    EglContext* old = t_bound;
    if (c->current && c != old) return fail(EGL_BAD_ACCESS, EGL_FALSE);  // another thread's
    // A surface current to another thread's context cannot be made current here (EGL 1.5 3.7.3).
    for (EglSurface* s : {ds, rs}) {
      if (s == nullptr || s->bindings == 0) continue;
      const bool ours = old && (old->draw == s || old->read == s);
      if (!ours) return fail(EGL_BAD_ACCESS, EGL_FALSE);
    }
    if (ds && ds->type == EGL_WINDOW_BIT) {
      uint32_t w = 0, h = 0;
      if (!ds->target()->query_size(&w, &h)) return fail(EGL_BAD_NATIVE_WINDOW, EGL_FALSE);
    }
    release_current_locked();
    c->current = true;
    t_bound = c;
    c->draw = ds;
    c->read = rs;
    for (EglSurface* s : {ds, rs})
      if (s) ++s->bindings;
    // glpt draws and reads the draw surface (one target per context, as GLX in glpt).
    glpt::bind_target_and_make_current(c->gl, ds ? ds->target() : nullptr);
    return succeed();
  });
}

GLPT_EXPORT EGLContext eglGetCurrentContext(void) {
  return egl_entry(EGL_NO_CONTEXT, [&]() -> EGLContext {
    t_error = EGL_SUCCESS;
    EglContext* c = current_egl();
    return c ? static_cast<EGLContext>(c) : EGL_NO_CONTEXT;
  });
}

GLPT_EXPORT EGLSurface eglGetCurrentSurface(EGLint readdraw) {
  return egl_entry(EGL_NO_SURFACE, [&]() -> EGLSurface {
    if (readdraw != EGL_DRAW && readdraw != EGL_READ)
      return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
    t_error = EGL_SUCCESS;
    EglContext* c = current_egl();
    if (c == nullptr) return EGL_NO_SURFACE;
    EglSurface* s = readdraw == EGL_DRAW ? c->draw : c->read;
    return s ? static_cast<EGLSurface>(s) : EGL_NO_SURFACE;
  });
}

GLPT_EXPORT EGLDisplay eglGetCurrentDisplay(void) {
  return egl_entry(EGL_NO_DISPLAY, [&]() -> EGLDisplay {
    t_error = EGL_SUCCESS;
    EglContext* c = current_egl();
    return c ? static_cast<EGLDisplay>(c->display) : EGL_NO_DISPLAY;
  });
}

GLPT_EXPORT EGLBoolean eglQueryContext(EGLDisplay dpy, EGLContext ctx, EGLint attribute,
                                       EGLint* value) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    EglContext* c = find_context(d, ctx);
    if (c == nullptr) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
    if (value == nullptr) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    switch (attribute) {
      case EGL_CONFIG_ID:
        *value = c->config.id;
        break;
      case EGL_CONTEXT_CLIENT_TYPE:
        *value = EGL_OPENGL_API;
        break;
      case EGL_CONTEXT_CLIENT_VERSION:
        *value = c->major;  // as Mesa: the major version asked for
        break;
      case EGL_RENDER_BUFFER:
        *value = c->draw ? c->draw->render_buffer : EGL_NONE;
        break;
      default:
        return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
    }
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglSwapBuffers(EGLDisplay dpy, EGLSurface surface) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    EglContext* c = nullptr;
    EglSurface* s = nullptr;
    {
      std::lock_guard lock(objects_mutex());
      EglDisplay* d = initialized_display(dpy);
      if (d == nullptr) return EGL_FALSE;
      s = find_surface(d, surface);
      if (s == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
      c = current_egl();
      // EGL 1.5 3.10.1: the surface must be the draw surface of this thread's current context.
      if (c == nullptr) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
      if (c->draw != s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    }
    // Rendering happens outside the lock: it takes long, and only this thread uses `c`.
    if (s->type == EGL_WINDOW_BIT && s->render_buffer == EGL_BACK_BUFFER)
      glpt::end_frame(c->gl, /*swap=*/true);
    else if (s->type == EGL_WINDOW_BIT)
      flush_current();  // single-buffered: what glFlush shows is all there is to show
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglSwapInterval(EGLDisplay dpy, EGLint interval) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    EglContext* c = current_egl();
    if (c == nullptr) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
    if (c->draw == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    // Clamped to the config's [EGL_MIN_SWAP_INTERVAL, EGL_MAX_SWAP_INTERVAL]. glpt presents at
    // each swap without waiting for a vertical retrace, so the interval is only recorded.
    c->draw->swap_interval = std::clamp(interval, 0, 1);
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglCopyBuffers(EGLDisplay dpy, EGLSurface surface,
                                      EGLNativePixmapType target) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    (void)target;
    std::lock_guard lock(objects_mutex());
    EglDisplay* d = initialized_display(dpy);
    if (d == nullptr) return EGL_FALSE;
    if (find_surface(d, surface) == nullptr) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    return fail(EGL_BAD_NATIVE_PIXMAP, EGL_FALSE);  // pixmaps are not supported
  });
}

// glpt executes a frame at the swap, read or flush that needs it; a swapped frame may still be
// on its way to the window (GLPT_PRESENT=later): native rendering after this sees it.
GLPT_EXPORT EGLBoolean eglWaitClient(void) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    {
      std::lock_guard lock(objects_mutex());
      EglContext* c = current_egl();
      if (c && ((c->draw && !c->draw->live) || (c->read && !c->read->live)))
        return fail(EGL_BAD_CURRENT_SURFACE, EGL_FALSE);
    }
    glpt::Context* gl = glpt::current_context();
    if (gl != nullptr && gl->target != nullptr) gl->target->wait_presented();
    return succeed();
  });
}

GLPT_EXPORT EGLBoolean eglWaitGL(void) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    // EGL 1.5 3.8: eglWaitGL is eglWaitClient with OpenGL ES bound; glpt binds OpenGL only.
    return eglWaitClient();
  });
}

GLPT_EXPORT EGLBoolean eglWaitNative(EGLint engine) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    if (engine != EGL_CORE_NATIVE_ENGINE) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    return eglWaitClient();
  });
}

GLPT_EXPORT EGLBoolean eglReleaseThread(void) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    flush_current_outside_lock();
    std::lock_guard lock(objects_mutex());
    release_current_locked();
    t_api = EGL_NONE;
    return succeed();
  });
}

// Sync objects and images (EGL 1.5 3.8, 3.9) are not supported: no type, target or handle is
// valid (EGL_BAD_PARAMETER once the display is).
GLPT_EXPORT EGLSync eglCreateSync(EGLDisplay dpy, EGLenum type, const EGLAttrib* attrib_list) {
  return egl_entry(EGL_NO_SYNC, [&]() -> EGLSync {
    (void)type;
    (void)attrib_list;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGL_NO_SYNC);
  });
}

GLPT_EXPORT EGLBoolean eglDestroySync(EGLDisplay dpy, EGLSync sync) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    (void)sync;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGLBoolean{EGL_FALSE});
  });
}

GLPT_EXPORT EGLint eglClientWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags, EGLTime timeout) {
  return egl_entry(EGLint{EGL_FALSE}, [&]() -> EGLint {
    (void)sync;
    (void)flags;
    (void)timeout;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGLint{EGL_FALSE});
  });
}

GLPT_EXPORT EGLBoolean eglGetSyncAttrib(EGLDisplay dpy, EGLSync sync, EGLint attribute,
                                        EGLAttrib* value) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    (void)sync;
    (void)attribute;
    (void)value;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGLBoolean{EGL_FALSE});
  });
}

GLPT_EXPORT EGLBoolean eglWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    (void)sync;
    (void)flags;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGLBoolean{EGL_FALSE});
  });
}

GLPT_EXPORT EGLImage eglCreateImage(EGLDisplay dpy, EGLContext ctx, EGLenum target,
                                    EGLClientBuffer buffer, const EGLAttrib* attrib_list) {
  return egl_entry(EGL_NO_IMAGE, [&]() -> EGLImage {
    (void)ctx;
    (void)target;
    (void)buffer;
    (void)attrib_list;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGL_NO_IMAGE);
  });
}

GLPT_EXPORT EGLBoolean eglDestroyImage(EGLDisplay dpy, EGLImage image) {
  return egl_entry(EGLBoolean{EGL_FALSE}, [&]() -> EGLBoolean {
    (void)image;
    return unsupported(dpy, EGL_BAD_PARAMETER, EGLBoolean{EGL_FALSE});
  });
}

GLPT_EXPORT __eglMustCastToProperFunctionPointerType eglGetProcAddress(const char* procname);

}  // extern "C"

namespace {

struct EglProc {
  const char* name;
  __eglMustCastToProperFunctionPointerType entry;
};

#define GLPT_EGL_PROC(name) \
  { #name, reinterpret_cast < __eglMustCastToProperFunctionPointerType>(&name) }
const EglProc kEglProcs[] = {
    GLPT_EGL_PROC(eglBindAPI),
    GLPT_EGL_PROC(eglBindTexImage),
    GLPT_EGL_PROC(eglChooseConfig),
    GLPT_EGL_PROC(eglClientWaitSync),
    GLPT_EGL_PROC(eglCopyBuffers),
    GLPT_EGL_PROC(eglCreateContext),
    GLPT_EGL_PROC(eglCreateImage),
    GLPT_EGL_PROC(eglCreatePbufferFromClientBuffer),
    GLPT_EGL_PROC(eglCreatePbufferSurface),
    GLPT_EGL_PROC(eglCreatePixmapSurface),
    GLPT_EGL_PROC(eglCreatePlatformPixmapSurface),
    GLPT_EGL_PROC(eglCreatePlatformWindowSurface),
    GLPT_EGL_PROC(eglCreatePlatformWindowSurfaceEXT),
    GLPT_EGL_PROC(eglCreateSync),
    GLPT_EGL_PROC(eglCreateWindowSurface),
    GLPT_EGL_PROC(eglDestroyContext),
    GLPT_EGL_PROC(eglDestroyImage),
    GLPT_EGL_PROC(eglDestroySurface),
    GLPT_EGL_PROC(eglDestroySync),
    GLPT_EGL_PROC(eglGetConfigAttrib),
    GLPT_EGL_PROC(eglGetConfigs),
    GLPT_EGL_PROC(eglGetCurrentContext),
    GLPT_EGL_PROC(eglGetCurrentDisplay),
    GLPT_EGL_PROC(eglGetCurrentSurface),
    GLPT_EGL_PROC(eglGetDisplay),
    GLPT_EGL_PROC(eglGetError),
    GLPT_EGL_PROC(eglGetPlatformDisplay),
    GLPT_EGL_PROC(eglGetPlatformDisplayEXT),
    GLPT_EGL_PROC(eglGetProcAddress),
    GLPT_EGL_PROC(eglGetSyncAttrib),
    GLPT_EGL_PROC(eglInitialize),
    GLPT_EGL_PROC(eglMakeCurrent),
    GLPT_EGL_PROC(eglQueryAPI),
    GLPT_EGL_PROC(eglQueryContext),
    GLPT_EGL_PROC(eglQueryString),
    GLPT_EGL_PROC(eglQuerySurface),
    GLPT_EGL_PROC(eglReleaseTexImage),
    GLPT_EGL_PROC(eglReleaseThread),
    GLPT_EGL_PROC(eglSurfaceAttrib),
    GLPT_EGL_PROC(eglSwapBuffers),
    GLPT_EGL_PROC(eglSwapInterval),
    GLPT_EGL_PROC(eglTerminate),
    GLPT_EGL_PROC(eglWaitClient),
    GLPT_EGL_PROC(eglWaitGL),
    GLPT_EGL_PROC(eglWaitNative),
    GLPT_EGL_PROC(eglWaitSync),
};
#undef GLPT_EGL_PROC

}  // namespace

// EGL_KHR_get_all_proc_addresses: EGL's own functions and every GL command glpt implements, from
// the same table as glXGetProcAddress. No error is generated (EGL 1.5 3.10).
GLPT_EXPORT __eglMustCastToProperFunctionPointerType eglGetProcAddress(const char* procname) {
  return egl_entry(__eglMustCastToProperFunctionPointerType{nullptr},
                   [&]() -> __eglMustCastToProperFunctionPointerType {
                     if (procname == nullptr) return nullptr;
                     if (std::strncmp(procname, "egl", 3) == 0) {
                       for (const EglProc& p : kEglProcs)
                         if (std::strcmp(p.name, procname) == 0) return p.entry;
                       return nullptr;
                     }
                     return reinterpret_cast<__eglMustCastToProperFunctionPointerType>(
                         glpt::lookup_gl_proc(procname));
                   });
}
