// glDrawArrays, glDrawElements, glDrawRangeElements, glMultiDrawArrays, glMultiDrawElements and
// glArrayElement (GL 1.5 2.8, 2.9.2).
//
// A draw reads its vertices from the enabled arrays when it is called and records them into the
// frame record as float attributes (array_fetch.hpp converts them as Mesa's vertex fetch does);
// glDrawElements keeps its indices. What Mesa does where GL 1.5 leaves room, followed here:
//   - the current values of array-sourced attributes are unchanged after glDrawArrays and
//     glDrawElements (GL 1.5 2.8 leaves them undefined); glArrayElement sets them;
//   - state is validated (matrices analysed) before the arguments are checked;
//   - a negative `first`, or indices that cannot be read (no element buffer and a null pointer,
//     a range beyond the element buffer's store), draw nothing without an error;
//   - while GL_COMPILE_AND_EXECUTE compiles a list, a draw executes as glBegin, one
//     glArrayElement per vertex and glEnd (Mesa executes the list's compiled form, which updates
//     the current values).
// Sourcing data from a mapped buffer object is GL_INVALID_OPERATION (GL 1.5 2.9.3; Mesa 25 no
// longer checks).
#include "gl_shim/arrays/array_draws.hpp"

#include <algorithm>
#include <cstring>
#include <new>
#include <optional>

#include "gl/gl_enums.h"
#include "gl_shim/arrays/buffer_draw_cache.hpp"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/geometry/attributes.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/out_of_memory.hpp"

