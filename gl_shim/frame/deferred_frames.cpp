#include "gl_shim/frame/deferred_frames.hpp"

#include <utility>

namespace glpt {

void DeferredFrames::render_all(const Execute& execute) {
  // Taken out first: a failing or throwing render leaves nothing held twice.
  std::vector<Held> held = std::move(held_);
  held_.clear();
  dirty_ = 0;
  bytes_ = 0;
  for (const Held& h : held) {
    execute(h.record, h.swap, h.frame);
    ++rendered_;
  }
}

void DeferredFrames::drop() noexcept {
  dropped_ += held_.size();
  held_.clear();
  dirty_ = 0;
  bytes_ = 0;
}

bool DeferredFrames::before_render(const rec::FrameRecord& next,
                                   const rec::DrawableConfig& drawable, bool next_swaps,
                                   const Execute& execute) {
  if (held_.empty()) return false;
  const rec::RecordAccess access = rec::record_access(next, drawable, next_swaps);
  // Nothing held shows in `next`, and `next` overwrites everything the held records changed:
  // they can never show. Otherwise they are rendered before it.
  if ((access.depends & dirty_) == 0 && (access.overwrites & dirty_) == dirty_) {
    drop();
    return false;
  }
  render_all(execute);
  return true;
}

void DeferredFrames::skip(rec::FrameRecord&& record, const rec::DrawableConfig& drawable, bool swap,
                          uint64_t frame, size_t vertex_bytes, const Execute& execute) {
  const rec::RecordAccess access = rec::record_access(record, drawable, swap);
  if (!held_.empty()) {
    if ((access.depends & dirty_) != 0) {
      render_all(execute);  // it builds on what is held
    } else if ((access.overwrites & dirty_) == dirty_) {
      drop();  // it covers everything held
    }
  }
  // What the held records changed and this one overwrites no longer matters; what it changes
  // does.
  dirty_ = static_cast<uint8_t>((dirty_ & ~access.overwrites) | access.writes);
  held_.push_back({std::move(record), swap, frame});
  bytes_ += vertex_bytes;
  if (bytes_ > kMaxHeldBytes) render_all(execute);
}

}  // namespace glpt
