// The trace's window-system calls (GLX, EGL) mapped to the backend's headless surfaces: context
// creation with share lists, make-current on a surface of the recorded size, swaps as frame
// ends. No X server or EGL display is involved. Sizes follow glretrace: pbuffers have theirs in
// the trace; windows start small and grow with glViewport (Replayer::grow_surface).
#include "gl/glx_enums.h"
#include "replay/replayer.hpp"

namespace glpt::replay {
namespace {

constexpr int64_t kEglWidth = 0x3057, kEglHeight = 0x3056, kEglNone = 0x3038,
                  kEglRenderBuffer = 0x3086, kEglSingleBuffer = 0x3085;

const trace::Value& arg(const trace::Call& call, size_t i) {
  static const trace::Value kNull;
  return i < call.args.size() ? call.args[i] : kNull;
}

// The value of `attribute` in a (name, value) list ending at `terminator`, or `fallback`.
int64_t attribute(const trace::Value& list, int64_t name, int64_t fallback, int64_t terminator) {
  const auto& e = list.elements;
  for (size_t i = 0; i + 1 < e.size(); i += 2) {
    if (e[i].as_sint() == terminator) break;
    if (e[i].as_sint() == name) return e[i + 1].as_sint();
  }
  return fallback;
}

// glXChooseVisual's list: GLX_USE_GL, GLX_RGBA, GLX_DOUBLEBUFFER and GLX_STEREO stand alone,
// every other attribute takes a value. Double-buffered iff GLX_DOUBLEBUFFER is there.
bool chooses_double_buffer_visual(const trace::Value& list) {
  const auto& e = list.elements;
  for (size_t i = 0; i < e.size(); ++i) {
    const int64_t a = e[i].as_sint();
    if (a == 0) break;
    if (a == GLX_DOUBLEBUFFER) return true;
    if (a != GLX_USE_GL && a != GLX_RGBA && a != GLX_STEREO) ++i;
  }
  return false;
}

uint32_t clamp_size(int64_t size) {
  return static_cast<uint32_t>(std::clamp<int64_t>(size, 1, 16384));
}

}  // namespace

bool Replayer::replay_window_system(const trace::Call& call, const std::string& name, bool* ok,
                                    std::string* error) {
  const bool glx = name.rfind("glX", 0) == 0, egl = name.rfind("egl", 0) == 0;
  if (!glx && !egl) return false;
  *ok = true;
  if (name == "glXChooseVisual") {
    next_double_buffered_ = chooses_double_buffer_visual(arg(call, 2));
  } else if (name == "glXChooseFBConfig" || name == "glXChooseFBConfigSGIX") {
    // GLX 1.4 3.3.3: GLX_DOUBLEBUFFER defaults to GLX_DONT_CARE (Mesa sorts double first).
    next_double_buffered_ = attribute(arg(call, 2), GLX_DOUBLEBUFFER, 1, 0) != 0;
  } else if (name == "eglChooseConfig") {
    next_double_buffered_ = true;  // EGL window surfaces render to the back buffer by default
  } else if (name == "glXCreateContext" || name == "glXCreateContextAttribsARB" ||
             name == "eglCreateContext") {
    *ok = create_context(call, 2, error);
  } else if (name == "glXCreateNewContext" || name == "glXCreateContextWithConfigSGIX") {
    *ok = create_context(call, 3, error);
  } else if (name == "glXDestroyContext" || name == "eglDestroyContext") {
    const auto it = contexts_.find(arg(call, 1).as_uint());
    if (it != contexts_.end()) {
      if (current_context_ == it->first) {
        backend_.make_current(nullptr, 0, 0, 0, false, nullptr);
        current_context_ = 0;
      }
      backend_.destroy_context(it->second.handle);
      contexts_.erase(it);
    }
  } else if (name == "glXMakeCurrent") {
    if (call.ret.kind == trace::ValueKind::Null || call.ret.as_uint() != 0)
      *ok = make_current(arg(call, 1).as_uint(), arg(call, 2).as_uint(), error);
  } else if (name == "glXMakeContextCurrent" || name == "eglMakeCurrent") {
    if (call.ret.kind == trace::ValueKind::Null || call.ret.as_uint() != 0)
      *ok = make_current(arg(call, 1).as_uint(), arg(call, 3).as_uint(), error);
  } else if (name == "glXCreatePbuffer") {
    Surface& s = surfaces_[call.ret.as_uint()];
    s.width = clamp_size(attribute(arg(call, 2), GLX_PBUFFER_WIDTH, 0, 0));
    s.height = clamp_size(attribute(arg(call, 2), GLX_PBUFFER_HEIGHT, 0, 0));
    s.fixed_size = true;
  } else if (name == "eglCreatePbufferSurface") {
    Surface& s = surfaces_[call.ret.as_uint()];
    s.width = clamp_size(attribute(arg(call, 2), kEglWidth, 0, kEglNone));
    s.height = clamp_size(attribute(arg(call, 2), kEglHeight, 0, kEglNone));
    s.fixed_size = true;
  } else if (name == "eglCreateWindowSurface" || name == "eglCreatePlatformWindowSurface") {
    surfaces_[call.ret.as_uint()].double_buffered =
        attribute(arg(call, 3), kEglRenderBuffer, 0, kEglNone) != kEglSingleBuffer;
  } else if ((call.sig->flags & trace::kCallFlagSwapRenderTarget) != 0) {
    // glXSwapBuffers, glXSwapBuffersMscOML, eglSwapBuffers, eglSwapBuffersWithDamage*: the
    // reader flags them as apitrace does.
    const auto it = surfaces_.find(current_surface_);
    const bool swap = it == surfaces_.end() || it->second.double_buffered;
    *ok = end_frame(swap, swap ? nullptr : flush_, error);
  }
  // Every other GLX/EGL call (queries, displays, configs, windows, swap intervals) has nothing
  // to replay on headless surfaces.
  return true;
}

bool Replayer::create_context(const trace::Call& call, size_t share_arg, std::string* error) {
  const uint64_t recorded = call.ret.as_uint();
  if (recorded == 0) return true;  // creation failed when recording
  const auto share = contexts_.find(arg(call, share_arg).as_uint());
  const bool shares = share != contexts_.end() && arg(call, share_arg).as_uint() != 0;
  RecordedContext context;
  context.handle = backend_.create_context(shares ? share->second.handle : nullptr, error);
  if (context.handle == nullptr) return false;
  context.state = std::make_unique<ReplayContextState>();
  if (shares) context.state->names = share->second.state->names;
  auto existing = contexts_.find(recorded);
  if (existing != contexts_.end()) backend_.destroy_context(existing->second.handle);
  contexts_[recorded] = std::move(context);
  context_double_buffered_[recorded] = next_double_buffered_;
  return true;
}

bool Replayer::make_current(uint64_t surface, uint64_t context, std::string* error) {
  const auto it = contexts_.find(context);
  if (context == 0 || it == contexts_.end()) {
    current_context_ = current_surface_ = 0;
    return backend_.make_current(nullptr, 0, 0, 0, false, error);
  }
  // A surface first seen here is a window of the context's visual.
  auto [s, inserted] = surfaces_.try_emplace(surface);
  if (inserted) s->second.double_buffered = context_double_buffered_[context];
  current_context_ = context;
  current_surface_ = surface;
  if (!backend_.make_current(it->second.handle, surface, s->second.width, s->second.height,
                             s->second.double_buffered, error))
    return false;
  backend_.begin_frame(counts_.frames, want_frame_(counts_.frames));
  return true;
}

}  // namespace glpt::replay