namespace glpt {
namespace {

template <typename T>
void append_values(const ArrayReader& reader, const VertexSelection& vertices,
                   std::vector<T>& out) {
  out.resize(vertices.count);
  if constexpr (std::is_same_v<T, glm::vec4>) {
    reader.read(vertices, out.data());
  } else {
    // Through a small buffer of vec4s: the conversion is chosen once per chunk, not per element.
    constexpr size_t kChunk = 512;
    glm::vec4 chunk[kChunk];
    for (size_t start = 0; start < vertices.count; start += kChunk) {
      VertexSelection part = vertices;
      part.count = std::min(kChunk, vertices.count - start);
      if (part.list != nullptr)
        part.list += start;
      else
        part.first += uint32_t(start);
      reader.read(part, chunk);
      for (size_t i = 0; i < part.count; ++i) {
        const glm::vec4& v = chunk[i];
        if constexpr (std::is_same_v<T, glm::vec3>)
          out[start + i] = glm::vec3(v);
        else if constexpr (std::is_same_v<T, uint8_t>)
          out[start + i] = v.x != 0.0f ? 1 : 0;
        else
          out[start + i] = v.x;
      }
    }
  }
}

bool executing_while_compiling(const Context& ctx) { return ctx.lists.compiling(); }

// Gives `values` (and `indices`, when given) the storage of a draw of the last frame
// (FrameRecorder::take_storage), so a program drawing the same large arrays every frame does not
// allocate them anew (and page-fault them in) each time.
void use_recorder_storage(Context& ctx, ArrayVertices& values,
                          std::vector<uint32_t>* indices = nullptr) {
  rec::VertexData storage = ctx.recorder.take_storage();
  if (indices != nullptr) indices->swap(storage.indices);
  values.position.swap(storage.position);
  values.color.swap(storage.color);
  values.secondary_color.swap(storage.secondary_color);
  values.normal.swap(storage.normal);
  values.fog_coord.swap(storage.fog_coord);
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    values.tex_coord[size_t(u)].swap(storage.tex_coord[size_t(u)]);
  values.edge_flag.swap(storage.edge_flag);
}

// Vertex numbers of `indices`, made compact: the selection returned names the distinct vertices
// to read and `indices` is rewritten to refer to positions in it. A dense range is kept as a
// range; otherwise `vertices` holds the list the selection points to.
VertexSelection compact_indices(std::vector<uint32_t>& indices, std::vector<uint32_t>& vertices) {
  vertices.clear();
  if (indices.empty()) return {};
  const auto [lo, hi] = std::minmax_element(indices.begin(), indices.end());
  const uint32_t first = *lo;
  const uint64_t span = uint64_t(*hi) - first + 1;
  if (span <= 2 * uint64_t(indices.size()) + 64) {
    if (first != 0)
      for (uint32_t& index : indices) index -= first;
    return VertexSelection::range(first, size_t(span));
  }
  vertices = indices;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (uint32_t& index : indices)
    index = uint32_t(std::lower_bound(vertices.begin(), vertices.end(), index) - vertices.begin());
  return VertexSelection::of(vertices);
}

uint8_t sampled_texture_units(const rec::StateSnapshot& state) {
  uint8_t units = 0;
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    if (state.texturing->units[size_t(u)].target != 0) units |= uint8_t(1u << u);
  return units;
}

// The attribute as recorded: the array's values (moved: a large draw's arrays are not copied
// again), or the current value (once, or per vertex when `per_vertex` is asked for).
template <typename T>
std::vector<T> attribute(bool from_array, std::vector<T>& values, const T& current, size_t count,
                         bool per_vertex) {
  if (from_array) return std::move(values);
  return std::vector<T>(per_vertex ? count : 1, current);
}

bool vertex_array_enabled(const Context& ctx) { return ctx.arrays[ArrayKind::kVertex].enabled; }

// Common checks of a live draw; false when it draws nothing (an error may have been raised).
bool begin_live_draw(Context& ctx, GLenum error) {
  // Mesa validates state, which analyses the matrices, before it checks the draw's arguments.
  ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask);
  if (error == GL_NO_ERROR) error = framebuffer_error(ctx);
  if (error != GL_NO_ERROR) {
    record_error(ctx, error);
    return false;
  }
  if (enabled_array_is_mapped(ctx.arrays)) {
    record_error(ctx, GL_INVALID_OPERATION);
    return false;
  }
  return true;
}

// GL_COMPILE_AND_EXECUTE's execution of a draw (see the file comment).
void draw_as_immediate(Context& ctx, GLenum mode, const std::vector<uint32_t>& elements) {
  ArrayVertices values;
  read_array_vertices(ctx, elements, ArrayConversion::kImmediate, values);
  impl::glBegin(ctx, mode);
  for (uint32_t i = 0; i < elements.size(); ++i) array_element(ctx, values, i);
  impl::glEnd(ctx);
}

// A live draw from buffer objects only (buffer_draw_cache.hpp): recorded again from the cache when
// the same draw was recorded with the same buffer contents (true), else the key to cache the
// draw under once recorded (when it can be cached).
struct CachedDraw {
  bool recorded = false;
  std::optional<BufferDrawKey> key;
};
CachedDraw record_cached_draw(Context& ctx, GLenum mode, GLint first, GLsizei count,
                              GLenum index_type, const void* indices) {
  if (executing_while_compiling(ctx) || ctx.render_mode.mode != GL_RENDER ||
      !draw_reads_static_buffers_only(ctx, index_type != 0))
    return {};
  const rec::StateId state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  const uint8_t units = sampled_texture_units(ctx.recorder.record().states[state]);
  CachedDraw result;
  result.key = buffer_draw_key(ctx, mode, first, count, index_type, indices, units);
  if (std::shared_ptr<const rec::VertexData> vertices = ctx.buffer_draws.find(*result.key)) {
    ctx.recorder.add_recorded_draw(state, std::move(vertices));
    note_frame_content(ctx);
    result.recorded = true;
  }
  return result;
}

void remember_draw(Context& ctx, const CachedDraw& cached,
                   std::shared_ptr<const rec::VertexData> recorded) {
  if (cached.key && recorded) ctx.buffer_draws.insert(*cached.key, std::move(recorded));
}

void draw_elements(Context& ctx, GLenum mode, const std::vector<GLsizei>& counts, GLenum type,
                   const std::vector<const void*>& index_pointers) {
  std::vector<uint32_t> elements, part;
  std::vector<rec::PrimitiveRange> ranges;
  uint64_t total = 0;
  for (size_t d = 0; d < counts.size(); ++d) total += uint64_t(std::max(counts[d], 0));
  if (total > kMaxArrayDrawVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
  // Before anything is read: a draw recorded before reads nothing again.
  CachedDraw cached;
  if (counts.size() == 1 && counts[0] > 0) {
    cached = record_cached_draw(ctx, mode, 0, counts[0], type, index_pointers[0]);
    if (cached.recorded) return;
  }
  ArrayVertices values;
  if (!executing_while_compiling(ctx)) use_recorder_storage(ctx, values, &part);
  for (size_t d = 0; d < counts.size(); ++d) {
    if (counts[d] <= 0 || !read_indices(ctx, counts[d], type, index_pointers[d], part)) continue;
    if (executing_while_compiling(ctx)) {
      draw_as_immediate(ctx, mode, part);
      continue;
    }
    ranges.push_back({uint32_t(elements.size()), uint32_t(part.size())});
    if (elements.empty())
      elements.swap(part);  // one draw (the usual case): its indices, not a copy
    else
      elements.insert(elements.end(), part.begin(), part.end());
  }
  if (elements.empty() || !vertex_array_enabled(ctx)) return;
  std::vector<uint32_t> vertices;
  const VertexSelection selection = compact_indices(elements, vertices);
  read_array_vertices(ctx, selection, ArrayConversion::kVertexFetch, values, kDrawnArrays);
  remember_draw(ctx, cached,
                record_array_draw(ctx, mode, std::move(values), std::move(elements),
                                  std::move(ranges), ArrayDrawSource::kElements));
}

}  // namespace

std::vector<uint32_t> vertex_range(GLint first, GLsizei count) {
  std::vector<uint32_t> v(static_cast<size_t>(std::max(count, 0)));
  for (size_t i = 0; i < v.size(); ++i) v[i] = uint32_t(first) + uint32_t(i);
  return v;
}

GLenum check_draw(const Context&, GLenum mode, GLsizei count) {
  if (count < 0) return GL_INVALID_VALUE;
  if (mode > GL_POLYGON) return GL_INVALID_ENUM;
  return GL_NO_ERROR;
}

bool is_index_type(GLenum type) {
  return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT || type == GL_UNSIGNED_INT;
}

bool read_indices(const Context& ctx, GLsizei count, GLenum type, const void* indices,
                  std::vector<uint32_t>& out) {
  out.clear();
  const size_t size = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
  const ArrayBytes bytes(ctx.arrays.element_buffer, indices);
  if (bytes.bytes() == nullptr || count < 0 || bytes.size() / size < size_t(count)) return false;
  out.resize(size_t(count));
  const uint8_t* p = bytes.bytes();
  for (size_t i = 0; i < out.size(); ++i, p += size) {
    if (size == 1) {
      out[i] = *p;
    } else if (size == 2) {
      uint16_t v;
      std::memcpy(&v, p, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], p, 4);
    }
  }
  return true;
}

