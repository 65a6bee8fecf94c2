#include "gl_shim/glx/glx_display.hpp"

#include <xcb/xcb.h>

#include <algorithm>

// Xlibint.h: _XError and the Display internals Mesa's __glXSendError uses to deliver an error to
// the program's handler. Only this file sees them; its min/max macros would break <algorithm>.
#include <X11/Xlibint.h>
#undef min
#undef max

namespace glpt::glx {
namespace {

// Every Display with GLX state. Like Mesa's glx_displays list this is process-wide: a Display is
// the program's, and GLX calls name it, not a context.
std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::map<Display*, std::unique_ptr<DisplayState>>& registry() {
  static std::map<Display*, std::unique_ptr<DisplayState>> displays;
  return displays;
}

int on_close_display(Display* dpy, XExtCodes*) {
  std::unique_ptr<DisplayState> state;
  {
    std::lock_guard lock(registry_mutex());
    auto it = registry().find(dpy);
    if (it == registry().end()) return 0;
    state = std::move(it->second);
    registry().erase(it);
  }
  return 0;
}

}  // namespace

DisplayState* DisplayState::of(Display* dpy) {
  if (dpy == nullptr) return nullptr;
  {
    std::lock_guard lock(registry_mutex());
    auto it = registry().find(dpy);
    if (it != registry().end()) return it->second.get();
  }
  auto state = std::make_unique<DisplayState>(dpy);
  DisplayState* raw = state.get();
  {
    std::lock_guard lock(registry_mutex());
    auto [it, inserted] = registry().emplace(dpy, std::move(state));
    if (!inserted) return it->second.get();  // another thread was first
  }
  // Dropped with the Display (an extension record of glpt's own carries the hook).
  if (XExtCodes* codes = XAddExtension(dpy))
    XESetCloseDisplay(dpy, codes->extension, on_close_display);
  return raw;
}

DisplayState::DisplayState(Display* dpy) : dpy_(dpy) {
  has_glx_ = XQueryExtension(dpy, "GLX", &glx_opcode_, &glx_event_base_, &glx_error_base_);
  if (!has_glx_) glx_opcode_ = glx_event_base_ = glx_error_base_ = 0;
  const int screens = ScreenCount(dpy);
  screens_.resize(screens > 0 ? static_cast<size_t>(screens) : 0);
}

DisplayState::~DisplayState() {
  // Not in a forked child exiting without exec (process_owner.hpp).
  if (connection_ != nullptr && owner_.is_this_process())
    xcb_disconnect(static_cast<xcb_connection_t*>(connection_));
}

const ScreenConfigs* DisplayState::screen(int n) {
  if (n < 0 || static_cast<size_t>(n) >= screens_.size()) return nullptr;
  std::lock_guard lock(mutex);
  if (screens_[n]) return screens_[n].get();
  auto configs = std::make_unique<ScreenConfigs>();
  bool from_server = false;
  if (has_glx_) {
    // The queries go over a connection of glpt's own: the program's Display stays untouched.
    if (void* c = connection()) from_server = query_server_configs(c, n, configs.get());
  }
  if (!from_server) *configs = synthesized_configs(dpy_, n);
  screens_[n] = std::move(configs);
  return screens_[n].get();
}

void* DisplayState::connection() {
  if (connection_ == nullptr) {
    auto* c = xcb_connect(DisplayString(dpy_), nullptr);
    if (xcb_connection_has_error(c) == 0)
      connection_ = c;
    else
      xcb_disconnect(c);
  }
  return connection_;
}

bool DisplayState::geometry(XID drawable, uint32_t* width, uint32_t* height) {
  std::lock_guard lock(mutex);
  return drawable_geometry(connection(), drawable, width, height);
}

bool drawable_geometry(void* connection, XID drawable, uint32_t* width, uint32_t* height) {
  auto* c = static_cast<xcb_connection_t*>(connection);
  if (c == nullptr) return false;
  xcb_generic_error_t* error = nullptr;
  xcb_get_geometry_reply_t* g =
      xcb_get_geometry_reply(c, xcb_get_geometry(c, static_cast<xcb_drawable_t>(drawable)), &error);
  free(error);
  if (g == nullptr) return false;
  *width = g->width;
  *height = g->height;
  free(g);
  return true;
}

const Config* DisplayState::validate(GLXFBConfig handle) {
  const auto* wanted = reinterpret_cast<const Config*>(handle);
  if (wanted == nullptr) return nullptr;
  for (size_t s = 0; s < screens_.size(); ++s) {
    const ScreenConfigs* configs = screen(static_cast<int>(s));
    if (configs == nullptr) continue;
    for (const Config& c : configs->fbconfigs)
      if (&c == wanted) return &c;
  }
  return nullptr;
}

const Config* DisplayState::visual_config(int n, VisualID visual) {
  const ScreenConfigs* configs = screen(n);
  if (configs == nullptr) return nullptr;
  for (const Config& c : configs->visuals)
    if (c.visual_id == static_cast<int>(visual)) return &c;
  return nullptr;
}

const Config* DisplayState::fbconfig_for_visual(int n, int visual_id) {
  const ScreenConfigs* configs = screen(n);
  if (configs == nullptr || visual_id == 0) return nullptr;
  for (const Config& c : configs->fbconfigs)
    if (c.visual_id == visual_id) return &c;
  return nullptr;
}

namespace {

void send_error(Display* dpy, int code, XID resource, int minor) {
  DisplayState* state = DisplayState::of(dpy);
  if (state == nullptr) return;
  xError error{};
  LockDisplay(dpy);
  error.type = X_Error;
  error.errorCode = static_cast<CARD8>(code);
  error.sequenceNumber = static_cast<CARD16>(dpy->request);
  error.resourceID = static_cast<CARD32>(resource);
  error.minorCode = static_cast<CARD16>(minor);
  error.majorCode = static_cast<CARD8>(state->glx_opcode());
  _XError(dpy, &error);
  UnlockDisplay(dpy);
}

}  // namespace

XID allocate_xid(Display* dpy) {
  // Xlib hands out the next ID only once the private sync handler ran (xcb_io.c): allocate under
  // the display lock and run it, as a request of Mesa's own would.
  LockDisplay(dpy);
  const XID id = XAllocID(dpy);
  UnlockDisplay(dpy);
  SyncHandle();
  return id;
}

void send_glx_error(Display* dpy, int glx_error, XID resource, int minor) {
  DisplayState* state = DisplayState::of(dpy);
  // Without the server's GLX extension there is no GLX error code to name.
  if (state == nullptr || state->glx_opcode() == 0) return;
  send_error(dpy, state->glx_error_base() + glx_error, resource, minor);
}

void send_x_error(Display* dpy, int core_error, XID resource, int minor) {
  send_error(dpy, core_error, resource, minor);
}

}  // namespace glpt::glx
