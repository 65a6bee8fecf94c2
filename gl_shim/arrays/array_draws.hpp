// Drawing from vertex arrays (GL 1.5 2.8): what glDrawArrays, glDrawElements,
// glDrawRangeElements, glMultiDraw*, glArrayElement and their display-list forms share.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gl_shim/arrays/array_fetch.hpp"
#include "gl_shim/gl_types.h"
#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;

// A draw may assemble at most this many vertices (as one glBegin/glEnd may); beyond it the draw
// is GL_OUT_OF_MEMORY and draws nothing.
inline constexpr uint64_t kMaxArrayDrawVertices = uint64_t{1} << 24;

// The vertices of the enabled arrays at `vertices` (vertex numbers), converted, each attribute
// stored per vertex.
struct ArrayVertices {
  uint32_t mask = 0;  // 1 << ArrayKind of the attributes held
  std::vector<glm::vec4> position, color, secondary_color;
  std::vector<glm::vec3> normal;
  std::vector<float> fog_coord, index;
  std::array<std::vector<glm::vec4>, rec::kMaxTextureUnits> tex_coord;
  std::vector<uint8_t> edge_flag;

  bool has(ArrayKind kind) const { return (mask & (1u << int(kind))) != 0; }
  uint32_t count() const { return uint32_t(position.size()); }
};

// Reads the listed vertices of every enabled array (the vertex array included) with `conversion`;
// only the arrays `kinds` names (bits 1 << ArrayKind).
inline constexpr uint32_t kAllArrays = (1u << kArrayKinds) - 1;
// What a draw reads: every array but the colour index one (glpt renders RGBA, and a draw sets
// no current value).
inline constexpr uint32_t kDrawnArrays = kAllArrays & ~(1u << int(ArrayKind::kIndex));
void read_array_vertices(const Context& ctx, const std::vector<uint32_t>& vertices,
                         ArrayConversion conversion, ArrayVertices& out,
                         uint32_t kinds = kAllArrays);
void read_array_vertices(const Context& ctx, const VertexSelection& vertices,
                         ArrayConversion conversion, ArrayVertices& out,
                         uint32_t kinds = kAllArrays);

// glArrayElement's effect for vertex `i` of the enabled arrays (immediate conversions): the
// current attributes, then a vertex (GL 1.5 2.8). Also what a compiled glArrayElement replays.
void array_element(Context& ctx, const ArrayVertices& values, uint32_t which);

// A draw of primitives of `mode` whose attributes come from `vertices` (arrays the program
// enabled) and otherwise from the current values, recorded into the frame. `indices` (may be
// empty: vertex i is element i) and `ranges` are the record's. `from_list`: replayed by glCallList
// (batched like a replayed glBegin/glEnd, as Mesa compiles array draws) rather than a live
// glDrawArrays/glDrawElements (one draw each).
// Returns the recorded vertices of a draw recorded on its own (null for batched, fed-back or
// selected draws and draws that record nothing).
enum class ArrayDrawSource : uint8_t { kArrays, kElements, kDisplayList };
std::shared_ptr<const rec::VertexData> record_array_draw(Context& ctx, GLenum mode,
                                                         ArrayVertices&& vertices,
                                                         std::vector<uint32_t> indices,
                                                         std::vector<rec::PrimitiveRange> ranges,
                                                         ArrayDrawSource source);

// Vertex numbers first .. first + count - 1.
std::vector<uint32_t> vertex_range(GLint first, GLsizei count);

// Validation shared by the live and compiled draws (GL 1.5 2.8, in Mesa's order): GL_NO_ERROR or
// the error the command raises.
GLenum check_draw(const Context& ctx, GLenum mode, GLsizei count);
bool is_index_type(GLenum type);

// The vertex numbers `count` indices of `type` at `indices` (an offset into the element array
// buffer when one is bound) name. False when they cannot be read (a null pointer without an
// element buffer, or a range beyond its store: nothing is drawn, as Mesa skips such draws).
bool read_indices(const Context& ctx, GLsizei count, GLenum type, const void* indices,
                  std::vector<uint32_t>& out);

}  // namespace glpt
