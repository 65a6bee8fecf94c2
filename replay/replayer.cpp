#include "replay/replayer.hpp"

#include <algorithm>

#include "replay/special_calls.hpp"

namespace glpt::replay {
namespace {

GlProc resolve_through(void* backend, const char* name) {
  return static_cast<Backend*>(backend)->resolve(name);
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// Commands without side effects: apitrace records their results, the replay needs none.
bool is_query(const std::string& name) {
  return starts_with(name, "glGet") || starts_with(name, "glIs") ||
         name == "glAreTexturesResident" || name == "glAreTexturesResidentEXT";
}

// Markers and debug calls that do not change GL state (apitrace's own and GREMEDY's).
bool is_marker(const std::string& name) {
  return name == "glStringMarkerGREMEDY" || name == "glFrameTerminatorGREMEDY" ||
         starts_with(name, "glDebugMessage") || starts_with(name, "glPushDebugGroup") ||
         starts_with(name, "glPopDebugGroup") || starts_with(name, "glObjectLabel");
}

}  // namespace

Replayer::Replayer(Backend& backend, WantFrame want_frame, FrameDone frame_done,
                   WantFrame write_frame)
    : backend_(backend),
      want_frame_(std::move(want_frame)),
      write_frame_(write_frame ? std::move(write_frame) : want_frame_),
      frame_done_(std::move(frame_done)),
      gl_(&resolve_through, &backend) {
  flush_ = backend_.resolve("glFlush");
  finish_ = backend_.resolve("glFinish");
  scissor_ = backend_.resolve("glScissor");
}

Replayer::~Replayer() {
  backend_.make_current(nullptr, 0, 0, 0, false, nullptr);
  for (auto& [id, context] : contexts_) backend_.destroy_context(context.handle);
}

bool Replayer::replay(const trace::Call& call, std::string* error) {
  ++counts_.calls;
  if (call.sig == nullptr) {
    ++counts_.unknown["(call without a signature)"];
    return true;
  }
  const std::string& name = call.sig->name;
  if (call.thread != thread_ && !switch_thread(call.thread, error)) return false;
  bool ok = true;
  if (replay_window_system(call, name, &ok, error)) return ok;
  if (name == "memcpy") {
    const auto it = contexts_.find(current_context_);
    if (it != contexts_.end() && !replay_memcpy(call, *it->second.state))
      ++counts_.memcpy_outside_mappings;
    return true;
  }
  if (starts_with(name, "gl") && !starts_with(name, "glX")) return replay_gl(call, name, error);
  ++counts_.unknown[name];
  return true;
}

bool Replayer::replay_gl(const trace::Call& call, const std::string& name, std::string* error) {
  if (is_query(name) || is_marker(name)) {
    ++counts_.skipped_queries;
    return true;
  }
  const auto found = entries_.find(call.sig);
  const DispatchEntry* entry =
      found != entries_.end() ? found->second : find_dispatch_entry(call.sig->name);
  if (found == entries_.end()) entries_.emplace(call.sig, entry);
  if (entry == nullptr) {
    ++counts_.unknown[name];
    return true;
  }
  const auto context = contexts_.find(current_context_);
  if (context == contexts_.end()) {
    ++counts_.without_context;
    return true;
  }
  ReplayContextState& state = *context->second.state;
  // apitrace's frame markers: glFlush/glFinish end a frame of a single-buffered drawable.
  const auto surface = surfaces_.find(current_surface_);
  if ((name == "glFlush" || name == "glFinish") && surface != surfaces_.end() &&
      !surface->second.double_buffered)
    return end_frame(/*swap=*/false, name == "glFlush" ? flush_ : finish_, error);

  const GlProc proc = gl_.proc(static_cast<size_t>(entry - kDispatchTable));
  if (proc == nullptr) {
    ++counts_.unresolved[name];
    return true;
  }
  if (name == "glClientActiveTexture" || name == "glClientActiveTextureARB")
    state.client_texture_unit = static_cast<GLenum>(call.args.empty() ? 0 : call.args[0].as_uint());
  CallContext c(call, proc, state, gl_);
  entry->fn(c);
  if (name == "glViewport" && call.args.size() >= 4)
    grow_surface(call.args[0].as_sint() + call.args[2].as_sint(),
                 call.args[1].as_sint() + call.args[3].as_sint());
  return true;
}

// glretrace's rule (window sizes are not in GL traces): a window surface starts small and grows
// to cover every viewport set on it; its first growth also sets the scissor box to the whole
// surface, as a window of that size would have had it.
void Replayer::grow_surface(int64_t width, int64_t height) {
  const auto it = surfaces_.find(current_surface_);
  if (it == surfaces_.end() || it->second.fixed_size || width <= 0 || height <= 0) return;
  // Larger than any screen, and small enough that a hostile trace cannot ask for buffers of
  // gigabytes: sides up to 8192, at most 2^25 pixels.
  constexpr int64_t kMaxSize = 8192, kMaxPixels = int64_t{1} << 25;
  Surface& s = it->second;
  const bool first = !s.grown;
  if (!first && width <= s.width && height <= s.height) return;
  s.width = static_cast<uint32_t>(std::clamp<int64_t>(width, first ? 1 : s.width, kMaxSize));
  s.height = static_cast<uint32_t>(std::clamp<int64_t>(height, first ? 1 : s.height, kMaxSize));
  while (int64_t{s.width} * s.height > kMaxPixels) s.height /= 2;
  s.grown = true;
  backend_.resize_current(s.width, s.height);
  if (scissor_ != nullptr)
    reinterpret_cast<void (*)(GLint, GLint, GLsizei, GLsizei)>(scissor_)(
        0, 0, static_cast<GLsizei>(s.width), static_cast<GLsizei>(s.height));
}

bool Replayer::switch_thread(uint32_t thread, std::string* error) {
  thread_bindings_[thread_] = {current_context_, current_surface_};
  const auto [context, surface] = thread_bindings_[thread];
  thread_ = thread;
  current_context_ = current_surface_ = 0;
  const auto c = contexts_.find(context);
  const auto s = surfaces_.find(surface);
  if (context == 0 || c == contexts_.end() || s == surfaces_.end())
    return backend_.make_current(nullptr, 0, 0, 0, false, error);
  current_context_ = context;
  current_surface_ = surface;
  return backend_.make_current(c->second.handle, surface, s->second.width, s->second.height,
                               s->second.double_buffered, error);
}

bool Replayer::end_frame(bool swap, GlProc flush, std::string* error) {
  const uint64_t frame = counts_.frames++;
  if (contexts_.find(current_context_) == contexts_.end()) return true;
  const bool render = want_frame_(frame);
  const bool write = render && write_frame_(frame);
  FrameImage image;
  const bool ended = backend_.end_frame(swap, flush, render, write ? &image : nullptr, error);
  backend_.begin_frame(counts_.frames, want_frame_(counts_.frames));
  if (!ended) return false;
  if (!render) return true;
  ++counts_.frames_rendered;
  if (!write) return true;
  if (image.rgba.empty()) return true;  // nothing presented (no drawable, renderer failed)
  return frame_done_(frame, image, error);
}

}  // namespace glpt::replay