void read_array_vertices(const Context& ctx, const std::vector<uint32_t>& vertices,
                         ArrayConversion conversion, ArrayVertices& out, uint32_t kinds) {
  read_array_vertices(ctx, VertexSelection::of(vertices), conversion, out, kinds);
}

void read_array_vertices(const Context& ctx, const VertexSelection& vertices,
                         ArrayConversion conversion, ArrayVertices& out, uint32_t kinds) {
  // Cleared, not replaced: `out` may hold reused storage (use_recorder_storage).
  out.mask = 0;
  out.position.clear();
  out.color.clear();
  out.secondary_color.clear();
  out.normal.clear();
  out.fog_coord.clear();
  out.index.clear();
  for (auto& t : out.tex_coord) t.clear();
  out.edge_flag.clear();
  const VertexArrays& a = ctx.arrays;
  for (int k = 0; k < kArrayKinds; ++k) {
    const ClientArray& array = a.arrays[size_t(k)];
    if (!array.enabled || (kinds & (1u << k)) == 0) continue;
    out.mask |= 1u << k;
    const ArrayReader reader(array, conversion);
    switch (ArrayKind(k)) {
      case ArrayKind::kVertex:
        append_values(reader, vertices, out.position);
        break;
      case ArrayKind::kNormal:
        append_values(reader, vertices, out.normal);
        break;
      case ArrayKind::kColor:
        append_values(reader, vertices, out.color);
        break;
      case ArrayKind::kSecondaryColor:
        append_values(reader, vertices, out.secondary_color);
        break;
      case ArrayKind::kFogCoord:
        append_values(reader, vertices, out.fog_coord);
        break;
      case ArrayKind::kIndex:
        append_values(reader, vertices, out.index);
        break;
      case ArrayKind::kEdgeFlag:
        append_values(reader, vertices, out.edge_flag);
        break;
      default:
        append_values(reader, vertices, out.tex_coord[size_t(k - int(ArrayKind::kTexCoord0))]);
        break;
    }
  }
}

