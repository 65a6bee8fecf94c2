// Where replayed GL calls go: glpt's own front end in this process (backend "glpt") or real
// Mesa through OSMesa (backend "mesa"). Both resolve GL entry points by name for the one
// generated dispatch table, and both give the replayer headless surfaces of the recorded sizes
// in place of the trace's windows.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "replay/call_context.hpp"

namespace glpt::replay {

// A frame's image: RGBA8, opaque, rows bottom to top (GL order).
struct FrameImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

class Backend {
 public:
  using ContextHandle = void*;
  virtual ~Backend() = default;
  virtual const char* name() const = 0;

  // The backend's entry point for a GL command, or nullptr.
  virtual GlProc resolve(const char* name) = 0;

  // A context sharing display lists and texture/buffer objects with `share` (may be null).
  virtual ContextHandle create_context(ContextHandle share, std::string* error) = 0;
  virtual void destroy_context(ContextHandle context) = 0;
  // Makes `context` current on surface `surface` (the recorded drawable; created width x height
  // on first use, with one or two colour buffers); a null context releases the current one.
  virtual bool make_current(ContextHandle context, uint64_t surface, uint32_t width,
                            uint32_t height, bool double_buffered, std::string* error) = 0;
  // The current surface's size, and growing it (as glretrace grows its drawables from
  // glViewport, the sizes of windows not being in GL traces).
  virtual bool current_size(uint32_t* width, uint32_t* height) = 0;
  virtual void resize_current(uint32_t width, uint32_t height) = 0;
  // The current context starts frame `frame_index` (after make-current and after each frame
  // end): what varies per frame (path tracing's random numbers) is seeded by the index and
  // nothing carries over from earlier frames, so a frame's pixels do not depend on which frames
  // were rendered before it. Everything the frame renders, reads within it included, follows.
  // `render` false: a frame no one looks at (another shard's): the backend may skip rendering
  // it, and what it reads goes nowhere.
  virtual void begin_frame(uint64_t /*frame_index*/, bool /*render*/) {}
  // A frame builds on the history (denoiser, accumulation) of the frames before it in its window
  // of `frames` frames (0, W, 2W... start windows), and on nothing else; 1: on nothing.
  virtual void set_history_window(uint32_t /*frames*/) {}
  // The end of the current context's frame: a swap (`swap`) or the glFlush/glFinish call
  // `flush` of a single-buffered surface (called through the backend). `render` false: a frame
  // no one looks at (another shard's), which the backend may skip rendering; otherwise the
  // frame's image lands in `image`.
  virtual bool end_frame(bool swap, GlProc flush, bool render, FrameImage* image,
                         std::string* error) = 0;
  // Calls this backend counted as not implemented, by command name, summed over contexts.
  virtual std::vector<std::pair<std::string, uint64_t>> unimplemented_calls() const = 0;
  // What the last rendered frame cost (milliseconds of rendering), 0 if unknown.
  virtual double last_render_ms() const { return 0; }
};

// glpt's front end in-process. Rendering settings come from the GLPT_* environment variables
// (the command line sets them).
std::unique_ptr<Backend> create_glpt_backend(std::string* error);
// libOSMesa.so.8, loaded at run time.
std::unique_ptr<Backend> create_mesa_backend(std::string* error);

}  // namespace glpt::replay
