// glVertexPointer ... glEdgeFlagPointer (and their EXT_vertex_array variants),
// glEnableClientState/glDisableClientState, glInterleavedArrays, glLockArraysEXT/glUnlockArraysEXT
// and glGetPointerv (GL 1.5 2.8, 6.1.11; EXT_compiled_vertex_array).
//
// Accepted sizes and types are GL 1.5 table 2.4's, with one exception taken from Mesa: a secondary
// colour array may have 4 components (Mesa accepts it; the fourth is ignored). Errors are checked
// in Mesa's order: a negative stride first, then the type, then the size.
#include <cstdint>

#include "gl/gl_enums.h"
#include "gl_shim/arrays/vertex_arrays.hpp"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

enum TypeBits : uint32_t {
  kByte = 1u << 0,
  kUnsignedByte = 1u << 1,
  kShort = 1u << 2,
  kUnsignedShort = 1u << 3,
  kInt = 1u << 4,
  kUnsignedInt = 1u << 5,
  kFloat = 1u << 6,
  kDouble = 1u << 7,
};

uint32_t type_bit(GLenum type) {
  switch (type) {
    case GL_BYTE:
      return kByte;
    case GL_UNSIGNED_BYTE:
      return kUnsignedByte;
    case GL_SHORT:
      return kShort;
    case GL_UNSIGNED_SHORT:
      return kUnsignedShort;
    case GL_INT:
      return kInt;
    case GL_UNSIGNED_INT:
      return kUnsignedInt;
    case GL_FLOAT:
      return kFloat;
    case GL_DOUBLE:
      return kDouble;
    default:
      return 0;
  }
}

constexpr uint32_t kAllTypes =
    kByte | kUnsignedByte | kShort | kUnsignedShort | kInt | kUnsignedInt | kFloat | kDouble;

// One row of GL 1.5 table 2.4.
struct ArrayRules {
  GLint min_size, max_size;
  uint32_t types;
};

void set_pointer(Context& ctx, ClientArray& array, const ArrayRules& rules, GLint size, GLenum type,
                 GLsizei stride, const void* pointer) {
  if (stride < 0) return record_error(ctx, GL_INVALID_VALUE);
  if ((type_bit(type) & rules.types) == 0) return record_error(ctx, GL_INVALID_ENUM);
  if (size < rules.min_size || size > rules.max_size) return record_error(ctx, GL_INVALID_VALUE);
  array.size = size;
  array.type = type;
  array.stride = stride;
  array.pointer = pointer;
  array.buffer = ctx.arrays.array_buffer;
  array.orphaned = false;
}

void set_client_state(Context& ctx, GLenum cap, bool on) {
  ClientArray* array = client_state_array(ctx.arrays, cap, ctx.textures.client_active);
  if (array == nullptr) return record_error(ctx, GL_INVALID_ENUM);
  array->enabled = on;
}

// GL 1.5 table 2.5: the layout of each glInterleavedArrays format. Offsets are in bytes; a
// 4-byte colour (GL_UNSIGNED_BYTE) takes the room of one float.
struct InterleavedLayout {
  int tex_size = 0, color_size = 0, vertex_size = 0;  // 0: no such array
  bool normal = false;
  GLenum color_type = GL_FLOAT;
  int color_offset = 0, normal_offset = 0, vertex_offset = 0, stride = 0;
};

