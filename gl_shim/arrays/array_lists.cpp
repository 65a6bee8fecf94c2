#include "gl_shim/arrays/array_lists.hpp"

#include <algorithm>
#include <cstring>
#include <new>

#include "gl/gl_enums.h"
#include "gl_shim/arrays/array_draws.hpp"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/state/out_of_memory.hpp"

namespace glpt {
namespace {

// A compiled primitive or array element: the attributes held (1 << ArrayKind), each an array of
// `count` values at its offset in the record's payload.
struct CompiledVertices {
  uint32_t mode;
  uint32_t error;  // raised instead when the list runs
  uint32_t mask;
  uint32_t count;
  uint32_t offsets[kArrayKinds];
};

template <typename T>
void put(ListStream::Writer& w, CompiledVertices& rec, ArrayKind kind, const std::vector<T>& v) {
  rec.offsets[int(kind)] = w.append_array(v.data(), uint32_t(v.size()));
}

template <typename T>
void get(const ListStream::Reader& r, const CompiledVertices& rec, ArrayKind kind,
         std::vector<T>& v) {
  v.resize(rec.count);
  // An empty primitive has no storage to copy (memcpy's pointers must not be null even then).
  if (rec.count > 0)
    std::memcpy(v.data(), r.payload<T>(rec.offsets[int(kind)]), sizeof(T) * rec.count);
}

// Writes one record of `command` holding `v` (or only `error`).
void write(ListStream& list, CommandId command, GLenum mode, GLenum error, const ArrayVertices& v) {
  ListStream::Writer w(list, command, sizeof(CompiledVertices));
  CompiledVertices rec{};
  rec.mode = mode;
  rec.error = error;
  if (error == GL_NO_ERROR) {
    rec.mask = v.mask;
    rec.count = v.count();
    if (v.has(ArrayKind::kVertex)) put(w, rec, ArrayKind::kVertex, v.position);
    if (v.has(ArrayKind::kNormal)) put(w, rec, ArrayKind::kNormal, v.normal);
    if (v.has(ArrayKind::kColor)) put(w, rec, ArrayKind::kColor, v.color);
    if (v.has(ArrayKind::kSecondaryColor))
      put(w, rec, ArrayKind::kSecondaryColor, v.secondary_color);
    if (v.has(ArrayKind::kFogCoord)) put(w, rec, ArrayKind::kFogCoord, v.fog_coord);
    if (v.has(ArrayKind::kIndex)) put(w, rec, ArrayKind::kIndex, v.index);
    if (v.has(ArrayKind::kEdgeFlag)) put(w, rec, ArrayKind::kEdgeFlag, v.edge_flag);
    for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
      const auto kind = ArrayKind(int(ArrayKind::kTexCoord0) + u);
      if (v.has(kind)) put(w, rec, kind, v.tex_coord[size_t(u)]);
    }
  }
  w.set_record(rec);
}

CompiledVertices read(const ListStream::Reader& r, ArrayVertices& v) {
  const auto rec = r.record<CompiledVertices>();
  v = ArrayVertices{};
  if (rec.error != GL_NO_ERROR) return rec;
  v.mask = rec.mask;
  // Every attribute has `count` values, the position included (a vertex count of 0 is none).
  v.position.resize(rec.count, glm::vec4(0, 0, 0, 1));
  if (v.has(ArrayKind::kVertex)) get(r, rec, ArrayKind::kVertex, v.position);
  if (v.has(ArrayKind::kNormal)) get(r, rec, ArrayKind::kNormal, v.normal);
  if (v.has(ArrayKind::kColor)) get(r, rec, ArrayKind::kColor, v.color);
  if (v.has(ArrayKind::kSecondaryColor)) get(r, rec, ArrayKind::kSecondaryColor, v.secondary_color);
  if (v.has(ArrayKind::kFogCoord)) get(r, rec, ArrayKind::kFogCoord, v.fog_coord);
  if (v.has(ArrayKind::kIndex)) get(r, rec, ArrayKind::kIndex, v.index);
  if (v.has(ArrayKind::kEdgeFlag)) get(r, rec, ArrayKind::kEdgeFlag, v.edge_flag);
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    const auto kind = ArrayKind(int(ArrayKind::kTexCoord0) + u);
    if (v.has(kind)) get(r, rec, kind, v.tex_coord[size_t(u)]);
  }
  return rec;
}

void write_error(ListStream& list, GLenum error) {
  write(list, CommandId::glDrawArrays, GL_POINTS, error, ArrayVertices{});
}

// The error a draw compiled now raises when the list runs, from its arguments and the arrays.
GLenum draw_error(const Context& ctx, GLenum mode, GLsizei count) {
  const GLenum error = check_draw(ctx, mode, count);
  if (error != GL_NO_ERROR) return error;
  return enabled_array_is_mapped(ctx.arrays) ? GLenum{GL_INVALID_OPERATION} : GLenum{GL_NO_ERROR};
}

// One compiled primitive of the given vertices (glBegin, glArrayElement each, glEnd).
// Without a vertex array (or vertices) the primitive is empty but still recorded: replayed
// inside glBegin/glEnd it is an error all the same (Mesa compiles an empty glBegin/glEnd).
void compile_primitive(Context& ctx, ListStream& list, GLenum mode,
                       const std::vector<uint32_t>& vertices) {
  ArrayVertices v;
  if (ctx.arrays[ArrayKind::kVertex].enabled)
    read_array_vertices(ctx, vertices, ArrayConversion::kImmediate, v, kDrawnArrays);
  write(list, CommandId::glDrawArrays, mode, GL_NO_ERROR, v);
}