// GL 1.5 2.8: the attribute commands in the spec's order, the vertex last.
void array_element(Context& ctx, const ArrayVertices& v, uint32_t i) {
  if (v.has(ArrayKind::kEdgeFlag)) attribute_edge_flag(ctx, v.edge_flag[i] != 0);
  for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
    if (v.has(ArrayKind(int(ArrayKind::kTexCoord0) + u)))
      attribute_multi_tex_coord(ctx, GLenum(GL_TEXTURE0 + u), v.tex_coord[size_t(u)][i]);
  }
  if (v.has(ArrayKind::kColor)) attribute_color(ctx, v.color[i]);
  if (v.has(ArrayKind::kSecondaryColor))
    attribute_secondary_color(ctx, glm::vec3(v.secondary_color[i]));
  if (v.has(ArrayKind::kFogCoord)) attribute_fog_coord(ctx, v.fog_coord[i]);
  if (v.has(ArrayKind::kIndex)) attribute_index(ctx, v.index[i]);
  if (v.has(ArrayKind::kNormal)) attribute_normal(ctx, v.normal[i]);
  if (v.has(ArrayKind::kVertex)) attribute_vertex(ctx, v.position[i]);
}

// The one place array draws enter the frame record. It also says how the draw was specified
// (rec::VertexData::source: Mesa assembles glDrawArrays, glDrawElements and compiled draws
// differently) and which colours came per vertex from arrays (per_vertex).
std::shared_ptr<const rec::VertexData> record_array_draw(Context& ctx, GLenum mode,
                                                         ArrayVertices&& v,
                                                         std::vector<uint32_t> indices,
                                                         std::vector<rec::PrimitiveRange> ranges,
                                                         ArrayDrawSource source) {
  if (v.position.empty() || ranges.empty()) return nullptr;
  const rec::StateId state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  uint8_t units = sampled_texture_units(ctx.recorder.record().states[state]);
  if (ctx.render_mode.mode == GL_FEEDBACK) units |= 1;  // feedback reports unit 0's coordinates
  const CurrentAttributes& c = ctx.current;
  // Batched draws (display lists) need every attribute per vertex (FrameRecorder::add_primitive).
  const bool per_vertex = source == ArrayDrawSource::kDisplayList;
  const size_t n = v.position.size();
  try {
    rec::VertexData d;
    d.mode = mode;
    d.position = std::move(v.position);
    d.normal = attribute(v.has(ArrayKind::kNormal), v.normal, c.normal, n, per_vertex);
    d.color = attribute(v.has(ArrayKind::kColor), v.color, c.color, n, per_vertex);
    d.secondary_color = attribute(v.has(ArrayKind::kSecondaryColor), v.secondary_color,
                                  c.secondary_color, n, per_vertex);
    d.fog_coord = attribute(v.has(ArrayKind::kFogCoord), v.fog_coord, c.fog_coord, n, per_vertex);
    for (int u = 0; u < rec::kMaxTextureUnits; ++u) {
      if ((units & (1u << u)) == 0) continue;
      d.tex_coord[size_t(u)] =
          attribute(v.has(ArrayKind(int(ArrayKind::kTexCoord0) + u)), v.tex_coord[size_t(u)],
                    c.tex_coord[size_t(u)], n, per_vertex);
    }
    d.edge_flag = attribute(v.has(ArrayKind::kEdgeFlag), v.edge_flag, uint8_t(c.edge_flag ? 1 : 0),
                            n, per_vertex);
    d.indices = std::move(indices);
    d.primitives = std::move(ranges);
    d.source = source == ArrayDrawSource::kArrays     ? rec::PrimitiveSource::kArrays
               : source == ArrayDrawSource::kElements ? rec::PrimitiveSource::kElements
                                                      : rec::PrimitiveSource::kDisplayList;
    d.per_vertex = uint8_t((v.has(ArrayKind::kColor) ? rec::kPerVertexColor : 0) |
                           (v.has(ArrayKind::kSecondaryColor) ? rec::kPerVertexSecondaryColor : 0));
    if (ctx.render_mode.mode != GL_RENDER) {
      render_mode_array_draw(ctx, ctx.recorder.record().states[state], d,
                             v.has(ArrayKind::kEdgeFlag));
      return nullptr;
    }
    std::shared_ptr<const rec::VertexData> recorded;
    if (source == ArrayDrawSource::kDisplayList)
      ctx.recorder.add_primitive(state, d);
    else
      recorded = ctx.recorder.add_draw(state, std::move(d));
    note_frame_content(ctx);
    return recorded;
  } catch (const std::bad_alloc&) {
    record_error(ctx, GL_OUT_OF_MEMORY);
    return nullptr;
  }
}