bool interleaved_layout(GLenum format, InterleavedLayout* l) {
  constexpr int f = sizeof(GLfloat);
  constexpr int c = 4;  // four GLubyte colour components
  switch (format) {
    case GL_V2F:
      *l = {0, 0, 2, false, GL_FLOAT, 0, 0, 0, 2 * f};
      return true;
    case GL_V3F:
      *l = {0, 0, 3, false, GL_FLOAT, 0, 0, 0, 3 * f};
      return true;
    case GL_C4UB_V2F:
      *l = {0, 4, 2, false, GL_UNSIGNED_BYTE, 0, 0, c, c + 2 * f};
      return true;
    case GL_C4UB_V3F:
      *l = {0, 4, 3, false, GL_UNSIGNED_BYTE, 0, 0, c, c + 3 * f};
      return true;
    case GL_C3F_V3F:
      *l = {0, 3, 3, false, GL_FLOAT, 0, 0, 3 * f, 6 * f};
      return true;
    case GL_N3F_V3F:
      *l = {0, 0, 3, true, GL_FLOAT, 0, 0, 3 * f, 6 * f};
      return true;
    case GL_C4F_N3F_V3F:
      *l = {0, 4, 3, true, GL_FLOAT, 0, 4 * f, 7 * f, 10 * f};
      return true;
    case GL_T2F_V3F:
      *l = {2, 0, 3, false, GL_FLOAT, 0, 0, 2 * f, 5 * f};
      return true;
    case GL_T4F_V4F:
      *l = {4, 0, 4, false, GL_FLOAT, 0, 0, 4 * f, 8 * f};
      return true;
    case GL_T2F_C4UB_V3F:
      *l = {2, 4, 3, false, GL_UNSIGNED_BYTE, 2 * f, 0, c + 2 * f, c + 5 * f};
      return true;
    case GL_T2F_C3F_V3F:
      *l = {2, 3, 3, false, GL_FLOAT, 2 * f, 0, 5 * f, 8 * f};
      return true;
    case GL_T2F_N3F_V3F:
      *l = {2, 0, 3, true, GL_FLOAT, 0, 2 * f, 5 * f, 8 * f};
      return true;
    case GL_T2F_C4F_N3F_V3F:
      *l = {2, 4, 3, true, GL_FLOAT, 2 * f, 6 * f, 9 * f, 12 * f};
      return true;
    case GL_T4F_C4F_N3F_V4F:
      *l = {4, 4, 4, true, GL_FLOAT, 4 * f, 8 * f, 11 * f, 15 * f};
      return true;
    default:
      return false;
  }
}

const void* offset_pointer(const void* pointer, int offset) {
  return reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(pointer) + uintptr_t(offset));
}

}  // namespace

namespace impl {

void glVertexPointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* pointer) {
  set_pointer(ctx, ctx.arrays[ArrayKind::kVertex], {2, 4, kShort | kInt | kFloat | kDouble}, size,
              type, stride, pointer);
}

void glNormalPointer(Context& ctx, GLenum type, GLsizei stride, const void* pointer) {
  set_pointer(ctx, ctx.arrays[ArrayKind::kNormal], {3, 3, kByte | kShort | kInt | kFloat | kDouble},
              3, type, stride, pointer);
}

void glColorPointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* pointer) {
  set_pointer(ctx, ctx.arrays[ArrayKind::kColor], {3, 4, kAllTypes}, size, type, stride, pointer);
}

void glSecondaryColorPointer(Context& ctx, GLint size, GLenum type, GLsizei stride,
                             const void* pointer) {
  set_pointer(ctx, ctx.arrays[ArrayKind::kSecondaryColor], {3, 4, kAllTypes}, size, type, stride,
              pointer);
}

void glFogCoordPointer(Context& ctx, GLenum type, GLsizei stride, const void* pointer) {
  set_pointer(ctx, ctx.arrays[ArrayKind::kFogCoord], {1, 1, kFloat | kDouble}, 1, type, stride,
              pointer);
}

void glTexCoordPointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* pointer) {
  set_pointer(ctx, ctx.arrays.tex_coord(ctx.textures.client_active),
              {1, 4, kShort | kInt | kFloat | kDouble}, size, type, stride, pointer);
}

void glIndexPointer(Context& ctx, GLenum type, GLsizei stride, const void* pointer) {
  set_pointer(ctx, ctx.arrays[ArrayKind::kIndex],
              {1, 1, kUnsignedByte | kShort | kInt | kFloat | kDouble}, 1, type, stride, pointer);
}

void glEdgeFlagPointer(Context& ctx, GLsizei stride, const void* pointer) {
  set_pointer(ctx, ctx.arrays[ArrayKind::kEdgeFlag], {1, 1, kUnsignedByte}, 1, GL_UNSIGNED_BYTE,
              stride, pointer);
}

// EXT_vertex_array: the same commands with an element count glpt does not need (as in Mesa).
void glVertexPointerEXT(Context& ctx, GLint size, GLenum type, GLsizei stride, GLsizei,
                        const void* pointer) {
  glVertexPointer(ctx, size, type, stride, pointer);
}
void glNormalPointerEXT(Context& ctx, GLenum type, GLsizei stride, GLsizei, const void* pointer) {
  glNormalPointer(ctx, type, stride, pointer);
}
void glColorPointerEXT(Context& ctx, GLint size, GLenum type, GLsizei stride, GLsizei,
                       const void* pointer) {
  glColorPointer(ctx, size, type, stride, pointer);
}
void glTexCoordPointerEXT(Context& ctx, GLint size, GLenum type, GLsizei stride, GLsizei,
                          const void* pointer) {
  glTexCoordPointer(ctx, size, type, stride, pointer);
}
void glIndexPointerEXT(Context& ctx, GLenum type, GLsizei stride, GLsizei, const void* pointer) {
  glIndexPointer(ctx, type, stride, pointer);
}
void glEdgeFlagPointerEXT(Context& ctx, GLsizei stride, GLsizei, const GLboolean* pointer) {
  glEdgeFlagPointer(ctx, stride, pointer);
}