// Compiles the elements of several index lists, each a primitive. `multi`: glMultiDrawElements,
// whose empty lists Mesa does not compile (glDrawElements compiles an empty primitive).
void compile_elements(Context& ctx, ListStream& list, GLenum mode, const GLsizei* counts,
                      GLenum type, const void* const* indices, GLsizei draws, bool multi) {
  uint64_t total = 0;
  for (GLsizei d = 0; d < draws; ++d) total += uint64_t(std::max(counts[d], 0));
  if (total > kMaxArrayDrawVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
  std::vector<uint32_t> elements;
  for (GLsizei d = 0; d < draws; ++d) {
    if (multi && counts[d] == 0) continue;
    if (!read_indices(ctx, counts[d], type, indices[d], elements)) elements.clear();
    compile_primitive(ctx, list, mode, elements);
  }
}

GLenum elements_error(const Context& ctx, GLenum mode, GLsizei count, GLenum type) {
  GLenum error = draw_error(ctx, mode, count);
  if (error == GL_NO_ERROR && !is_index_type(type)) error = GL_INVALID_ENUM;
  if (error == GL_NO_ERROR && ctx.arrays.element_buffer && ctx.arrays.element_buffer->mapped)
    error = GL_INVALID_OPERATION;
  return error;
}

}  // namespace

void compile_array_element(Context& ctx, ListStream& list, GLint i) {
  or_out_of_memory(ctx, [&] {
    if (enabled_array_is_mapped(ctx.arrays)) return write_error(list, GL_INVALID_OPERATION);
    if (i < 0) return;
    ArrayVertices v;
    read_array_vertices(ctx, {uint32_t(i)}, ArrayConversion::kImmediate, v);
    write(list, CommandId::glArrayElement, GL_POINTS, GL_NO_ERROR, v);
  });
}

void compile_draw_arrays(Context& ctx, ListStream& list, GLenum mode, GLint first, GLsizei count) {
  or_out_of_memory(ctx, [&] {
    if (const GLenum error = draw_error(ctx, mode, count)) return write_error(list, error);
    if (uint64_t(count) > kMaxArrayDrawVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
    compile_primitive(ctx, list, mode,
                      first < 0 ? std::vector<uint32_t>{} : vertex_range(first, count));
  });
}

void compile_multi_draw_arrays(Context& ctx, ListStream& list, GLenum mode, const GLint* first,
                               const GLsizei* count, GLsizei drawcount) {
  or_out_of_memory(ctx, [&] {
    if (drawcount < 0) return write_error(list, GL_INVALID_VALUE);
    if (first == nullptr || count == nullptr) return;
    uint64_t total = 0;
    for (GLsizei d = 0; d < drawcount; ++d) {
      if (count[d] < 0) return write_error(list, GL_INVALID_VALUE);
      total += uint64_t(count[d]);
    }
    if (const GLenum error = draw_error(ctx, mode, 0)) return write_error(list, error);
    if (total > kMaxArrayDrawVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
    for (GLsizei d = 0; d < drawcount; ++d) {
      if (count[d] > 0)
        compile_primitive(
            ctx, list, mode,
            first[d] < 0 ? std::vector<uint32_t>{} : vertex_range(first[d], count[d]));
    }
  });
}

void compile_draw_elements(Context& ctx, ListStream& list, GLenum mode, GLsizei count, GLenum type,
                           const void* indices) {
  or_out_of_memory(ctx, [&] {
    if (const GLenum error = elements_error(ctx, mode, count, type))
      return write_error(list, error);
    compile_elements(ctx, list, mode, &count, type, &indices, 1, false);
  });
}

void compile_draw_range_elements(Context& ctx, ListStream& list, GLenum mode, GLuint start,
                                 GLuint end, GLsizei count, GLenum type, const void* indices) {
  if (end < start) return or_out_of_memory(ctx, [&] { write_error(list, GL_INVALID_VALUE); });
  compile_draw_elements(ctx, list, mode, count, type, indices);
}

void compile_multi_draw_elements(Context& ctx, ListStream& list, GLenum mode, const GLsizei* count,
                                 GLenum type, const void* const* indices, GLsizei drawcount) {
  or_out_of_memory(ctx, [&] {
    if (drawcount < 0) return write_error(list, GL_INVALID_VALUE);
    if (count == nullptr || indices == nullptr) return;
    for (GLsizei d = 0; d < drawcount; ++d)
      if (count[d] < 0) return write_error(list, GL_INVALID_VALUE);
    if (const GLenum error = elements_error(ctx, mode, 0, type)) return write_error(list, error);
    compile_elements(ctx, list, mode, count, type, indices, drawcount, true);
  });
}

void replay_array_element(Context& ctx, const ListStream::Reader& r) {
  or_out_of_memory(ctx, [&] {
    ArrayVertices v;
    const CompiledVertices rec = read(r, v);
    if (rec.error != GL_NO_ERROR) return record_error(ctx, rec.error);
    if (rec.count == 1) array_element(ctx, v, 0);
  });
}

void replay_array_primitive(Context& ctx, const ListStream::Reader& r) {
  or_out_of_memory(ctx, [&] {
    ArrayVertices v;
    const CompiledVertices rec = read(r, v);
    if (rec.error != GL_NO_ERROR) return record_error(ctx, rec.error);
    if (ctx.inside_begin_end()) return record_error(ctx, GL_INVALID_OPERATION);
    ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask);
    record_array_draw(ctx, rec.mode, std::move(v), {}, {{0, rec.count}},
                      ArrayDrawSource::kDisplayList);
  });
}

}  // namespace glpt
