// GLX 1.4 entry points (plus GLX_ARB_create_context and GLX_ARB_get_proc_address): contexts,
// framebuffer configurations, make-current and swap. A GLX context wraps a glpt::Context and
// the window it currently draws to.
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "gl/glx_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/glx/fbconfigs.hpp"
#include "gl_shim/glx/glx_api.hpp"
#include "gl_shim/glx/glx_types.hpp"
#include "gl_shim/glx/x11_window_target.hpp"

struct __GLXcontextRec {
  explicit __GLXcontextRec(const __GLXcontextRec* share) : gl(share ? &share->gl : nullptr) {
    gl.window_system_context = this;
    gl.window_system = glpt::WindowSystem::kGlx;
  }
  glpt::Context gl;
  Display* display = nullptr;  // of the last make-current
  GLXDrawable drawable = None;
  GLXDrawable readable = None;
  GLXFBConfig config = nullptr;
  std::unique_ptr<glpt::X11WindowTarget> target;
  bool destroy_when_released = false;  // glXDestroyContext while current (GLX 1.4 3.3.7)
};

namespace {

GLXContext current_glx() {
  glpt::Context* gl = glpt::current_context();
  if (gl == nullptr || gl->window_system != glpt::WindowSystem::kGlx) return nullptr;
  return static_cast<GLXContext>(gl->window_system_context);
}

void release_current() {
  GLXContext old = current_glx();
  glpt::set_current_context(nullptr);
  if (old && old->destroy_when_released) delete old;
}

GLXContext create_context(Display* dpy, GLXFBConfig config, GLXContext share) {
  if (dpy == nullptr) return nullptr;
  auto* ctx = new __GLXcontextRec(share);
  ctx->display = dpy;
  ctx->config = config;
  return ctx;
}

bool make_current(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx) {
  if (ctx == nullptr) {
    release_current();
    return true;
  }
  if (draw == None) return false;  // GLX: BadMatch for a context without a drawable
  GLXContext old = current_glx();
  if (old != ctx) release_current();
  if (!ctx->target || ctx->target->window() != draw) {
    std::string error;
    glpt::glx::FBConfig c;
    glpt::rec::DrawableConfig config;
    if (glpt::glx::decode(dpy, ctx->config, &c)) {
      config.double_buffered = c.double_buffered;
      config.has_alpha = c.alpha;
    }
    ctx->target = glpt::X11WindowTarget::create(DisplayString(dpy), static_cast<uint32_t>(draw),
                                                config, &error);
    if (!ctx->target) {
      std::fprintf(stderr, "glpt: %s\n", error.c_str());
      return false;
    }
  }
  ctx->display = dpy;
  ctx->drawable = draw;
  ctx->readable = read;
  glpt::bind_target_and_make_current(ctx->gl, ctx->target.get());
  return true;
}

XVisualInfo* visual_info(Display* dpy, VisualID id) {
  XVisualInfo templ{};
  templ.visualid = id;
  int n = 0;
  return XGetVisualInfo(dpy, VisualIDMask, &templ, &n);
}

constexpr const char kGlxExtensions[] =
    "GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address";

struct GlxProc {
  const char* name;
  __GLXextFuncPtr entry;
};
const GlxProc* glx_proc_table(size_t* count);

}  // namespace

