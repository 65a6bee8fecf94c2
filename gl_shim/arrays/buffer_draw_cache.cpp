#include "gl_shim/arrays/buffer_draw_cache.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include "common/content_hash.hpp"
#include "gl_shim/arrays/array_draws.hpp"
#include "gl_shim/context.hpp"

namespace glpt {
namespace {

// Appends words; floats go in by their bits (the record keeps -0.0 and 0.0 apart, so must the key).
class KeyWriter {
 public:
  explicit KeyWriter(BufferDrawKey& key) : key_(key) {}
  void word(uint64_t value) { key_.words.at(next_++) = value; }
  void floats(const float* values, size_t count) {
    for (size_t i = 0; i < count; ++i) {
      uint32_t bits;
      std::memcpy(&bits, &values[i], sizeof bits);
      if (half_) {
        key_.words.at(next_ - 1) |= uint64_t{bits} << 32;
      } else {
        word(bits);
      }
      half_ = !half_;
    }
  }
  void end_floats() { half_ = false; }

 private:
  BufferDrawKey& key_;
  size_t next_ = 0;
  bool half_ = false;
};

bool is_static(BufferObject& buffer) {
  const std::lock_guard lock(buffer.mutex);
  return buffer.usage == GL_STATIC_DRAW || buffer.usage == GL_STATIC_READ ||
         buffer.usage == GL_STATIC_COPY;
}

}  // namespace

size_t BufferDrawKeyHash::operator()(const BufferDrawKey& key) const {
  ContentHash hash;
  hash.add_bytes(key.words.data(), sizeof key.words);
  return static_cast<size_t>(hash.value());
}

bool draw_reads_static_buffers_only(const Context& ctx, bool indexed) {
  const VertexArrays& arrays = ctx.arrays;
  if (!arrays[ArrayKind::kVertex].enabled) return false;
  if (indexed && (!arrays.element_buffer || !is_static(*arrays.element_buffer))) return false;
  for (int k = 0; k < kArrayKinds; ++k) {
    const ClientArray& a = arrays.arrays[size_t(k)];
    if ((kDrawnArrays & (1u << k)) == 0 || !a.enabled) continue;
    if (!a.buffer || a.orphaned || !is_static(*a.buffer)) return false;
  }
  return true;
}

BufferDrawKey buffer_draw_key(const Context& ctx, GLenum mode, GLint first, GLsizei count,
                              GLenum index_type, const void* indices, uint8_t units) {
  const VertexArrays& arrays = ctx.arrays;
  BufferDrawKey key;
  KeyWriter out(key);
  out.word(mode);
  out.word(uint64_t(int64_t{first}));
  out.word(uint64_t(int64_t{count}));
  out.word(index_type);
  out.word(reinterpret_cast<uintptr_t>(indices));
  out.word(index_type != 0 ? arrays.element_buffer->contents_version() : 0);
  out.word(units);
  for (int k = 0; k < kArrayKinds; ++k) {
    if ((kDrawnArrays & (1u << k)) == 0) continue;
    const ClientArray& a = arrays.arrays[size_t(k)];
    if (!a.enabled) {
      out.word(0);
      continue;
    }
    out.word(1 | uint64_t{a.normalized} << 1 | uint64_t(uint32_t(a.size)) << 32);
    out.word(uint64_t{a.type} | uint64_t(uint32_t(a.stride)) << 32);
    out.word(reinterpret_cast<uintptr_t>(a.pointer));
    out.word(a.buffer->contents_version());
  }
  // The current values a draw records for attributes without an enabled array.
  const CurrentAttributes& c = ctx.current;
  auto current = [&](ArrayKind kind, const float* values, size_t n) {
    if (!arrays[kind].enabled) out.floats(values, n);
  };
  current(ArrayKind::kNormal, &c.normal[0], 3);
  current(ArrayKind::kColor, &c.color[0], 4);
  current(ArrayKind::kSecondaryColor, &c.secondary_color[0], 4);
  current(ArrayKind::kFogCoord, &c.fog_coord, 1);
  for (uint32_t u = 0; u < uint32_t(rec::kMaxTextureUnits); ++u)
    if ((units & (1u << u)) != 0 && !arrays.tex_coord(u).enabled) out.floats(&c.tex_coord[u][0], 4);
  out.end_floats();
  out.word(arrays[ArrayKind::kEdgeFlag].enabled ? 2 : c.edge_flag ? 1 : 0);
  return key;
}

std::shared_ptr<const rec::VertexData> BufferDrawCache::find(const BufferDrawKey& key) {
  const auto it = entries_.find(key);
  if (it == entries_.end()) return nullptr;
  it->second.last_used = record_;
  return it->second.vertices;
}

void BufferDrawCache::insert(const BufferDrawKey& key,
                             std::shared_ptr<const rec::VertexData> vertices) {
  if (!vertices) return;
  if (const auto it = entries_.find(key); it != entries_.end()) erase(it);
  const size_t bytes = vertices->bytes();
  if (bytes > kMaxBytes) return;
  while (!entries_.empty() && (entries_.size() >= kMaxEntries || bytes_ + bytes > kMaxBytes)) {
    erase(std::min_element(entries_.begin(), entries_.end(), [](const auto& a, const auto& b) {
      return a.second.last_used < b.second.last_used;
    }));
  }
  entries_.emplace(key, Entry{std::move(vertices), record_, bytes});
  bytes_ += bytes;
}

void BufferDrawCache::erase(
    std::unordered_map<BufferDrawKey, Entry, BufferDrawKeyHash>::iterator it) {
  bytes_ -= it->second.bytes;
  entries_.erase(it);
}

void BufferDrawCache::record_cleared() {
  ++record_;
  for (auto it = entries_.begin(); it != entries_.end();) {
    const auto next = std::next(it);
    if (it->second.last_used + kKeepRecords < record_) erase(it);
    it = next;
  }
}

}  // namespace glpt