namespace impl {

void glDrawArrays(Context& ctx, GLenum mode, GLint first, GLsizei count) {
  or_out_of_memory(ctx, [&] {
    if (!begin_live_draw(ctx, check_draw(ctx, mode, count))) return;
    if (count == 0 || first < 0) return;
    if (uint64_t(count) > kMaxArrayDrawVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
    if (executing_while_compiling(ctx))
      return draw_as_immediate(ctx, mode, vertex_range(first, count));
    if (!vertex_array_enabled(ctx)) return;
    const CachedDraw cached = record_cached_draw(ctx, mode, first, count, 0, nullptr);
    if (cached.recorded) return;
    ArrayVertices values;
    use_recorder_storage(ctx, values);
    read_array_vertices(ctx, VertexSelection::range(uint32_t(first), size_t(count)),
                        ArrayConversion::kVertexFetch, values, kDrawnArrays);
    remember_draw(ctx, cached,
                  record_array_draw(ctx, mode, std::move(values), {}, {{0, uint32_t(count)}},
                                    ArrayDrawSource::kArrays));
  });
}

void glMultiDrawArrays(Context& ctx, GLenum mode, const GLint* first, const GLsizei* count,
                       GLsizei drawcount) {
  or_out_of_memory(ctx, [&] {
    GLenum error = drawcount < 0 ? GLenum{GL_INVALID_VALUE} : GLenum{GL_NO_ERROR};
    uint64_t total = 0;
    for (GLsizei d = 0; error == GL_NO_ERROR && d < drawcount && count != nullptr; ++d) {
      if (count[d] < 0) error = GL_INVALID_VALUE;
      total += uint64_t(std::max(count[d], 0));
    }
    if (error == GL_NO_ERROR) error = check_draw(ctx, mode, 0);
    if (!begin_live_draw(ctx, error) || first == nullptr || count == nullptr) return;
    if (total > kMaxArrayDrawVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
    std::vector<uint32_t> vertices;
    std::vector<rec::PrimitiveRange> ranges;
    for (GLsizei d = 0; d < drawcount; ++d) {
      if (count[d] == 0 || first[d] < 0) continue;
      const std::vector<uint32_t> part = vertex_range(first[d], count[d]);
      if (executing_while_compiling(ctx)) {
        draw_as_immediate(ctx, mode, part);
        continue;
      }
      ranges.push_back({uint32_t(vertices.size()), uint32_t(part.size())});
      vertices.insert(vertices.end(), part.begin(), part.end());
    }
    if (vertices.empty() || !vertex_array_enabled(ctx)) return;
    ArrayVertices values;
    read_array_vertices(ctx, vertices, ArrayConversion::kVertexFetch, values, kDrawnArrays);
    record_array_draw(ctx, mode, std::move(values), {}, std::move(ranges),
                      ArrayDrawSource::kArrays);
  });
}

void glDrawElements(Context& ctx, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  or_out_of_memory(ctx, [&] {
    GLenum error = check_draw(ctx, mode, count);
    if (error == GL_NO_ERROR && !is_index_type(type)) error = GL_INVALID_ENUM;
    if (!begin_live_draw(ctx, error)) return;
    if (ctx.arrays.element_buffer && ctx.arrays.element_buffer->mapped)
      return record_error(ctx, GL_INVALID_OPERATION);
    draw_elements(ctx, mode, {count}, type, {indices});
  });
}

void glDrawRangeElements(Context& ctx, GLenum mode, GLuint start, GLuint end, GLsizei count,
                         GLenum type, const void* indices) {
  or_out_of_memory(ctx, [&] {
    // The range is a promise about the indices; glpt reads the indices themselves (as Mesa does,
    // indices outside it are drawn).
    if (end < start) {
      ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask);
      return record_error(ctx, GL_INVALID_VALUE);
    }
    glDrawElements(ctx, mode, count, type, indices);
  });
}

void glMultiDrawElements(Context& ctx, GLenum mode, const GLsizei* count, GLenum type,
                         const void* const* indices, GLsizei drawcount) {
  or_out_of_memory(ctx, [&] {
    GLenum error = drawcount < 0 ? GLenum{GL_INVALID_VALUE} : GLenum{GL_NO_ERROR};
    for (GLsizei d = 0; error == GL_NO_ERROR && d < drawcount && count != nullptr; ++d)
      if (count[d] < 0) error = GL_INVALID_VALUE;
    if (error == GL_NO_ERROR) error = check_draw(ctx, mode, 0);
    if (error == GL_NO_ERROR && !is_index_type(type)) error = GL_INVALID_ENUM;
    if (!begin_live_draw(ctx, error) || count == nullptr || indices == nullptr) return;
    if (ctx.arrays.element_buffer && ctx.arrays.element_buffer->mapped)
      return record_error(ctx, GL_INVALID_OPERATION);
    if (uint64_t(drawcount) > kMaxArrayDrawVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
    draw_elements(ctx, mode, std::vector<GLsizei>(count, count + drawcount), type,
                  std::vector<const void*>(indices, indices + drawcount));
  });
}

void glArrayElement(Context& ctx, GLint i) {
  or_out_of_memory(ctx, [&] {
    if (enabled_array_is_mapped(ctx.arrays)) return record_error(ctx, GL_INVALID_OPERATION);
    if (i < 0) return;  // reads nothing (Mesa reads before the arrays)
    ArrayVertices values;
    read_array_vertices(ctx, {uint32_t(i)}, ArrayConversion::kImmediate, values);
    array_element(ctx, values, 0);
  });
}

}  // namespace impl
}  // namespace glpt