extern "C" {

GLPT_EXPORT XVisualInfo* glXChooseVisual(Display* dpy, int screen, int* attrib_list) {
  if (dpy == nullptr) return nullptr;
  for (const auto& c : glpt::glx::configs_of_screen(dpy, screen))
    if (glpt::glx::visual_list_matches(c, attrib_list)) return visual_info(dpy, c.visual);
  return nullptr;
}

GLPT_EXPORT int glXGetConfig(Display* dpy, XVisualInfo* vis, int attrib, int* value) {
  if (dpy == nullptr || vis == nullptr || value == nullptr) return GLX_BAD_VALUE;
  if (vis->c_class != TrueColor || (vis->depth != 24 && vis->depth != 32)) {
    if (attrib == GLX_USE_GL) {
      *value = 0;
      return Success;
    }
    return GLX_BAD_VISUAL;
  }
  // Visuals from glXChooseVisual are the double-buffered configs.
  const glpt::glx::FBConfig c{vis->visualid, vis->screen, vis->depth, true};
  return glpt::glx::config_attribute(c, attrib, value) ? Success : GLX_BAD_ATTRIBUTE;
}

GLPT_EXPORT GLXFBConfig* glXGetFBConfigs(Display* dpy, int screen, int* nelements) {
  if (nelements) *nelements = 0;
  if (dpy == nullptr || nelements == nullptr) return nullptr;
  const auto configs = glpt::glx::configs_of_screen(dpy, screen);
  if (configs.empty()) return nullptr;
  // Freed by the program with XFree, which is free().
  auto* out = static_cast<GLXFBConfig*>(std::malloc(sizeof(GLXFBConfig) * configs.size()));
  if (out == nullptr) return nullptr;
  for (size_t i = 0; i < configs.size(); ++i) out[i] = glpt::glx::encode(configs[i]);
  *nelements = static_cast<int>(configs.size());
  return out;
}

GLPT_EXPORT GLXFBConfig* glXChooseFBConfig(Display* dpy, int screen, const int* attrib_list,
                                           int* nelements) {
  if (nelements) *nelements = 0;
  if (dpy == nullptr || nelements == nullptr) return nullptr;
  std::vector<glpt::glx::FBConfig> configs;
  for (const auto& c : glpt::glx::configs_of_screen(dpy, screen))
    if (glpt::glx::config_matches(c, attrib_list)) configs.push_back(c);
  glpt::glx::sort_for_choose(configs);
  std::vector<GLXFBConfig> matching;
  for (const auto& c : configs) matching.push_back(glpt::glx::encode(c));
  if (matching.empty()) return nullptr;
  auto* out = static_cast<GLXFBConfig*>(std::malloc(sizeof(GLXFBConfig) * matching.size()));
  if (out == nullptr) return nullptr;
  std::memcpy(out, matching.data(), sizeof(GLXFBConfig) * matching.size());
  *nelements = static_cast<int>(matching.size());
  return out;
}

GLPT_EXPORT int glXGetFBConfigAttrib(Display* dpy, GLXFBConfig config, int attribute, int* value) {
  glpt::glx::FBConfig c;
  if (!glpt::glx::decode(dpy, config, &c)) return GLX_BAD_VALUE;
  if (value == nullptr) return GLX_BAD_VALUE;
  return glpt::glx::config_attribute(c, attribute, value) ? Success : GLX_BAD_ATTRIBUTE;
}

GLPT_EXPORT XVisualInfo* glXGetVisualFromFBConfig(Display* dpy, GLXFBConfig config) {
  glpt::glx::FBConfig c;
  if (!glpt::glx::decode(dpy, config, &c)) return nullptr;
  return visual_info(dpy, c.visual);
}

GLPT_EXPORT GLXContext glXCreateContext(Display* dpy, XVisualInfo* vis, GLXContext share_list,
                                        Bool direct) {
  (void)direct;
  if (vis == nullptr) return nullptr;
  return create_context(dpy, glpt::glx::encode({vis->visualid, vis->screen, vis->depth, true}),
                        share_list);
}

GLPT_EXPORT GLXContext glXCreateNewContext(Display* dpy, GLXFBConfig config, int render_type,
                                           GLXContext share_list, Bool direct) {
  (void)direct;
  if (render_type != GLX_RGBA_TYPE) return nullptr;  // colour-index contexts are not supported
  glpt::glx::FBConfig c;
  if (!glpt::glx::decode(dpy, config, &c)) return nullptr;
  return create_context(dpy, config, share_list);
}

GLPT_EXPORT GLXContext glXCreateContextAttribsARB(Display* dpy, GLXFBConfig config,
                                                  GLXContext share_context, Bool direct,
                                                  const int* attrib_list) {
  (void)direct;
  glpt::glx::FBConfig c;
  if (!glpt::glx::decode(dpy, config, &c)) return nullptr;
  int major = 1, minor = 0, render_type = GLX_RGBA_TYPE;
  for (int i = 0; attrib_list && attrib_list[i] != None; i += 2) {
    switch (attrib_list[i]) {
      case GLX_CONTEXT_MAJOR_VERSION_ARB:
        major = attrib_list[i + 1];
        break;
      case GLX_CONTEXT_MINOR_VERSION_ARB:
        minor = attrib_list[i + 1];
        break;
      case GLX_CONTEXT_PROFILE_MASK_ARB:  // GL 1.x has no profiles; the version decides below
        break;
      case GLX_RENDER_TYPE:
        render_type = attrib_list[i + 1];
        break;
      case GLX_CONTEXT_FLAGS_ARB:
        break;
      default:
        return nullptr;  // unknown attribute: BadValue in GLX terms
    }
  }
  // glpt is an OpenGL 1.5 compatibility implementation.
  if (major > 1 || (major == 1 && minor > 5) || render_type != GLX_RGBA_TYPE) return nullptr;
  return create_context(dpy, config, share_context);
}

GLPT_EXPORT void glXDestroyContext(Display* dpy, GLXContext ctx) {
  (void)dpy;
  if (ctx == nullptr) return;
  if (ctx == current_glx()) {
    ctx->destroy_when_released = true;
    return;
  }
  delete ctx;
}

GLPT_EXPORT Bool glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext ctx) {
  return make_current(dpy, drawable, drawable, ctx) ? True : False;
}

GLPT_EXPORT Bool glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read,
                                       GLXContext ctx) {
  return make_current(dpy, draw, read, ctx) ? True : False;
}

GLPT_EXPORT void glXSwapBuffers(Display* dpy, GLXDrawable drawable) {
  (void)dpy;
  GLXContext ctx = current_glx();
  // Swapping a drawable that is not current here has no GL work of this thread to show.
  if (ctx == nullptr || ctx->drawable != drawable) return;
  glpt::end_frame(ctx->gl, /*swap=*/true);
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
  if (dpy == nullptr) return False;
  if (error_base) *error_base = 0;
  if (event_base) *event_base = 0;
  return True;
}

