// What a frame record needs of the records before it, and what it leaves for those after it.
// glpt-replay's shards skip the frames other shards write (gl_shim/frame/deferred_frames.hpp):
// a skipped frame costs only its recording when a later frame draws over everything it left,
// and is rendered when a later frame builds on its pixels (a program that does not clear, or
// draws over part of the window).
#pragma once

#include <cstdint>

#include "rt_core/record/frame_record.hpp"

namespace glpt::rec {

// The buffers of a drawable a record can depend on or change.
enum DrawableBuffer : uint8_t {
  kFrontColor = 1,
  kBackColor = 2,  // double-buffered drawables only
  kDepthBuffer = 4,
  kStencilBuffer = 8,
  kAccumBuffer = 16,
};

struct RecordAccess {
  // Buffers whose content from before the record shows in its result (drawn into, tested or
  // read before the record overwrote them whole).
  uint8_t depends = 0;
  // Buffers the record overwrites whole before anything reads them (a clear of the whole
  // drawable with every channel written; the front buffer of a double-buffered drawable at the
  // record's swap): what earlier records left there no longer matters.
  uint8_t overwrites = 0;
  // Buffers the record may change.
  uint8_t writes = 0;
};

// `swaps`: the record ends with a double-buffered swap (back -> front).
RecordAccess record_access(const FrameRecord& record, const DrawableConfig& drawable, bool swaps);

}  // namespace glpt::rec
