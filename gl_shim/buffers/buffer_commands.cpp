// glGenBuffers, glDeleteBuffers, glIsBuffer, glBindBuffer, glBufferData, glBufferSubData,
// glGetBufferSubData, glMapBuffer, glUnmapBuffer, glGetBufferParameteriv, glGetBufferPointerv
// (GL 1.5 2.9; the ARB_vertex_buffer_object names share these). Where GL 1.5 is silent, Mesa's
// behaviour is followed: binding a name glGenBuffers did not return creates the object
// (compatibility contexts), mapping an empty store fails with GL_INVALID_OPERATION, glBufferData
// on a mapped buffer unmaps it, and GL_BUFFER_ACCESS reads GL_READ_WRITE again once unmapped.
#include <algorithm>
#include <cstring>
#include <mutex>
#include <new>

#include "gl/gl_enums.h"
#include "gl_shim/buffers/buffer_objects.hpp"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {

ArrayBytes::ArrayBytes(const std::shared_ptr<BufferObject>& buffer, const void* pointer_or_offset) {
  if (!buffer) {
    bytes_ = static_cast<const uint8_t*>(pointer_or_offset);
    size_ = bytes_ == nullptr ? 0 : SIZE_MAX;
    return;
  }
  store_ = buffer->contents();
  const auto offset = reinterpret_cast<uintptr_t>(pointer_or_offset);
  if (offset >= store_->size()) return;
  bytes_ = store_->data() + offset;
  size_ = store_->size() - offset;
}

namespace {

// The binding point a target names; null (after GL_INVALID_ENUM) for any other target. Mesa
// checks the target, then that a buffer is bound, then the other arguments.
std::shared_ptr<BufferObject>* binding(Context& ctx, GLenum target) {
  switch (target) {
    case GL_ARRAY_BUFFER:
      return &ctx.arrays.array_buffer;
    case GL_ELEMENT_ARRAY_BUFFER:
      return &ctx.arrays.element_buffer;
    default:
      record_error(ctx, GL_INVALID_ENUM);
      return nullptr;
  }
}

// The object bound to `target`; null, after the error GL names, when the target is invalid
// (GL_INVALID_ENUM) or nothing is bound (GL_INVALID_OPERATION).
BufferObject* bound(Context& ctx, GLenum target) {
  std::shared_ptr<BufferObject>* b = binding(ctx, target);
  if (b == nullptr) return nullptr;
  if (!*b) record_error(ctx, GL_INVALID_OPERATION);
  return b->get();
}

bool valid_usage(GLenum usage) {
  switch (usage) {
    case GL_STREAM_DRAW:
    case GL_STREAM_READ:
    case GL_STREAM_COPY:
    case GL_STATIC_DRAW:
    case GL_STATIC_READ:
    case GL_STATIC_COPY:
    case GL_DYNAMIC_DRAW:
    case GL_DYNAMIC_READ:
    case GL_DYNAMIC_COPY:
      return true;
    default:
      return false;
  }
}

// The range [offset, offset + size) of `buffer`'s store, checked as glBufferSubData and
// glGetBufferSubData check it.
bool valid_range(Context& ctx, BufferObject& buffer, GLintptr offset, GLsizeiptr size) {
  if (offset < 0 || size < 0) {
    record_error(ctx, GL_INVALID_VALUE);
    return false;
  }
  if (uint64_t(offset) + uint64_t(size) > buffer.store->size()) {
    record_error(ctx, GL_INVALID_VALUE);
    return false;
  }
  if (buffer.mapped) {
    record_error(ctx, GL_INVALID_OPERATION);
    return false;
  }
  return true;
}

}  // namespace

uint64_t new_buffer_contents_version() {
  static std::atomic<uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

namespace impl {

void glGenBuffers(Context& ctx, GLsizei n, GLuint* buffers) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (buffers == nullptr) return;
  BufferStore& store = *ctx.buffers;
  const std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    GLuint name = store.next_name;
    while (name == 0 || store.objects.count(name) != 0) ++name;
    store.next_name = name + 1;
    store.objects.emplace(name, nullptr);  // reserved; an object once bound
    buffers[i] = name;
  }
}

void glDeleteBuffers(Context& ctx, GLsizei n, const GLuint* buffers) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (buffers == nullptr) return;
  BufferStore& store = *ctx.buffers;
  const std::lock_guard lock(store.mutex);
  for (GLsizei i = 0; i < n; ++i) {
    const auto it = store.objects.find(buffers[i]);
    if (buffers[i] == 0 || it == store.objects.end()) continue;  // silently ignored
    if (const std::shared_ptr<BufferObject>& object = it->second) {
      // A mapped buffer is unmapped; this context's bindings revert to zero (GL 1.5 2.9.1). Other
      // contexts, and attribute stacks, keep the object alive until they let go of it.
      object->mapped = false;
      unbind_buffer(ctx.arrays, object.get());
    }
    store.objects.erase(it);
  }
}

GLboolean glIsBuffer(Context& ctx, GLuint buffer) {
  BufferStore& store = *ctx.buffers;
  const std::lock_guard lock(store.mutex);
  const auto it = store.objects.find(buffer);
  return it != store.objects.end() && it->second != nullptr ? 1 : 0;
}

