// Everything a path-traced image depends on, for deciding whether a frame may be accumulated onto
// the previous one: the record's commands up to and including the traced draws (the G-buffer
// pass: their kinds, state snapshots, geometry and attribute identities, clear values) and the
// drawable. The draws rasterized after the trace are not part of it: they are drawn anew over
// the image every frame.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rt_core/record/frame_record.hpp"

namespace glpt::rt {

class FrameSignature {
 public:
  FrameSignature() = default;  // equal to no frame's signature
  // `commands`: indices into `record` of the commands the traced image depends on.
  FrameSignature(const rec::FrameRecord& record, std::span<const size_t> commands,
                 const rec::DrawableConfig& drawable);

  // State blocks compare by pointer first (blocks are shared while unchanged), then by value.
  bool operator==(const FrameSignature& other) const;

 private:
  struct Entry {
    uint32_t kind = 0;  // the Command alternative
    uint64_t geometry_key = 0, attribute_key = 0;
    rec::StateSnapshot state;
    // Clear: mask, colour, depth, stencil as raw bits (NaNs compare equal to themselves).
    uint32_t clear[8] = {};  // mask, colour, depth (a double), stencil
  };
  static bool same(const Entry& a, const Entry& b);

  bool valid_ = false;
  rec::DrawableConfig drawable_;
  std::vector<Entry> entries_;
};

}  // namespace glpt::rt