void glEnableClientState(Context& ctx, GLenum array) { set_client_state(ctx, array, true); }
void glDisableClientState(Context& ctx, GLenum array) { set_client_state(ctx, array, false); }

// GL 1.5 2.8: the effect of the command sequence the spec lists. As in Mesa, the secondary colour
// and fog coordinate arrays keep their state (the GL 1.5 sequence only names the edge flag and
// index arrays).
void glInterleavedArrays(Context& ctx, GLenum format, GLsizei stride, const void* pointer) {
  if (stride < 0) return record_error(ctx, GL_INVALID_VALUE);
  InterleavedLayout l;
  if (!interleaved_layout(format, &l)) return record_error(ctx, GL_INVALID_ENUM);
  if (stride == 0) stride = l.stride;
  VertexArrays& a = ctx.arrays;
  a[ArrayKind::kEdgeFlag].enabled = false;
  a[ArrayKind::kIndex].enabled = false;
  ClientArray& tex = a.tex_coord(ctx.textures.client_active);
  tex.enabled = l.tex_size != 0;
  if (tex.enabled) glTexCoordPointer(ctx, l.tex_size, GL_FLOAT, stride, pointer);
  a[ArrayKind::kColor].enabled = l.color_size != 0;
  if (l.color_size != 0)
    glColorPointer(ctx, l.color_size, l.color_type, stride,
                   offset_pointer(pointer, l.color_offset));
  a[ArrayKind::kNormal].enabled = l.normal;
  if (l.normal) glNormalPointer(ctx, GL_FLOAT, stride, offset_pointer(pointer, l.normal_offset));
  a[ArrayKind::kVertex].enabled = true;
  glVertexPointer(ctx, l.vertex_size, GL_FLOAT, stride, offset_pointer(pointer, l.vertex_offset));
}

// EXT_compiled_vertex_array (errors as Mesa reports them).
void glLockArraysEXT(Context& ctx, GLint first, GLsizei count) {
  if (first < 0 || count <= 0) return record_error(ctx, GL_INVALID_VALUE);
  if (ctx.arrays.lock_count != 0) return record_error(ctx, GL_INVALID_OPERATION);
  ctx.arrays.lock_first = first;
  ctx.arrays.lock_count = count;
}

void glUnlockArraysEXT(Context& ctx) {
  if (ctx.arrays.lock_count == 0) return record_error(ctx, GL_INVALID_OPERATION);
  ctx.arrays.lock_first = 0;
  ctx.arrays.lock_count = 0;
}

void glGetPointerv(Context& ctx, GLenum pname, void** params) {
  const VertexArrays& a = ctx.arrays;
  const void* value = nullptr;
  switch (pname) {
    case GL_VERTEX_ARRAY_POINTER:
      value = a[ArrayKind::kVertex].pointer;
      break;
    case GL_NORMAL_ARRAY_POINTER:
      value = a[ArrayKind::kNormal].pointer;
      break;
    case GL_COLOR_ARRAY_POINTER:
      value = a[ArrayKind::kColor].pointer;
      break;
    case GL_SECONDARY_COLOR_ARRAY_POINTER:
      value = a[ArrayKind::kSecondaryColor].pointer;
      break;
    case GL_FOG_COORD_ARRAY_POINTER:
      value = a[ArrayKind::kFogCoord].pointer;
      break;
    case GL_INDEX_ARRAY_POINTER:
      value = a[ArrayKind::kIndex].pointer;
      break;
    case GL_EDGE_FLAG_ARRAY_POINTER:
      value = a[ArrayKind::kEdgeFlag].pointer;
      break;
    case GL_TEXTURE_COORD_ARRAY_POINTER:
      value = a.tex_coord(ctx.textures.client_active).pointer;
      break;
    case GL_FEEDBACK_BUFFER_POINTER:
      value = ctx.render_mode.feedback.buffer;
      break;
    case GL_SELECTION_BUFFER_POINTER:
      value = ctx.render_mode.selection.buffer;
      break;
    default:
      return record_error(ctx, GL_INVALID_ENUM);
  }
  if (params != nullptr) *params = const_cast<void*>(value);
}

}  // namespace impl
}  // namespace glpt
