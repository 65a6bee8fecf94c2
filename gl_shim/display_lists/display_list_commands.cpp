// glNewList, glEndList, glCallList(s), glGenLists, glDeleteLists, glIsList, glListBase
// (GL 1.5 spec 5.4). Recording itself is generated (gl_entry_points.cpp).
#include <cmath>
#include <limits>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

void call_list(Context& ctx, GLuint name) {
  if (ctx.lists.call_depth >= DisplayListState::kMaxNesting) return;
  std::shared_ptr<const ListStream> stream;
  {
    DisplayListStore& store = *ctx.lists.store;
    std::lock_guard lock(store.mutex);
    auto it = store.lists.find(name);
    if (it == store.lists.end() || !it->second.defined) return;  // undefined lists do nothing
    stream = it->second.stream;
  }
  // Replayed without the lock (lists call lists) and without copying: the stream is immutable
  // and this call holds it.
  ++ctx.lists.call_depth;
  replay_list(ctx, *stream);
  --ctx.lists.call_depth;
}

// Size in bytes of one name of glCallLists' `type`, 0 if invalid.
int list_name_size(GLenum type) {
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE:
      return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_2_BYTES:
      return 2;
    case GL_3_BYTES:
      return 3;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT:
    case GL_4_BYTES:
      return 4;
    default:
      return 0;
  }
}

GLuint list_name_at(const void* lists, GLenum type, GLsizei i) {
  const auto* b = static_cast<const unsigned char*>(lists);
  switch (type) {
    case GL_BYTE:
      return static_cast<GLuint>(static_cast<GLint>(static_cast<const GLbyte*>(lists)[i]));
    case GL_UNSIGNED_BYTE:
      return b[i];
    case GL_SHORT:
      return static_cast<GLuint>(static_cast<GLint>(static_cast<const GLshort*>(lists)[i]));
    case GL_UNSIGNED_SHORT:
      return static_cast<const GLushort*>(lists)[i];
    case GL_INT:
      return static_cast<GLuint>(static_cast<const GLint*>(lists)[i]);
    case GL_UNSIGNED_INT:
      return static_cast<const GLuint*>(lists)[i];
    case GL_FLOAT: {
      // As Mesa: (GLint) value. A float no GLint holds (NaN, infinities, beyond 2^31) would be
      // undefined to convert; it names what x86 converts it to, INT_MIN, as in Mesa there.
      const GLfloat f = static_cast<const GLfloat*>(lists)[i];
      return static_cast<GLuint>(std::isfinite(f) && std::fabs(f) < 2147483520.0f
                                     ? static_cast<GLint>(f)
                                     : std::numeric_limits<GLint>::min());
    }
    case GL_2_BYTES:
      return (GLuint{b[2 * i]} << 8) | b[2 * i + 1];
    case GL_3_BYTES:
      return (GLuint{b[3 * i]} << 16) | (GLuint{b[3 * i + 1]} << 8) | b[3 * i + 2];
    case GL_4_BYTES:
      return (GLuint{b[4 * i]} << 24) | (GLuint{b[4 * i + 1]} << 16) | (GLuint{b[4 * i + 2]} << 8) |
             b[4 * i + 3];
    default:
      return 0;
  }
}

}  // namespace

uint32_t call_lists_bytes(GLsizei n, GLenum type) {
  return clamp_count(n) * static_cast<uint32_t>(list_name_size(type));
}

namespace impl {

void glNewList(Context& ctx, GLuint list, GLenum mode) {
  if (list == 0) return record_error(ctx, GL_INVALID_VALUE);
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE)
    return record_error(ctx, GL_INVALID_ENUM);
  if (ctx.lists.compiling()) return record_error(ctx, GL_INVALID_OPERATION);
  ctx.lists.compiling_name = list;
  ctx.lists.compiling_mode = mode;
  ctx.lists.pending = ListStream();
}

void glEndList(Context& ctx) {
  if (!ctx.lists.compiling()) return record_error(ctx, GL_INVALID_OPERATION);
  auto stream = std::make_shared<const ListStream>(std::move(ctx.lists.pending));
  ctx.lists.pending = ListStream();
  {
    DisplayListStore& store = *ctx.lists.store;
    std::lock_guard lock(store.mutex);
    DisplayListStore::Entry& entry = store.lists[ctx.lists.compiling_name];
    entry.stream = std::move(stream);
    entry.defined = true;
  }
  ctx.lists.compiling_name = 0;
  ctx.lists.compiling_mode = 0;
}

void glCallList(Context& ctx, GLuint list) {
  render_mode_flush_vertices(ctx);  // (Mesa flushes its immediate-mode vertices)
  call_list(ctx, list);
}

void glCallLists(Context& ctx, GLsizei n, GLenum type, const void* lists) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (list_name_size(type) == 0) return record_error(ctx, GL_INVALID_ENUM);
  if (lists == nullptr) return;
  render_mode_flush_vertices(ctx);
  for (GLsizei i = 0; i < n; ++i)
    call_list(ctx, ctx.lists.list_base + list_name_at(lists, type, i));
}

GLuint glGenLists(Context& ctx, GLsizei range) {
  if (range < 0) {
    record_error(ctx, GL_INVALID_VALUE);
    return 0;
  }
  if (range == 0) return 0;
  std::lock_guard lock(ctx.lists.store->mutex);
  auto& lists = ctx.lists.store->lists;
  // The first run of `range` unused names after the highest one in use (or from 1).
  GLuint start = 1;
  for (const auto& [name, entry] : lists)
    if (name >= start) start = name + 1;
  // Each reserved name is a map entry (~64 bytes): a range beyond 2^20 names in one call is
  // refused as GL_OUT_OF_MEMORY rather than exhausting the machine (no program needs more).
  constexpr GLsizei kMaxRange = GLsizei{1} << 20;
  if (range > kMaxRange ||
      static_cast<uint64_t>(start) + static_cast<uint64_t>(range) > 0xffffffffull) {
    record_error(ctx, GL_OUT_OF_MEMORY);
    return 0;
  }
  for (GLsizei i = 0; i < range; ++i)
    lists[start + static_cast<GLuint>(i)] = DisplayListStore::Entry{};
  return start;
}

void glDeleteLists(Context& ctx, GLuint list, GLsizei range) {
  if (range < 0) return record_error(ctx, GL_INVALID_VALUE);
  std::lock_guard lock(ctx.lists.store->mutex);
  auto& lists = ctx.lists.store->lists;
  if (static_cast<size_t>(range) > lists.size()) {
    std::erase_if(lists, [&](const auto& kv) {
      return kv.first >= list &&
             static_cast<uint64_t>(kv.first) < static_cast<uint64_t>(list) + range;
    });
    return;
  }
  for (GLsizei i = 0; i < range; ++i) lists.erase(list + static_cast<GLuint>(i));
}

GLboolean glIsList(Context& ctx, GLuint list) {
  std::lock_guard lock(ctx.lists.store->mutex);
  auto& lists = ctx.lists.store->lists;
  auto it = lists.find(list);
  return it != lists.end() && it->second.defined ? 1 : 0;
}

void glListBase(Context& ctx, GLuint base) { ctx.lists.list_base = base; }

}  // namespace impl
}  // namespace glpt
