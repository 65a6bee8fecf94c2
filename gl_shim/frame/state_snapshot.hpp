// Turns the live GL state into the frame record's immutable, deduplicated state snapshots.
//
// Called at every draw (and every clear or pixel command), so it must be cheap when nothing
// changed: each block is compared with the block the previous snapshot used and only copied when
// it differs; a snapshot is appended to the record only when one of its blocks changed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_set>

#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;

class StateSnapshotter {
 public:
  // The id in `record` of a snapshot of the current state.
  // Non-const: the modelview's inverse is analysed lazily (Mesa's way), if not yet done.
  rec::StateId capture(Context& ctx, rec::FrameRecord& record);
  // The record's states were cleared (it was executed): the next capture starts a new table.
  // The blocks themselves are kept, so an unchanged state shares them across frames.
  void record_cleared() {
    last_id_.reset();
    texture_versions_.clear();
    texture_bytes_ = 0;
  }
  // Bytes of texels of the distinct texture contents the record's snapshots sample: a program
  // that replaces its textures at every draw (a video, piglit streaming-texture-leak) fills
  // memory with them unless the record is executed (note_frame_content).
  size_t texture_bytes() const { return texture_bytes_; }

 private:
  std::shared_ptr<const rec::TransformState> transform_;
  std::shared_ptr<const rec::LightingState> lighting_;
  std::shared_ptr<const rec::TexturingState> texturing_;
  std::shared_ptr<const rec::RasterState> raster_;
  std::shared_ptr<const rec::PixelTransferState> pixel_transfer_;
  std::optional<rec::StateId> last_id_;
  std::unordered_set<uint64_t> texture_versions_;  // content versions counted in texture_bytes_
  size_t texture_bytes_ = 0;
  // Built at every capture and compared with the current block; kept to reuse its storage.
  rec::TransformState transform_scratch_;
  rec::TexturingState texturing_scratch_;

  void count_textures(const rec::TexturingState& texturing);
};

}  // namespace glpt
