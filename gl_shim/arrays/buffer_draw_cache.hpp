// Draws that read only buffer objects (GL 1.5 2.9) read the same vertices again as long as the
// buffers' contents, the array pointers and the current values the draw falls back to are
// unchanged. A program drawing a static VBO every frame then need not have 300 000 vertices read,
// converted and copied each frame (Mesa's llvmpipe reads a VBO in place): the cache hands the
// draw's recorded rec::VertexData out again, the same immutable object, so consumers keep what
// they derived from it too (rt_core's resident geometry, the path tracer's acceleration
// structures, both by its content id).
//
// Only live glDrawArrays and glDrawElements in GL_RENDER mode are cached; every enabled array
// they read, and glDrawElements' indices, must come from buffer objects the program declared
// static (GL_STATIC_DRAW, _READ, _COPY: GL 1.5 2.9's usage hint). Dynamic and stream buffers
// change every frame or so: caching them would only hold on to stale vertices (and keep the
// recorder from reusing their storage). A key holds everything the recorded vertices are a
// function of (BufferDrawKey); buffer contents enter by version
// (BufferObject::contents_version), never by hashing their bytes.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "gl_shim/gl_types.h"
#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;

// What a cached draw's vertices depend on, as words compared and hashed whole (no padding).
struct BufferDrawKey {
  static constexpr size_t kWords = 72;
  std::array<uint64_t, kWords> words{};
  bool operator==(const BufferDrawKey&) const = default;
};

struct BufferDrawKeyHash {
  size_t operator()(const BufferDrawKey& key) const;
};

// Whether every array a draw reads (and, for glDrawElements, `indexed`, its indices) comes from a
// static buffer object: the draws a key can be made for. Cheap; checked before anything else.
bool draw_reads_static_buffers_only(const Context& ctx, bool indexed);

// The key of a draw of `count` vertices of `mode` from `first` (glDrawArrays: `index_type` 0)
// or of `count` indices of `index_type` at offset `indices` into the element buffer
// (glDrawElements), drawn with texture units `units` sampled. Only for draws that
// draw_reads_static_buffers_only accepts.
BufferDrawKey buffer_draw_key(const Context& ctx, GLenum mode, GLint first, GLsizei count,
                              GLenum index_type, const void* indices, uint8_t units);

class BufferDrawCache {
 public:
  // Entries not drawn in this many records in a row are dropped.
  static constexpr uint64_t kKeepRecords = 4;
  // At most this many entries and bytes of vertices; the least recently drawn go first.
  static constexpr size_t kMaxEntries = 256;
  static constexpr size_t kMaxBytes = size_t{512} << 20;

  // The vertices recorded for `key`, or null.
  std::shared_ptr<const rec::VertexData> find(const BufferDrawKey& key);
  void insert(const BufferDrawKey& key, std::shared_ptr<const rec::VertexData> vertices);
  // A record was executed and cleared.
  void record_cleared();
  size_t size() const { return entries_.size(); }
  size_t bytes() const { return bytes_; }

 private:
  struct Entry {
    std::shared_ptr<const rec::VertexData> vertices;
    uint64_t last_used = 0;
    size_t bytes = 0;
  };
  void erase(std::unordered_map<BufferDrawKey, Entry, BufferDrawKeyHash>::iterator it);
  std::unordered_map<BufferDrawKey, Entry, BufferDrawKeyHash> entries_;
  uint64_t record_ = 0;
  size_t bytes_ = 0;
};

}  // namespace glpt