void glBindBuffer(Context& ctx, GLenum target, GLuint buffer) {
  std::shared_ptr<BufferObject>* b = binding(ctx, target);
  if (b == nullptr) return;
  if (buffer == 0) {
    b->reset();
    return;
  }
  BufferStore& store = *ctx.buffers;
  const std::lock_guard lock(store.mutex);
  std::shared_ptr<BufferObject>& object = store.objects[buffer];
  if (!object) object = std::make_shared<BufferObject>(buffer);
  *b = object;
}

void glBufferData(Context& ctx, GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  BufferObject* buffer = bound(ctx, target);
  if (buffer == nullptr) return;
  if (size < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (!valid_usage(usage)) return record_error(ctx, GL_INVALID_ENUM);
  if (uint64_t(size) > kMaxBufferBytes) return record_error(ctx, GL_OUT_OF_MEMORY);
  const std::lock_guard lock(buffer->mutex);
  buffer->mapped = false;
  buffer->access = GL_READ_WRITE;
  try {
    auto store = std::make_shared<std::vector<uint8_t>>(size_t(size), 0);
    if (data != nullptr && size > 0) std::memcpy(store->data(), data, size_t(size));
    buffer->store = std::move(store);
    buffer->contents_changed();
  } catch (const std::bad_alloc&) {
    // The old store is kept (GL 1.5 2.5: the command has no other effect).
    return record_error(ctx, GL_OUT_OF_MEMORY);
  }
  buffer->usage = usage;
}

void glBufferSubData(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr size,
                     const void* data) {
  BufferObject* buffer = bound(ctx, target);
  if (buffer == nullptr) return;
  const std::lock_guard lock(buffer->mutex);
  if (!valid_range(ctx, *buffer, offset, size)) return;
  if (data != nullptr && size > 0) std::memcpy(buffer->store->data() + offset, data, size_t(size));
  buffer->contents_changed();
}

void glGetBufferSubData(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  BufferObject* buffer = bound(ctx, target);
  if (buffer == nullptr) return;
  const std::lock_guard lock(buffer->mutex);
  if (!valid_range(ctx, *buffer, offset, size)) return;
  if (data != nullptr && size > 0) std::memcpy(data, buffer->store->data() + offset, size_t(size));
}

void* glMapBuffer(Context& ctx, GLenum target, GLenum access) {
  if (access != GL_READ_ONLY && access != GL_WRITE_ONLY && access != GL_READ_WRITE) {
    record_error(ctx, GL_INVALID_ENUM);
    return nullptr;
  }
  BufferObject* buffer = bound(ctx, target);
  if (buffer == nullptr) return nullptr;
  const std::lock_guard lock(buffer->mutex);
  if (buffer->mapped || buffer->store->empty()) {
    record_error(ctx, GL_INVALID_OPERATION);
    return nullptr;
  }
  // The program reads and writes the store itself until glUnmapBuffer; the store is not
  // reallocated while mapped (glBufferData unmaps first), so the pointer stays valid. Accesses
  // against `access` are undefined in GL and simply reach the store here.
  buffer->mapped = true;
  buffer->access = access;
  buffer->contents_changed();
  return buffer->store->data();
}

GLboolean glUnmapBuffer(Context& ctx, GLenum target) {
  BufferObject* buffer = bound(ctx, target);
  if (buffer == nullptr) return 0;
  const std::lock_guard lock(buffer->mutex);
  if (!buffer->mapped) {
    record_error(ctx, GL_INVALID_OPERATION);
    return 0;
  }
  buffer->mapped = false;
  buffer->access = GL_READ_WRITE;
  buffer->contents_changed();
  return 1;  // the store cannot be corrupted while mapped: it is glpt's own memory
}

void glGetBufferParameteriv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  BufferObject* buffer = bound(ctx, target);
  if (buffer == nullptr) return;
  if (pname != GL_BUFFER_SIZE && pname != GL_BUFFER_USAGE && pname != GL_BUFFER_ACCESS &&
      pname != GL_BUFFER_MAPPED)
    return record_error(ctx, GL_INVALID_ENUM);
  if (params == nullptr) return;
  const std::lock_guard lock(buffer->mutex);
  switch (pname) {
    case GL_BUFFER_SIZE:
      *params = GLint(std::min<size_t>(buffer->store->size(), 0x7fffffff));
      break;
    case GL_BUFFER_USAGE:
      *params = GLint(buffer->usage);
      break;
    case GL_BUFFER_ACCESS:
      *params = GLint(buffer->access);
      break;
    default:  // GL_BUFFER_MAPPED
      *params = buffer->mapped ? 1 : 0;
      break;
  }
}

void glGetBufferPointerv(Context& ctx, GLenum target, GLenum pname, void** params) {
  BufferObject* buffer = bound(ctx, target);
  if (buffer == nullptr) return;
  if (pname != GL_BUFFER_MAP_POINTER) return record_error(ctx, GL_INVALID_ENUM);
  if (params == nullptr) return;
  const std::lock_guard lock(buffer->mutex);
  *params = buffer->mapped ? buffer->store->data() : nullptr;
}

}  // namespace impl
}  // namespace glpt
