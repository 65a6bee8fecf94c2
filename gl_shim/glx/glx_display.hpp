// What GLX keeps per X Display, as Mesa's struct glx_display: the screens' configs (queried once
// from the server), the GLX drawables created on it (GLXWindow, GLXPixmap, GLXPbuffer) and their
// swap intervals. Created on the Display's first GLX use and dropped by XCloseDisplay (an
// XESetCloseDisplay hook), so a handle (GLXFBConfig = pointer to a Config) stays valid exactly as
// long as its Display, as with Mesa.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "gl_shim/c_abi_guard.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/headless_target.hpp"
#include "gl_shim/glx/glx_configs.hpp"
#include "gl_shim/process_owner.hpp"

namespace glpt {
class X11WindowTarget;
}

namespace glpt::glx {

enum class DrawableKind { kWindow, kPixmap, kPbuffer };

// The size of an X drawable asked on XCB connection `connection` (an xcb_connection_t*): false
// if it does not exist, the error consumed here rather than reported to an error handler.
bool drawable_geometry(void* connection, XID drawable, uint32_t* width, uint32_t* height);

struct GlxDrawable {
  DrawableKind kind = DrawableKind::kWindow;
  const Config* config = nullptr;
  XID x_drawable = 0;                       // the X window or pixmap (none for a pbuffer)
  std::shared_ptr<HeadlessTarget> pbuffer;  // a pbuffer's surface
  bool largest_pbuffer = false;
  unsigned long event_mask = 0;  // glXSelectEvent
};

class DisplayState {
 public:
  // The state of `dpy`, created on first use; nullptr for a null Display.
  static DisplayState* of(Display* dpy);

  const ScreenConfigs* screen(int screen);  // nullptr for a screen the display does not have
  // The config a handle points to, if it is one of this display's (GLXBadFBConfig otherwise).
  const Config* validate(GLXFBConfig handle);
  // The visual config of an X visual on `screen` (glXGetConfig, glXCreateContext).
  const Config* visual_config(int screen, VisualID visual);
  // The size of an X window or pixmap, asked over glpt's own connection (a drawable that does
  // not exist is false, not an X error for the program).
  bool geometry(XID drawable, uint32_t* width, uint32_t* height);
  // The first FBConfig of an X visual (in the server's order).
  const Config* fbconfig_for_visual(int screen, int visual_id);

  // The GLX extension's major opcode and first error (0 when the server has none).
  int glx_opcode() const { return glx_opcode_; }
  int glx_error_base() const { return glx_error_base_; }
  int glx_event_base() const { return glx_event_base_; }

  std::mutex mutex;  // guards drawables, swap_intervals and window_targets
  std::map<XID, GlxDrawable> drawables;
  // The X windows and pixmaps contexts draw to, each with glpt's connection to it and its
  // buffers: one per X drawable, shared by every context drawing to it (held by the contexts).
  std::map<XID, std::weak_ptr<X11WindowTarget>> window_targets;
  std::map<XID, int> swap_intervals;  // GLX_EXT_swap_control, per drawable (default 1)

  explicit DisplayState(Display* dpy);
  ~DisplayState();

 private:
  Display* dpy_;
  void* connection_ = nullptr;  // glpt's own xcb connection for GLX queries (under `mutex`)
  void* connection();           // opened on first use
  ProcessOwner owner_;          // the process that may use and close the connection
  bool has_glx_ = false;
  int glx_opcode_ = 0, glx_error_base_ = 0, glx_event_base_ = 0;
  std::vector<std::unique_ptr<ScreenConfigs>> screens_;  // loaded on first use
};

// A new XID from the program's connection's range, for a GLX drawable (as Mesa's are).
XID allocate_xid(Display* dpy);

// Reports a GLX error (`glx_error`: GLXBadContext = 0 ... GLXBadWindow = 12, offset by the
// extension's error base) or a core X error (`core_error`: BadValue, BadMatch, ...) through the
// program's Xlib error handler, as Mesa's __glXSendError does. `minor`: the GLX request code.
void send_glx_error(Display* dpy, int glx_error, XID resource, int minor);
void send_x_error(Display* dpy, int core_error, XID resource, int minor);

// A GLX entry point's body: an exception (allocation failure) returns the function's `failure`
// value (NULL, False, None, an error code) instead of crossing the C ABI, and is a BadAlloc X
// error for request `minor` as the server would send it; kClientSide: a function Mesa answers
// on the client side, whose result alone says it failed.
inline constexpr int kClientSide = -1;
inline void report_bad_alloc(Display* dpy, int minor) {
  if (dpy != nullptr && minor != kClientSide) send_x_error(dpy, BadAlloc, 0, minor);
}
template <typename Result, typename Body>
Result glx_entry(Display* dpy, int minor, Result failure, Body&& body) noexcept {
  return guard_c_abi(
      failure, [&] { report_bad_alloc(dpy, minor); }, std::forward<Body>(body));
}
template <typename Body>
void glx_entry_void(Display* dpy, int minor, Body&& body) noexcept {
  guard_c_abi_void([&] { report_bad_alloc(dpy, minor); }, std::forward<Body>(body));
}

// A GLX function whose work is GL's (the frame glXSwapBuffers renders, glXWaitGL's finish, the
// lists glXUseXFont makes): an exception is GL_OUT_OF_MEMORY on the current context, as in GL's
// own commands, not an X error (whose default handler would end the program).
template <typename Body>
void gl_work_entry(Body&& body) noexcept {
  guard_c_abi_void([] { exception_at_entry_point(); }, std::forward<Body>(body));
}

// GLX error codes (glxproto.h), offsets from the extension's first error.
inline constexpr int kGlxBadContext = 0;
inline constexpr int kGlxBadDrawable = 2;
inline constexpr int kGlxBadPixmap = 3;
inline constexpr int kGlxBadCurrentWindow = 5;
inline constexpr int kGlxBadFBConfig = 9;
inline constexpr int kGlxBadPbuffer = 10;
inline constexpr int kGlxBadWindow = 12;
inline constexpr int kGlxBadProfileArb = 13;

// GLX request codes (glxproto.h), the minor code errors name.
inline constexpr int kXGlxCreateContext = 3;
inline constexpr int kXGlxDestroyContext = 4;
inline constexpr int kXGlxMakeCurrent = 5;
inline constexpr int kXGlxIsDirect = 6;
inline constexpr int kXGlxCopyContext = 10;
inline constexpr int kXGlxSwapBuffers = 11;
inline constexpr int kXGlxCreateGLXPixmap = 13;
inline constexpr int kXGlxVendorPrivate = 16;  // GLX_EXT_swap_control's request
inline constexpr int kXGlxDestroyGLXPixmap = 15;
inline constexpr int kXGlxCreateNewContext = 24;
inline constexpr int kXGlxMakeContextCurrent = 26;
inline constexpr int kXGlxCreatePbuffer = 27;
inline constexpr int kXGlxDestroyPbuffer = 28;
inline constexpr int kXGlxGetDrawableAttributes = 29;
inline constexpr int kXGlxChangeDrawableAttributes = 30;
inline constexpr int kXGlxCreatePixmap = 22;
inline constexpr int kXGlxDestroyPixmap = 23;
inline constexpr int kXGlxCreateWindow = 31;
inline constexpr int kXGlxDestroyWindow = 32;
inline constexpr int kXGlxCreateContextAttribsArb = 34;

}  // namespace glpt::glx
