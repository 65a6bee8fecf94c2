// glGet* answers for the client vertex arrays and buffer bindings (GL 1.5 tables 6.6-6.8), the
// compiled-array lock (EXT_compiled_vertex_array), the attribute stack depths (6.31) and the
// hints (6.27). queries.cpp consults lookup_array_state for pnames it does not answer itself.
#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/state/query_values.hpp"

namespace glpt {
namespace {

using query::ints;

const ClientArray* array_of(const Context& ctx, GLenum pname) {
  const VertexArrays& a = ctx.arrays;
  switch (pname) {
    case GL_VERTEX_ARRAY_SIZE:
    case GL_VERTEX_ARRAY_TYPE:
    case GL_VERTEX_ARRAY_STRIDE:
    case GL_VERTEX_ARRAY_BUFFER_BINDING:
      return &a[ArrayKind::kVertex];
    case GL_NORMAL_ARRAY_TYPE:
    case GL_NORMAL_ARRAY_STRIDE:
    case GL_NORMAL_ARRAY_BUFFER_BINDING:
      return &a[ArrayKind::kNormal];
    case GL_COLOR_ARRAY_SIZE:
    case GL_COLOR_ARRAY_TYPE:
    case GL_COLOR_ARRAY_STRIDE:
    case GL_COLOR_ARRAY_BUFFER_BINDING:
      return &a[ArrayKind::kColor];
    case GL_SECONDARY_COLOR_ARRAY_SIZE:
    case GL_SECONDARY_COLOR_ARRAY_TYPE:
    case GL_SECONDARY_COLOR_ARRAY_STRIDE:
    case GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING:
      return &a[ArrayKind::kSecondaryColor];
    case GL_FOG_COORD_ARRAY_TYPE:
    case GL_FOG_COORD_ARRAY_STRIDE:
    case GL_FOG_COORD_ARRAY_BUFFER_BINDING:
      return &a[ArrayKind::kFogCoord];
    case GL_INDEX_ARRAY_TYPE:
    case GL_INDEX_ARRAY_STRIDE:
    case GL_INDEX_ARRAY_BUFFER_BINDING:
      return &a[ArrayKind::kIndex];
    case GL_EDGE_FLAG_ARRAY_STRIDE:
    case GL_EDGE_FLAG_ARRAY_BUFFER_BINDING:
      return &a[ArrayKind::kEdgeFlag];
    case GL_TEXTURE_COORD_ARRAY_SIZE:
    case GL_TEXTURE_COORD_ARRAY_TYPE:
    case GL_TEXTURE_COORD_ARRAY_STRIDE:
    case GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING:
      return &a.tex_coord(ctx.textures.client_active);
    default:
      return nullptr;
  }
}

bool lookup_array(const Context& ctx, GLenum pname, query::Value* out) {
  const ClientArray* array = array_of(ctx, pname);
  if (array == nullptr) return false;
  switch (pname) {
    case GL_VERTEX_ARRAY_SIZE:
    case GL_COLOR_ARRAY_SIZE:
    case GL_SECONDARY_COLOR_ARRAY_SIZE:
    case GL_TEXTURE_COORD_ARRAY_SIZE:
      *out = ints({double(array->size)});
      return true;
    case GL_VERTEX_ARRAY_TYPE:
    case GL_NORMAL_ARRAY_TYPE:
    case GL_COLOR_ARRAY_TYPE:
    case GL_SECONDARY_COLOR_ARRAY_TYPE:
    case GL_FOG_COORD_ARRAY_TYPE:
    case GL_INDEX_ARRAY_TYPE:
    case GL_TEXTURE_COORD_ARRAY_TYPE:
      *out = ints({double(array->type)});
      return true;
    case GL_VERTEX_ARRAY_STRIDE:
    case GL_NORMAL_ARRAY_STRIDE:
    case GL_COLOR_ARRAY_STRIDE:
    case GL_SECONDARY_COLOR_ARRAY_STRIDE:
    case GL_FOG_COORD_ARRAY_STRIDE:
    case GL_INDEX_ARRAY_STRIDE:
    case GL_EDGE_FLAG_ARRAY_STRIDE:
    case GL_TEXTURE_COORD_ARRAY_STRIDE:
      *out = ints({double(array->stride)});
      return true;
    default:  // the *_ARRAY_BUFFER_BINDINGs
      *out = ints({double(array->buffer_name())});
      return true;
  }
}

GLuint name_of(const std::shared_ptr<BufferObject>& buffer) { return buffer ? buffer->name() : 0; }

}  // namespace

bool lookup_array_state(const Context& ctx, GLenum pname, query::Value* out) {
  if (lookup_array(ctx, pname, out)) return true;
  if (const GLenum* hint = ctx.hints.target(pname)) {
    *out = ints({double(*hint)});
    return true;
  }
  switch (pname) {
    case GL_ARRAY_BUFFER_BINDING:
      *out = ints({double(name_of(ctx.arrays.array_buffer))});
      return true;
    case GL_ELEMENT_ARRAY_BUFFER_BINDING:
      *out = ints({double(name_of(ctx.arrays.element_buffer))});
      return true;
    case GL_ARRAY_ELEMENT_LOCK_FIRST_EXT:
      *out = ints({double(ctx.arrays.lock_first)});
      return true;
    case GL_ARRAY_ELEMENT_LOCK_COUNT_EXT:
      *out = ints({double(ctx.arrays.lock_count)});
      return true;
    case GL_ATTRIB_STACK_DEPTH:
      *out = ints({double(ctx.attrib_stacks.server.size())});
      return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH:
      *out = ints({double(ctx.attrib_stacks.client.size())});
      return true;
    default:
      return false;
  }
}

}  // namespace glpt
