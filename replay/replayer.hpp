// Replays a stream of trace calls into a backend: GL calls through the generated dispatch, the
// window-system calls (GLX, EGL) onto the backend's headless surfaces, apitrace's fake calls
// (memcpy into mapped buffers), and frame ends (swaps; glFlush/glFinish of single-buffered
// drawables), handing the images of the frames asked for to a callback.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "replay/backend.hpp"
#include "replay/call_context.hpp"
#include "replay/trace/trace_model.hpp"

namespace glpt::replay {

struct ReplayCounts {
  uint64_t calls = 0;
  uint64_t frames = 0;           // frames ended
  uint64_t frames_rendered = 0;  // of which rendered (wanted)
  uint64_t skipped_queries = 0;  // glGet*, glIs*, ...: no side effects
  uint64_t without_context = 0;  // GL calls while no context was current
  // Calls the replayer does not know (neither GL commands glpt exports nor window-system calls
  // it maps), and GL commands the backend has no entry point for, by name.
  std::map<std::string, uint64_t> unknown;
  std::map<std::string, uint64_t> unresolved;
  uint64_t memcpy_outside_mappings = 0;
};

class Replayer {
 public:
  // Which frames to render (by index from 0, in trace order); the others replay their state
  // only. `frame_done` receives the image of each rendered frame that `write_frame` wants (all
  // of them without it; the others are rendered for the history of later ones); false +
  // message stops the replay.
  using WantFrame = std::function<bool(uint64_t frame)>;
  using FrameDone =
      std::function<bool(uint64_t frame, const FrameImage& image, std::string* error)>;

  Replayer(Backend& backend, WantFrame want_frame, FrameDone frame_done,
           WantFrame write_frame = nullptr);
  ~Replayer();

  // Replays one call. False + message on a failure that ends the replay (a backend failure,
  // the frame callback's).
  bool replay(const trace::Call& call, std::string* error);
  const ReplayCounts& counts() const { return counts_; }
  // The dispatch entries are cached by the trace reader's function signatures, which live as
  // long as their reader: a replay that opens the trace again (--repeat) calls this first, or a
  // new signature allocated where an old one was would dispatch to the old one's command.
  void forget_signatures() { entries_.clear(); }

  // The surface size glretrace starts a window with before glViewport grows it.
  static constexpr uint32_t kInitialSurfaceSize = 32;

 private:
  struct RecordedContext {
    Backend::ContextHandle handle = nullptr;
    std::unique_ptr<ReplayContextState> state;
  };
  struct Surface {
    uint32_t width = kInitialSurfaceSize, height = kInitialSurfaceSize;
    bool double_buffered = true;
    bool fixed_size = false;  // pbuffers: their size is recorded
    bool grown = false;       // a glViewport has sized it
  };

  // window_system_calls.cpp: GLX and EGL. Returns true if `name` was one of them.
  bool replay_window_system(const trace::Call& call, const std::string& name, bool* ok,
                            std::string* error);
  bool create_context(const trace::Call& call, size_t share_arg, std::string* error);
  bool make_current(uint64_t surface, uint64_t context, std::string* error);
  bool end_frame(bool swap, GlProc flush, std::string* error);
  // The calls of another recording thread follow: make its context current (all threads'
  // calls replay on this one, in trace order).
  bool switch_thread(uint32_t thread, std::string* error);

  bool replay_gl(const trace::Call& call, const std::string& name, std::string* error);
  void grow_surface(int64_t width, int64_t height);

  Backend& backend_;
  WantFrame want_frame_;
  WantFrame write_frame_;
  FrameDone frame_done_;
  GlFunctions gl_;
  ReplayCounts counts_;
  std::unordered_map<const trace::FunctionSig*, const DispatchEntry*> entries_;
  std::map<uint64_t, RecordedContext> contexts_;        // by the recorded context pointer
  std::map<uint64_t, Surface> surfaces_;                // by the recorded drawable / surface
  uint64_t current_context_ = 0, current_surface_ = 0;  // of the recording thread `thread_`
  // GL's current context is per thread: what each other recording thread had current.
  uint32_t thread_ = 0;
  std::map<uint32_t, std::pair<uint64_t, uint64_t>> thread_bindings_;  // context, surface
  bool next_double_buffered_ = true;  // what the last glXChooseVisual/FBConfig asked for
  std::map<uint64_t, bool> context_double_buffered_;  // the visual each context was made for
  GlProc flush_ = nullptr, finish_ = nullptr, scissor_ = nullptr;
};

}  // namespace glpt::replay
