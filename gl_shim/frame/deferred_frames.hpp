// The frames glpt-replay skips (Context::render_frame_ends false: another shard writes them),
// held unrendered for as long as no later frame needs their pixels. A shard should cost only the
// recording of the frames it skips, yet write exactly the frames one whole replay writes: most
// programs clear the whole window every frame, so the frames before such a frame are dropped;
// a program that draws over what it drew before (no clear, a partial one, the front buffer, the
// accumulation buffer) gets the skipped frames it builds on rendered first, in order.
//
// Held records are bounded (kMaxHeldBytes of vertices): past it they are rendered.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "rt_core/record/frame_record.hpp"
#include "rt_core/record/record_dependencies.hpp"

namespace glpt {

class DeferredFrames {
 public:
  static constexpr size_t kMaxHeldBytes = size_t{256} << 20;
  // Renders one held record on the drawable (`swap`: it ended with a double-buffered swap;
  // `frame`: the index of the frame it was recorded in, which seeds its random numbers).
  using Execute = std::function<bool(const rec::FrameRecord& record, bool swap, uint64_t frame)>;

  // A skipped frame (or the part of one before the drawable changed) ends: `record` is held,
  // unless what is held already can be dropped (it overwrites everything they left) or must be
  // rendered now (it builds on it, or the held records grew past kMaxHeldBytes).
  void skip(rec::FrameRecord&& record, const rec::DrawableConfig& drawable, bool swap,
            uint64_t frame, size_t vertex_bytes, const Execute& execute);
  // `next` is about to be rendered: the held records are dropped when nothing of them shows in
  // it or after it, else rendered first, in order. Returns whether any was rendered.
  bool before_render(const rec::FrameRecord& next, const rec::DrawableConfig& drawable,
                     bool next_swaps, const Execute& execute);
  // Renders everything held now (the drawable is about to change).
  void render_all(const Execute& execute);
  // Forgets everything held (the context or its drawable went away).
  void drop() noexcept;

  size_t held() const { return held_.size(); }
  // Records dropped and rendered so far (for tests and statistics).
  uint64_t dropped() const { return dropped_; }
  uint64_t rendered() const { return rendered_; }

 private:
  struct Held {
    rec::FrameRecord record;
    bool swap = false;
    uint64_t frame = 0;
  };
  std::vector<Held> held_;
  uint8_t dirty_ = 0;  // buffers the held records may have changed (rec::DrawableBuffer)
  size_t bytes_ = 0;
  uint64_t dropped_ = 0, rendered_ = 0;
};

}  // namespace glpt