GLPT_EXPORT Bool glXQueryVersion(Display* dpy, int* major, int* minor) {
  if (dpy == nullptr) return False;
  if (major) *major = 1;
  if (minor) *minor = 4;
  return True;
}

GLPT_EXPORT Bool glXIsDirect(Display* dpy, GLXContext ctx) {
  (void)dpy;
  return ctx != nullptr ? True : False;
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

GLPT_EXPORT Display* glXGetCurrentDisplay(void) {
  GLXContext ctx = current_glx();
  return ctx ? ctx->display : nullptr;
}

GLPT_EXPORT int glXQueryContext(Display* dpy, GLXContext ctx, int attribute, int* value) {
  if (ctx == nullptr || value == nullptr) return GLX_BAD_CONTEXT;
  glpt::glx::FBConfig c;
  switch (attribute) {
    case GLX_FBCONFIG_ID:
      if (!glpt::glx::decode(dpy, ctx->config, &c)) return GLX_BAD_CONTEXT;
      return glpt::glx::config_attribute(c, GLX_FBCONFIG_ID, value) ? Success : GLX_BAD_ATTRIBUTE;
    case GLX_RENDER_TYPE:
      *value = GLX_RGBA_TYPE;
      return Success;
    case GLX_SCREEN:
      if (!glpt::glx::decode(dpy, ctx->config, &c)) return GLX_BAD_CONTEXT;
      *value = c.screen;
      return Success;
    default:
      return GLX_BAD_ATTRIBUTE;
  }
}

// A GLXWindow is the X window itself: glpt draws into the window it was created for.
GLPT_EXPORT GLXWindow glXCreateWindow(Display* dpy, GLXFBConfig config, Window win,
                                      const int* attrib_list) {
  (void)dpy;
  (void)config;
  (void)attrib_list;
  return win;
}

GLPT_EXPORT void glXDestroyWindow(Display* dpy, GLXWindow win) {
  (void)dpy;
  (void)win;
}

// A GLX pixmap is the X pixmap itself: glpt draws into it like into a window (single-buffered).
GLPT_EXPORT GLXPixmap glXCreatePixmap(Display* dpy, GLXFBConfig config, Pixmap pixmap,
                                      const int* attrib_list) {
  (void)attrib_list;
  glpt::glx::FBConfig c;
  if (dpy == nullptr || pixmap == None || !glpt::glx::decode(dpy, config, &c)) return None;
  return pixmap;
}

GLPT_EXPORT void glXDestroyPixmap(Display* dpy, GLXPixmap pixmap) {
  (void)dpy;
  (void)pixmap;
}

GLPT_EXPORT GLXPixmap glXCreateGLXPixmap(Display* dpy, XVisualInfo* vis, Pixmap pixmap) {
  if (dpy == nullptr || vis == nullptr || pixmap == None) return None;
  return pixmap;
}

GLPT_EXPORT void glXDestroyGLXPixmap(Display* dpy, GLXPixmap pixmap) {
  (void)dpy;
  (void)pixmap;
}

GLPT_EXPORT void glXQueryDrawable(Display* dpy, GLXDrawable draw, int attribute,
                                  unsigned int* value) {
  if (dpy == nullptr || value == nullptr || draw == None) return;
  switch (attribute) {
    case GLX_WIDTH:
    case GLX_HEIGHT: {
      Window root;
      int x, y;
      unsigned int w = 0, h = 0, border, depth;
      if (XGetGeometry(dpy, draw, &root, &x, &y, &w, &h, &border, &depth))
        *value = attribute == GLX_WIDTH ? w : h;
      return;
    }
    case GLX_PRESERVED_CONTENTS:
    case GLX_LARGEST_PBUFFER:
      *value = 0;
      return;
    case GLX_FBCONFIG_ID:
      *value = 0;
      return;
    default:
      return;
  }
}

// Rendering is synchronous, so GL and X work are always complete relative to each other.
GLPT_EXPORT void glXWaitGL(void) {}
GLPT_EXPORT void glXWaitX(void) {}

GLPT_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name) {
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
      GLPT_GLX_PROC(glXGetCurrentDisplay),
      GLPT_GLX_PROC(glXQueryContext),
      GLPT_GLX_PROC(glXCreateWindow),
      GLPT_GLX_PROC(glXDestroyWindow),
      GLPT_GLX_PROC(glXCreatePixmap),
      GLPT_GLX_PROC(glXDestroyPixmap),
      GLPT_GLX_PROC(glXCreateGLXPixmap),
      GLPT_GLX_PROC(glXDestroyGLXPixmap),
      GLPT_GLX_PROC(glXQueryDrawable),
      GLPT_GLX_PROC(glXWaitGL),
      GLPT_GLX_PROC(glXWaitX),
      GLPT_GLX_PROC(glXGetProcAddressARB),
      GLPT_GLX_PROC(glXGetProcAddress),
  };
  *count = sizeof(table) / sizeof(table[0]);
  return table;
}
#undef GLPT_GLX_PROC

}  // namespace
