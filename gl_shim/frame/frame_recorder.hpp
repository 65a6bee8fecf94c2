// Builds the frame record (rt_core/record/frame_record.hpp) from the GL calls of one frame.
//
// Consecutive primitives drawn with the same state snapshot and primitive mode are batched into
// one Draw (one glBegin/glEnd becomes one PrimitiveRange of it), so a display list of thousands
// of tiny glBegin/glEnd blocks is a handful of draws. A batch stays open, and mutable, until any
// other command is recorded or the record is sealed; then its attribute arrays are compacted (an
// attribute that never changed keeps one value). Its identity keys are hashed when a consumer
// asks (rec::VertexData::keys).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "rt_core/record/frame_record.hpp"

namespace glpt {

class FrameRecorder {
 public:
  // Appends one primitive: `primitive` holds one value per vertex for every attribute it records
  // and exactly one PrimitiveRange. It is left unspecified (moved from, or holding other
  // storage): the caller clears it before reuse.
  void add_primitive(rec::StateId state, rec::VertexData& primitive);
  // Appends one complete draw (an array draw: any number of primitives, indices allowed; an
  // attribute may hold one value for all vertices). It is never batched with others.
  // Returns the recorded vertices.
  std::shared_ptr<const rec::VertexData> add_draw(rec::StateId state, rec::VertexData&& draw);
  // Appends a draw of vertices recorded before (and never changed since): a draw from buffer
  // objects whose contents did not change (gl_shim/arrays/buffer_draw_cache.hpp).
  void add_recorded_draw(rec::StateId state, std::shared_ptr<const rec::VertexData> vertices);
  // Storage for a new draw: the cleared arrays of a spare batch (their capacity kept), or none.
  rec::VertexData take_storage();
  // Any other command ends the open batch.
  void add(rec::Command command);
  // Completes the open batch; the record is then ready for a consumer.
  void seal();
  const rec::FrameRecord& record() const { return record_; }
  rec::FrameRecord& record() { return record_; }
  // After the record was executed.
  void clear();
  bool empty() const { return record_.empty() && !open_; }
  // Vertex bytes held by the record (a frame that never ends is executed early past a limit).
  size_t vertex_bytes() const { return vertex_bytes_; }
  // Counts additions (commands, primitives) and clears: unchanged means nothing was recorded
  // since, so the last command is still the one added then (gl_shim/pixels/bitmap_cache.hpp).
  uint64_t events() const { return events_; }

 private:
  rec::FrameRecord record_;
  std::shared_ptr<rec::VertexData> open_;
  // Draws of cleared records that nothing else held: a new batch reuses their arrays' storage, so
  // a program drawing megabytes of vertices per frame does not allocate (and page-fault in) them
  // again every frame.
  std::vector<std::shared_ptr<rec::VertexData>> spare_;
  size_t spare_bytes_ = 0;  // what the spares' arrays have allocated
  rec::StateId open_state_ = 0;
  size_t vertex_bytes_ = 0;
  uint64_t events_ = 0;
};

// Empties every array of `data` (attributes, indices, primitives), keeping their storage.
void clear_vertex_arrays(rec::VertexData& data);

// Shrinks attributes whose values are all equal to one value (exposed for tests).
void finish_vertex_data(rec::VertexData& data);

}  // namespace glpt
