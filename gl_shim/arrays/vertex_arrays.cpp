#include "gl_shim/arrays/vertex_arrays.hpp"

#include "gl/gl_enums.h"

namespace glpt {
namespace {

size_t type_bytes(GLenum type) {
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE:
      return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
      return 2;
    case GL_DOUBLE:
      return 8;
    default:  // GL_INT, GL_UNSIGNED_INT, GL_FLOAT
      return 4;
  }
}

ClientArray array_of(GLint size, GLenum type, bool normalized) {
  ClientArray a;
  a.size = size;
  a.type = type;
  a.normalized = normalized;
  return a;
}

}  // namespace

size_t ClientArray::element_bytes() const { return size_t(size) * type_bytes(type); }

// GL 1.5 tables 6.6-6.7: every array starts disabled, GL_FLOAT, stride 0, pointer 0, with the
// largest size its command accepts (the edge flag array is of GLboolean).
std::array<ClientArray, kArrayKinds> VertexArrays::initial_arrays() {
  std::array<ClientArray, kArrayKinds> a;
  a[size_t(ArrayKind::kVertex)] = array_of(4, GL_FLOAT, false);
  a[size_t(ArrayKind::kNormal)] = array_of(3, GL_FLOAT, true);
  a[size_t(ArrayKind::kColor)] = array_of(4, GL_FLOAT, true);
  a[size_t(ArrayKind::kSecondaryColor)] = array_of(3, GL_FLOAT, true);
  a[size_t(ArrayKind::kFogCoord)] = array_of(1, GL_FLOAT, false);
  a[size_t(ArrayKind::kIndex)] = array_of(1, GL_FLOAT, false);
  a[size_t(ArrayKind::kEdgeFlag)] = array_of(1, GL_UNSIGNED_BYTE, false);
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    a[size_t(ArrayKind::kTexCoord0) + size_t(u)] = array_of(4, GL_FLOAT, false);
  return a;
}

ClientArray* client_state_array(VertexArrays& arrays, GLenum cap, uint32_t client_active_unit) {
  switch (cap) {
    case GL_VERTEX_ARRAY:
      return &arrays[ArrayKind::kVertex];
    case GL_NORMAL_ARRAY:
      return &arrays[ArrayKind::kNormal];
    case GL_COLOR_ARRAY:
      return &arrays[ArrayKind::kColor];
    case GL_SECONDARY_COLOR_ARRAY:
      return &arrays[ArrayKind::kSecondaryColor];
    case GL_FOG_COORD_ARRAY:
      return &arrays[ArrayKind::kFogCoord];
    case GL_INDEX_ARRAY:
      return &arrays[ArrayKind::kIndex];
    case GL_EDGE_FLAG_ARRAY:
      return &arrays[ArrayKind::kEdgeFlag];
    case GL_TEXTURE_COORD_ARRAY:
      return &arrays.tex_coord(client_active_unit);
    default:
      return nullptr;
  }
}

void unbind_buffer(VertexArrays& arrays, const BufferObject* buffer) {
  if (arrays.array_buffer.get() == buffer) arrays.array_buffer.reset();
  if (arrays.element_buffer.get() == buffer) arrays.element_buffer.reset();
  for (ClientArray& a : arrays.arrays) {
    if (a.buffer.get() != buffer) continue;
    a.buffer.reset();
    a.orphaned = true;
  }
}

bool enabled_array_is_mapped(const VertexArrays& arrays) {
  for (const ClientArray& a : arrays.arrays)
    if (a.enabled && a.buffer && a.buffer->mapped) return true;
  return false;
}

}  // namespace glpt
