// The frame record: the frame as GL drew it, in GL's order. The one contract between the GL
// front end (gl_shim, which produces it) and its consumers in rt_core (raster mode draws it; the
// path tracer derives its scene from it). Nothing in it is specific to either consumer.
//
//   commands   Clear | Draw | Bitmap | DrawPixels | CopyPixels | Accum | Read | BeginQuery |
//              EndQuery, in call order
//   states     immutable, deduplicated snapshots of the GL state that decides pixels; each
//              command that produces fragments refers to one by StateId
//   vertices   per draw: the primitives as GL assembled them, attributes in object space
//
// A record covers the commands since the last time its consumer executed one (a swap, a read, a
// glFinish): the consumer applies them to the drawable's persistent buffers (colour front/back,
// depth, stencil, accumulation), which keep their contents between records as GL's do.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <memory>
#include <variant>
#include <vector>

#include "rt_core/record/gl_state.hpp"
#include "rt_core/record/texture.hpp"

namespace glpt::rec {

// ---- state ------------------------------------------------------------------------------------

// One snapshot of all the GL state that decides a command's pixels. Blocks are shared between
// snapshots (and between frames) while they are unchanged, so comparing two blocks by pointer
// is a cheap "certainly equal" test; equal contents under different pointers are still equal.
struct StateSnapshot {
  std::shared_ptr<const TransformState> transform;
  std::shared_ptr<const LightingState> lighting;
  std::shared_ptr<const TexturingState> texturing;
  std::shared_ptr<const RasterState> raster;
  std::shared_ptr<const PixelTransferState> pixel_transfer;
};

using StateId = uint32_t;  // index into FrameRecord::states

// ---- geometry ---------------------------------------------------------------------------------

struct PrimitiveRange {
  uint32_t first = 0;  // first element (index into `indices`, or vertex number without indices)
  uint32_t count = 0;
};

// How the program specified a draw's primitives. GL draws the same primitives either way, but
// Mesa assembles them differently (rt_core/record/decompose.hpp): its immediate-mode and
// glDrawArrays draws are non-indexed (llvmpipe splits smooth quads along the 0-2 diagonal), its
// display lists and glDrawElements are indexed (quads always split along 1-3).
enum class PrimitiveSource : uint8_t {
  kImmediate,    // glBegin/glEnd executed directly, including GL_COMPILE_AND_EXECUTE's execution
  kDisplayList,  // glBegin/glEnd replayed by glCallList(s) (Mesa compiles them to indexed draws)
  kArrays,       // glDrawArrays, glMultiDrawArrays: one range per call
  kElements,     // glDrawElements, glDrawRangeElements, glMultiDrawElements: indexed
};

// Bits of VertexData::per_vertex: attributes the program gave per vertex (for kImmediate and
// kDisplayList: set inside glBegin/glEnd; for arrays: from an enabled client array). Mesa's
// fragment shader reads such a colour as an interpolated input and a colour set only outside
// glBegin/glEnd as a constant, which decides how llvmpipe splits flat-shaded quads.
inline constexpr uint8_t kPerVertexColor = 1;
inline constexpr uint8_t kPerVertexSecondaryColor = 2;

// Content hashes of a draw's vertex data, so equal draws in different frames have equal keys.
// `geometry` covers what decides the shape (mode, source, per_vertex, positions, indices,
// primitives): recolouring never changes it, so an acceleration structure is reused.
// `attributes` covers everything else. The bounds come with them (computed in the same pass, and
// as reusable): the object-space box of the positions with w > 0 (after the divide by w); empty
// (min > max) when there is none.
struct VertexKeys {
  uint64_t geometry = 0;
  uint64_t attributes = 0;
  glm::vec3 bounds_min{1.0f}, bounds_max{-1.0f};
  bool bounded() const { return bounds_min.x <= bounds_max.x; }
};

// VertexData's cache of its keys and content id. A copy or move starts without them: the copy
// may be changed.
class CachedVertexKeys {
 public:
  CachedVertexKeys() = default;
  CachedVertexKeys(const CachedVertexKeys&) {}
  CachedVertexKeys& operator=(const CachedVertexKeys&) {
    valid = false;
    content_id.store(0, std::memory_order_relaxed);
    return *this;
  }
  bool valid = false;
  VertexKeys keys;
  std::atomic<uint64_t> content_id{0};  // 0: none given yet
};

// Per-vertex attributes of a draw in object space, with GL's current values as they were at
// each glVertex / array element. Every attribute array holds either one value per vertex or a
// single value shared by all vertices (it did not change during the draw). A texture coordinate
// array is empty when the unit is not used by the draw's state.
struct VertexData {
  // GL primitive type as given to glBegin / glDrawArrays: GL_POINTS .. GL_POLYGON. Consumers
  // decompose it as GL does (decompose.hpp): provoking vertices, edge flags, stipple resets.
  uint32_t mode = GL_TRIANGLES;
  PrimitiveSource source = PrimitiveSource::kImmediate;
  uint8_t per_vertex = 0;           // kPerVertex* bits
  std::vector<glm::vec4> position;  // homogeneous, as specified (w kept)
  std::vector<glm::vec3> normal;
  std::vector<glm::vec4> color;            // primary
  std::vector<glm::vec4> secondary_color;  // a is 0
  std::vector<float> fog_coord;
  std::array<std::vector<glm::vec4>, kMaxTextureUnits> tex_coord;
  std::vector<uint8_t> edge_flag;  // 0 / 1
  // Only when glMaterial was called between glBegin and glEnd (GL allows it): the front and back
  // material in effect at each vertex. Empty otherwise: the state snapshot's material applies.
  std::vector<std::array<Material, 2>> material;
  // Elements -> vertices (empty: element i is vertex i), and the primitives: one range per
  // glBegin/glEnd or per glDrawArrays/Elements call batched into this draw.
  std::vector<uint32_t> indices;
  std::vector<PrimitiveRange> primitives;

