// The client vertex arrays (GL 1.5 2.8) and the buffer bindings that go with them (2.9): the
// "vertex-array" client attribute group of GL 1.5 tables 6.6-6.8. Pointers are kept as given;
// draws read and convert the arrays when they are recorded (array_draws.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "gl_shim/buffers/buffer_objects.hpp"
#include "gl_shim/gl_types.h"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

struct ClientArray {
  bool enabled = false;
  GLint size = 4;           // components per element
  GLenum type = 0x1406;     // GL_FLOAT
  GLsizei stride = 0;       // as given (0: tightly packed)
  bool normalized = false;  // integer components map to [0, 1] / [-1, 1] (colours, normals)
  // A client address, or an offset into `buffer` when one was bound to GL_ARRAY_BUFFER when the
  // pointer was specified.
  const void* pointer = nullptr;
  std::shared_ptr<BufferObject> buffer;
  // The buffer object the offset referred to was deleted: GL reverts the binding to zero, which
  // would make the offset a client address; draws read nothing from such an array instead.
  bool orphaned = false;

  size_t element_bytes() const;
  size_t effective_stride() const { return stride != 0 ? size_t(stride) : element_bytes(); }
  GLuint buffer_name() const { return buffer ? buffer->name() : 0; }
};

enum class ArrayKind : uint8_t {
  kVertex,
  kNormal,
  kColor,
  kSecondaryColor,
  kFogCoord,
  kIndex,
  kEdgeFlag,
  kTexCoord0,  // ... kTexCoord0 + rec::kMaxTextureUnits - 1
};
inline constexpr int kArrayKinds = int(ArrayKind::kTexCoord0) + rec::kMaxTextureUnits;

struct VertexArrays {
  std::array<ClientArray, kArrayKinds> arrays = initial_arrays();
  // GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER (null: zero, client memory).
  std::shared_ptr<BufferObject> array_buffer;
  std::shared_ptr<BufferObject> element_buffer;
  // EXT_compiled_vertex_array: glLockArraysEXT's range (count 0: unlocked). glpt converts arrays
  // at every draw, so locking changes nothing but these queries.
  GLint lock_first = 0;
  GLsizei lock_count = 0;

  ClientArray& operator[](ArrayKind kind) { return arrays[size_t(kind)]; }
  const ClientArray& operator[](ArrayKind kind) const { return arrays[size_t(kind)]; }
  ClientArray& tex_coord(uint32_t unit) { return arrays[size_t(ArrayKind::kTexCoord0) + unit]; }
  const ClientArray& tex_coord(uint32_t unit) const {
    return arrays[size_t(ArrayKind::kTexCoord0) + unit];
  }

  static std::array<ClientArray, kArrayKinds> initial_arrays();
};

// The array a client-state capability (GL_VERTEX_ARRAY, ..., GL_TEXTURE_COORD_ARRAY of the client
// active texture unit) names; null for any other enum.
ClientArray* client_state_array(VertexArrays& arrays, GLenum cap, uint32_t client_active_unit);

// Every binding of `buffer` among the arrays and targets reverts to zero (glDeleteBuffers in this
// context, GL 1.5 2.9.1).
void unbind_buffer(VertexArrays& arrays, const BufferObject* buffer);

// Whether an enabled array sources its data from a mapped buffer object (draws then fail with
// GL_INVALID_OPERATION, GL 1.5 2.9.3).
bool enabled_array_is_mapped(const VertexArrays& arrays);

}  // namespace glpt