  uint32_t vertex_count() const { return static_cast<uint32_t>(position.size()); }
  // The bytes its arrays hold (attributes, edge flags, materials, indices, primitives), and the
  // bytes they have allocated (what keeping their storage for reuse keeps).
  size_t bytes() const;
  size_t capacity_bytes() const;

  // Identity (VertexKeys), hashed on first use and cached: only path-traced mode asks (to reuse
  // acceleration structures and accumulation), so raster mode never hashes a frame's megabytes of
  // vertices. A draw's data does not change once it is in a record; whoever changes a VertexData
  // in place after asking calls forget_keys(). Not thread-safe (a record has one consumer).
  const VertexKeys& keys() const;
  // A process-unique number for these contents, given on first use: two draws with the same
  // number hold the same vertices (the same object, unchanged). Cheaper than keys() (nothing is
  // hashed), but equal contents in two objects get two numbers. Consumers key what they derive
  // from a draw and keep across frames by it (rt_core's resident geometry): the front end hands
  // the same object to every frame that draws the same buffer-object vertices
  // (gl_shim/arrays/buffer_draw_cache.hpp). Thread-safe.
  uint64_t content_id() const;
  // Whoever changes a VertexData in place after it was in a record calls this: new keys and a
  // new content id on next use.
  void forget_keys() {
    cached_keys.valid = false;
    cached_keys.content_id.store(0, std::memory_order_relaxed);
  }
  mutable CachedVertexKeys cached_keys;
};

// Attribute accessors that hide the "one value or one per vertex" rule.
template <typename T>
const T& attribute_at(const std::vector<T>& values, uint32_t vertex, const T& fallback) {
  if (values.empty()) return fallback;
  return values.size() == 1 ? values[0] : values[vertex];
}

// The first vertex whose attribute differs from the one value stored so far: the earlier
// vertices get their copies (once per primitive at most, so kept out of the inline path).
template <typename T>
[[gnu::noinline, gnu::cold]] void widen_attribute(std::vector<T>& values, size_t vertex) {
  values.resize(vertex, T(values[0]));
}

// Stores the attribute of vertex `vertex` (the count before it) keeping the rule: the array
// stays one value while every vertex has the same bits, and becomes one value per vertex (the
// earlier ones filled in) at the first that differs. Bitwise: -0.0 and 0.0 are two values, as GL
// gave them. Always inline: immediate mode calls it for five attributes of every vertex, and as
// calls they were a fifth of bench/vertex_stream's capture time.
template <typename T>
[[gnu::always_inline]] inline void store_attribute(std::vector<T>& values, const T& value,
                                                   size_t vertex) {
  if (values.size() == 1 && vertex >= 1) [[likely]] {
    if (std::memcmp(&values[0], &value, sizeof value) == 0) [[likely]]
      return;
    widen_attribute(values, vertex);
  }
  values.push_back(value);
}

// Appends the attribute array of `from_count` vertices to that of `to_count` vertices, each under
// the rule; the result stays one value when both are the same one value. An empty `from` (an
// attribute the draw does not use) appends nothing.
template <typename T>
void append_attribute(std::vector<T>& to, size_t to_count, const std::vector<T>& from,
                      size_t from_count) {
  if (from.empty()) return;
  if (to.size() == 1 && from.size() == 1 && std::memcmp(&to[0], &from[0], sizeof(T)) == 0) return;
  if (to.size() == 1 && to_count > 1) to.resize(to_count, T(to[0]));
  if (from.size() == 1)
    to.insert(to.end(), from_count, from[0]);
  else
    to.insert(to.end(), from.begin(), from.end());
}

// ---- commands ---------------------------------------------------------------------------------

// glClear: `state` supplies the scissor box, colour/depth/stencil write masks, dither and the
// draw buffer the clear honours (GL 1.5 4.2.3).
struct Clear {
  StateId state = 0;
  uint32_t mask = 0;  // GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | ACCUM
  glm::vec4 color{0.0f};
  double depth = 1.0;  // glClearDepth's double: Mesa converts from it (raster/depth_clear.hpp)
  int32_t stencil = 0;
  glm::vec4 accum{0.0f};
};

struct Draw {
  StateId state = 0;
  std::shared_ptr<const VertexData> vertices;
};

// The current raster position (GL 1.5 2.13) as pixel commands use it.
struct RasterPosition {
  glm::vec4 window{0.0f, 0.0f, 0.0f, 1.0f};  // x, y, z in window coordinates; w: clip w
  bool valid = true;
  float distance = 0.0f;  // eye distance (fog coordinate)
  glm::vec4 color{1.0f};
  glm::vec4 secondary_color{0.0f, 0.0f, 0.0f, 1.0f};
  std::array<glm::vec4, kMaxTextureUnits> tex_coord{};
};

// glBitmap: fragments of the raster colour where the bitmap has ones, at the raster position
// minus (xorig, yorig); bitmaps are never zoomed.
struct Bitmap {
  StateId state = 0;
  RasterPosition raster;
  glm::vec2 origin{0.0f};  // window position of the bitmap's lower-left corner
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> bits;  // width * height, 0 or 1, rows bottom to top (unpacked)
  // The program's glBitmap calls this covers: Mesa's bitmap cache merges consecutive ones (text)
  // into one (gl_shim/pixels/bitmap_cache.cpp).
  uint32_t calls = 1;
};

enum class PixelKind : uint8_t { kColor, kDepth, kStencil };

// glDrawPixels: the image is already unpacked and through pixel transfer (GL 1.5 3.6.4-3.6.5),
// so what remains is rasterization with zoom and the per-fragment pipeline.
struct DrawPixels {
  StateId state = 0;
  RasterPosition raster;
  PixelKind kind = PixelKind::kColor;
  uint32_t width = 0, height = 0;
  std::vector<glm::vec4> color;   // kColor: width * height RGBA, rows bottom to top
  std::vector<float> depth;       // kDepth: [0, 1]
  std::vector<uint32_t> stencil;  // kStencil
  // False for the stencil half of a GL_DEPTH_STENCIL rectangle: GL counts its fragments once
  // (occlusion queries), with the depth half.
  bool counted = true;
};

// glCopyPixels: a rectangle of the read buffer (state's FragmentOpsState::read_buffer) drawn at
// the raster position, through the state's pixel transfer, zoom and per-fragment pipeline.
struct CopyPixels {
  StateId state = 0;
  RasterPosition raster;
  PixelKind kind = PixelKind::kColor;
  int32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
  bool counted = true;  // as DrawPixels::counted
};

// glAccum (GL 1.5 4.2.4): `state` supplies the scissor, colour write mask and buffers.
struct Accum {
  StateId state = 0;
  uint32_t op = GL_ACCUM;  // GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_ADD
  float value = 0.0f;
};

// A point where the program reads pixels back (glReadPixels, glCopyTexImage, glCopyPixels reads
// its source itself): everything before it must be rendered before the read is answered. The
// front end answers the read from the consumer's buffers after executing the record up to here.
struct Read {
  uint32_t buffer = GL_BACK;  // resolved read buffer
  PixelKind kind = PixelKind::kColor;
  int32_t x = 0, y = 0;
  uint32_t width = 0, height = 0;
  bool counted = true;  // as DrawPixels::counted
};

// glBeginQuery(GL_SAMPLES_PASSED, ...) and glEndQuery (GL 1.5 4.1.6): the samples of the
// commands between them that pass the depth and stencil tests are counted into the occlusion
// query `id`. Ids are the front end's (one per glBeginQuery, never reused by a context), so a
// restarted or deleted query never receives another query's samples. A query may begin in an
// earlier record (FrameRecord::query_at_start) and end in a later one; at most one is active at a
// time. Fragments count as Mesa counts them: those of glDrawPixels, glCopyPixels (Mesa never
// blits while a query is active) and glBitmap too, those of glClear and glAccum never.
struct BeginQuery {
  uint64_t id = 0;
};
struct EndQuery {
  uint64_t id = 0;
};

using Command =
    std::variant<Clear, Draw, Bitmap, DrawPixels, CopyPixels, Accum, Read, BeginQuery, EndQuery>;

struct FrameRecord {
  std::vector<StateSnapshot> states;
  std::vector<Command> commands;
  // The occlusion query active when the record starts (its BeginQuery was in an earlier record);
  // 0: none.
  uint64_t query_at_start = 0;

  void clear() {
    states.clear();
    commands.clear();
    query_at_start = 0;
  }
  bool empty() const { return commands.empty(); }
};

// The drawable a record is executed on: its size and which buffers it has (GLX visual / EGL
// config). Buffers a drawable lacks ignore clears, tests and writes as GL specifies.
struct DrawableConfig {
  uint32_t width = 0, height = 0;
  bool double_buffered = true;
  bool has_alpha = true;
  uint32_t depth_bits = 24;
  uint32_t stencil_bits = 8;
  uint32_t accum_bits = 16;  // per component; 0: no accumulation buffer
  // A framebuffer object's (EXT_framebuffer_object): single-buffered, its one colour buffer the
  // attachment the draw buffer names (GL_COLOR_ATTACHMENTn draws into the front buffer); what is
  // drawn there becomes a texture, so path-traced mode renders it as raster mode does.
  bool framebuffer_object = false;

  bool operator==(const DrawableConfig&) const = default;
};

}  // namespace glpt::rec
