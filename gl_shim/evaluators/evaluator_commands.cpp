// Evaluators (GL 1.5 5.1): glMap1/glMap2, glMapGrid, glEvalCoord, glEvalPoint, glEvalMesh,
// glGetMap. Where the spec leaves room, Mesa 25.0.7 is followed (measured with OSMesa,
// tests/unit/mesa_reference/mesa_evaluator_probe.c):
//   - Errors come in Mesa's order (the domain before the order, the points, the target, the
//     strides, then a non-zero active texture unit). glMap1 with NULL points is
//     GL_INVALID_VALUE; glMap2 with NULL points is accepted and leaves the map without control
//     points (Mesa keeps a null pointer and would crash evaluating it; glpt evaluates nothing).
//   - An evaluated vertex is an ordinary vertex of the primitive being assembled; its colour,
//     normal and texture coordinates (unit 0) are evaluated if their maps are enabled and the
//     current ones otherwise. The current values are not changed (GL 1.5 5.1; Mesa saves and
//     restores its vertex). Of several texture maps the one with the most components counts, of
//     GL_MAP*_VERTEX_3/4 the 4-component one; GL_MAP*_INDEX maps do nothing (RGBA only).
//   - GL_AUTO_NORMAL takes the normal from Mesa's de Casteljau derivatives, unscaled by the
//     domain (Mesa 25.0.7 does not multiply by du * dv: a reversed domain does not flip it).
//   - glEvalMesh2(GL_FILL) draws one GL_TRIANGLE_STRIP per row, (u, v), (u, v + dv), ...;
//     GL_LINE the rows, then the columns, as line strips. glEvalMesh accumulates the grid step
//     (u += du), glEvalPoint computes i * du + u1 with a step it recomputes from the grid.
//   - Mesa fills attributes that were not yet part of its vertex with stale values for plain
//     vertices that follow an evaluated one in the same glBegin/glEnd; glpt gives them the
//     current values (the spec's rule).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/evaluators/bezier.hpp"
#include "gl_shim/evaluators/evaluator_state.hpp"
#include "gl_shim/geometry/attributes.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/query_values.hpp"

namespace glpt {
namespace {

// Slots (target - GL_MAP1_COLOR_4).
constexpr int kColorSlot = 0;
constexpr int kNormalSlot = 2;
constexpr int kTexture1Slot = 3;
constexpr int kTexture4Slot = 6;
constexpr int kVertex3Slot = 7;
constexpr int kVertex4Slot = 8;
constexpr int kComponents[kEvaluatorTargets] = {4, 1, 3, 1, 2, 3, 4, 3, 4};

// One glEvalMesh draws at most this many vertices; a bigger grid is GL_OUT_OF_MEMORY (the
// per-primitive limit of immediate mode, geometry/vertex_commands.cpp).
constexpr int64_t kMaxMeshVertices = int64_t{1} << 24;

GLenum first_target(int dimension) { return dimension == 1 ? GL_MAP1_COLOR_4 : GL_MAP2_COLOR_4; }

bool map_enabled(const Context& ctx, int dimension, int slot) {
  return ctx.enables.is(first_target(dimension) + GLenum(slot));
}

// Mesa's choice among the enabled maps of one attribute: the one with the most components.
std::optional<int> vertex_slot(const Context& ctx, int dimension) {
  if (map_enabled(ctx, dimension, kVertex4Slot)) return kVertex4Slot;
  if (map_enabled(ctx, dimension, kVertex3Slot)) return kVertex3Slot;
  return std::nullopt;
}

std::optional<int> texture_slot(const Context& ctx, int dimension) {
  for (int slot = kTexture4Slot; slot >= kTexture1Slot; --slot)
    if (map_enabled(ctx, dimension, slot)) return slot;
  return std::nullopt;
}

// The attributes of one evaluated vertex (unset: the current value).
struct EvaluatedVertex {
  glm::vec4 position{0.0f, 0.0f, 0.0f, 1.0f};
  std::optional<glm::vec4> color;
  std::optional<glm::vec3> normal;
  std::optional<glm::vec4> tex_coord;
};

// Unevaluated components are (0, 0, 0, 1).
glm::vec4 padded(const float* v) { return glm::vec4(v[0], v[1], v[2], v[3]); }

std::optional<glm::vec4> evaluate(const EvaluatorMap1& m, int slot, float u) {
  if (m.points.empty()) return std::nullopt;
  const float uu = (u - m.u1) * m.du;
  float out[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  const unsigned dim = unsigned(kComponents[slot]);
  bezier::curve(m.points.data(), dim, dim, unsigned(m.order), uu, out);
  return padded(out);
}

std::optional<glm::vec4> evaluate(const EvaluatorMap2& m, int slot, float u, float v) {
  if (m.points.empty()) return std::nullopt;
  const float uu = (u - m.u1) * m.du;
  const float vv = (v - m.v1) * m.dv;
  float out[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  bezier::surface(m.points.data(), unsigned(kComponents[slot]), unsigned(m.uorder),
                  unsigned(m.vorder), uu, vv, out);
  return padded(out);
}

// The vertex of a 2-D vertex map with its GL_AUTO_NORMAL normal, as Mesa computes it: the
// derivatives of a rational map corrected by w, their cross product normalized (a zero normal
// stays zero).
std::optional<EvaluatedVertex> evaluate_with_normal(const EvaluatorMap2& m, int slot, float u,
                                                    float v) {
  if (m.points.empty()) return std::nullopt;
  const float uu = (u - m.u1) * m.du;
  const float vv = (v - m.v1) * m.dv;
  const unsigned dim = unsigned(kComponents[slot]);
  float p[4] = {0.0f, 0.0f, 0.0f, 1.0f}, du[4], dv[4];
  bezier::surface_with_derivatives(m.points.data(), dim, unsigned(m.uorder), unsigned(m.vorder), uu,
                                   vv, p, du, dv);
  if (dim == 4) {
    for (int k = 0; k < 3; ++k) {
      du[k] = du[k] * p[3] - du[3] * p[k];
      dv[k] = dv[k] * p[3] - dv[3] * p[k];
    }
  }
  glm::vec3 n(du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
              du[0] * dv[1] - du[1] * dv[0]);
  float length_squared = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (length_squared != 0.0f) {
    const float scale = 1.0f / std::sqrt(length_squared);
    n[0] *= scale;
    n[1] *= scale;
    n[2] *= scale;
  }
  EvaluatedVertex e;
  e.position = padded(p);
  e.normal = n;
  return e;
}

// Adds the vertex to the primitive being assembled, with the evaluated attributes in place of the
// current ones for this vertex only. Mesa replays a display list's primitive that contains
// evaluated vertices through immediate mode (its "loopback"), so the primitive counts as
// immediate.
void emit(Context& ctx, const EvaluatedVertex& e) {
  if (!ctx.assembly.inside) return;  // a vertex outside glBegin/glEnd has no effect
  const CurrentAttributes saved = ctx.current;
  rec::VertexData& d = ctx.assembly.vertices;
  if (e.color) {
    ctx.current.color = *e.color;
    d.per_vertex |= rec::kPerVertexColor;
  }
  if (e.normal) ctx.current.normal = *e.normal;
  if (e.tex_coord) ctx.current.tex_coord[0] = *e.tex_coord;
  d.source = rec::PrimitiveSource::kImmediate;
  attribute_vertex(ctx, e.position);
  ctx.current = saved;
}

void eval_coord1(Context& ctx, float u) {
  const std::optional<int> vertex = vertex_slot(ctx, 1);
  if (!vertex || !ctx.assembly.inside) return;
  const auto& maps = ctx.evaluators.map1;
  const std::optional<glm::vec4> position = evaluate(maps[size_t(*vertex)], *vertex, u);
  if (!position) return;
  EvaluatedVertex e;
  e.position = *position;
  if (map_enabled(ctx, 1, kColorSlot)) e.color = evaluate(maps[kColorSlot], kColorSlot, u);
  if (const std::optional<int> t = texture_slot(ctx, 1))
    e.tex_coord = evaluate(maps[size_t(*t)], *t, u);
  if (map_enabled(ctx, 1, kNormalSlot)) {
    if (auto n = evaluate(maps[kNormalSlot], kNormalSlot, u)) e.normal = glm::vec3(*n);
  }
  emit(ctx, e);
}

void eval_coord2(Context& ctx, float u, float v) {
  const std::optional<int> vertex = vertex_slot(ctx, 2);
  if (!vertex || !ctx.assembly.inside) return;
  const auto& maps = ctx.evaluators.map2;
  const EvaluatorMap2& vertex_map = maps[size_t(*vertex)];
  std::optional<EvaluatedVertex> e;
  if (ctx.enables.is(GL_AUTO_NORMAL)) {
    e = evaluate_with_normal(vertex_map, *vertex, u, v);
  } else if (const std::optional<glm::vec4> p = evaluate(vertex_map, *vertex, u, v)) {
    e = EvaluatedVertex{};
    e->position = *p;
  }
  if (!e) return;
  if (map_enabled(ctx, 2, kColorSlot)) e->color = evaluate(maps[kColorSlot], kColorSlot, u, v);
  if (const std::optional<int> t = texture_slot(ctx, 2))
    e->tex_coord = evaluate(maps[size_t(*t)], *t, u, v);
  if (!e->normal && map_enabled(ctx, 2, kNormalSlot)) {  // GL_AUTO_NORMAL's takes precedence
    if (auto n = evaluate(maps[kNormalSlot], kNormalSlot, u, v)) e->normal = glm::vec3(*n);
  }
  emit(ctx, *e);
}

// The primitives of one glEvalMesh: glBegin/glEnd pairs as Mesa issues them, except that a run
// of empty ones after the first is skipped (they change nothing).
class MeshPrimitives {
 public:
  explicit MeshPrimitives(Context& ctx) : ctx_(ctx) {}
  template <typename Body>
  void add(GLenum mode, int64_t vertices, Body body) {
    if (vertices <= 0 && begun_) return;
    begun_ = true;
    impl::glBegin(ctx_, mode);
    if (!ctx_.assembly.inside) return;
    ctx_.assembly.vertices.source = rec::PrimitiveSource::kImmediate;  // Mesa calls glBegin
    body();
    impl::glEnd(ctx_);
  }

 private:
  Context& ctx_;
  bool begun_ = false;
};

int64_t span(GLint first, GLint last) { return std::max<int64_t>(0, int64_t(last) - first + 1); }

template <typename T>
void copy_points(std::vector<float>& out, const T* points, int components, int64_t uorder,
                 int64_t ustride, int64_t vorder, int64_t vstride) {
  out.resize(size_t(uorder * vorder * components));
  float* p = out.data();
  for (int64_t i = 0; i < uorder; ++i)
    for (int64_t j = 0; j < vorder; ++j)
      for (int k = 0; k < components; ++k) *p++ = float(points[i * ustride + j * vstride + k]);
}

template <typename T>
void map1(Context& ctx, GLenum target, float u1, float u2, GLint stride, GLint order,
          const T* points) {
  if (u1 == u2) return record_error(ctx, GL_INVALID_VALUE);
  if (order < 1 || order > kMaxEvalOrder) return record_error(ctx, GL_INVALID_VALUE);
  if (points == nullptr) return record_error(ctx, GL_INVALID_VALUE);
  const std::optional<EvaluatorTarget> t = evaluator_target(target);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (stride < t->components) return record_error(ctx, GL_INVALID_VALUE);
  // GL 1.2.1 F.2.13, as Mesa: maps belong to texture unit 0.
  if (ctx.textures.active != 0) return record_error(ctx, GL_INVALID_OPERATION);
  if (t->dimension != 1) return record_error(ctx, GL_INVALID_ENUM);
  EvaluatorMap1& m = ctx.evaluators.map1[size_t(t->slot)];
  copy_points(m.points, points, t->components, order, stride, 1, 0);
  m.order = order;
  m.u1 = u1;
  m.u2 = u2;
  m.du = 1.0f / (u2 - u1);
}

template <typename T>
void map2(Context& ctx, GLenum target, float u1, float u2, GLint ustride, GLint uorder, float v1,
          float v2, GLint vstride, GLint vorder, const T* points) {
  if (u1 == u2 || v1 == v2) return record_error(ctx, GL_INVALID_VALUE);
  if (uorder < 1 || uorder > kMaxEvalOrder || vorder < 1 || vorder > kMaxEvalOrder)
    return record_error(ctx, GL_INVALID_VALUE);
  const std::optional<EvaluatorTarget> t = evaluator_target(target);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (ustride < t->components || vstride < t->components)
    return record_error(ctx, GL_INVALID_VALUE);
  if (ctx.textures.active != 0) return record_error(ctx, GL_INVALID_OPERATION);
  if (t->dimension != 2) return record_error(ctx, GL_INVALID_ENUM);
  EvaluatorMap2& m = ctx.evaluators.map2[size_t(t->slot)];
  if (points == nullptr) {
    m.points.clear();  // Mesa: no error, and a map without points
  } else {
    copy_points(m.points, points, t->components, uorder, ustride, vorder, vstride);
  }
  m.uorder = uorder;
  m.vorder = vorder;
  m.u1 = u1;
  m.u2 = u2;
  m.du = 1.0f / (u2 - u1);
  m.v1 = v1;
  m.v2 = v2;
  m.dv = 1.0f / (v2 - v1);
}

// Mesa's integer conversion of map values: lroundf, then the long narrowed to GLint. Out of the
// range of long (NaN included) x86-64's conversion gives LONG_MIN, whose low half is 0.
GLint lround_to_int(float f) {
  if (!(std::fabs(f) < 9.2233720368547758e18f)) return 0;
  return static_cast<GLint>(static_cast<uint32_t>(static_cast<uint64_t>(std::lround(f))));
}

// glGetMap{f,d,i}v: the values of `query` for `target` through `convert` (Mesa's order of checks;
// a null `v` receives nothing).
template <typename T, typename Convert>
void get_map(Context& ctx, GLenum target, GLenum query, T* v, Convert convert) {
  const std::optional<EvaluatorTarget> t = evaluator_target(target);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (query != GL_COEFF && query != GL_ORDER && query != GL_DOMAIN)
    return record_error(ctx, GL_INVALID_ENUM);
  if (v == nullptr) return;
  const EvaluatorState& s = ctx.evaluators;
  if (t->dimension == 1) {
    const EvaluatorMap1& m = s.map1[size_t(t->slot)];
    if (query == GL_COEFF) {
      for (size_t i = 0; i < m.points.size(); ++i) v[i] = convert(m.points[i]);
    } else if (query == GL_ORDER) {
      v[0] = T(m.order);
    } else {
      v[0] = convert(m.u1);
      v[1] = convert(m.u2);
    }
    return;
  }
  const EvaluatorMap2& m = s.map2[size_t(t->slot)];
  if (query == GL_COEFF) {
    for (size_t i = 0; i < m.points.size(); ++i) v[i] = convert(m.points[i]);
  } else if (query == GL_ORDER) {
    v[0] = T(m.uorder);
    v[1] = T(m.vorder);
  } else {
    v[0] = convert(m.u1);
    v[1] = convert(m.u2);
    v[2] = convert(m.v1);
    v[3] = convert(m.v2);
  }
}

}  // namespace

EvaluatorState::EvaluatorState() {
  // GL 1.5 table 6.25: order-1 maps of the initial attribute values.
  static constexpr float kInitial[kEvaluatorTargets][4] = {
      {1, 1, 1, 1}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}, {0, 0, 0, 1},
      {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}};
  for (int slot = 0; slot < kEvaluatorTargets; ++slot) {
    const float* p = kInitial[slot];
    map1[size_t(slot)].points.assign(p, p + kComponents[slot]);
    map2[size_t(slot)].points.assign(p, p + kComponents[slot]);
  }
}

std::optional<EvaluatorTarget> evaluator_target(GLenum target) {
  for (int dimension = 1; dimension <= 2; ++dimension) {
    const GLenum first = first_target(dimension);
    if (target >= first && target < first + kEvaluatorTargets) {
      const int slot = int(target - first);
      return EvaluatorTarget{dimension, slot, kComponents[slot]};
    }
  }
  return std::nullopt;
}

bool lookup_evaluator_state(const Context& ctx, GLenum pname, query::Value* out) {
  const EvaluatorGrid& g = ctx.evaluators.grid;
  switch (pname) {
    case GL_MAP1_GRID_DOMAIN: {
      const float d[2] = {g.u1_1, g.u2_1};
      *out = query::floats(d, 2);
      return true;
    }
    case GL_MAP1_GRID_SEGMENTS:
      *out = query::ints({double(g.un1)});
      return true;
    case GL_MAP2_GRID_DOMAIN: {
      const float d[4] = {g.u1_2, g.u2_2, g.v1_2, g.v2_2};
      *out = query::floats(d, 4);
      return true;
    }
    case GL_MAP2_GRID_SEGMENTS:
      *out = query::ints({double(g.un2), double(g.vn2)});
      return true;
    default:
      return false;
  }
}

namespace impl {

void glMap1f(Context& ctx, GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
             const GLfloat* points) {
  map1(ctx, target, u1, u2, stride, order, points);
}

void glMap1d(Context& ctx, GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
             const GLdouble* points) {
  map1(ctx, target, float(u1), float(u2), stride, order, points);
}

void glMap2f(Context& ctx, GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
             GLfloat v1, GLfloat v2, GLint vstride, GLint vorder, const GLfloat* points) {
  map2(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

void glMap2d(Context& ctx, GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
             GLdouble v1, GLdouble v2, GLint vstride, GLint vorder, const GLdouble* points) {
  map2(ctx, target, float(u1), float(u2), ustride, uorder, float(v1), float(v2), vstride, vorder,
       points);
}

void glMapGrid1f(Context& ctx, GLint un, GLfloat u1, GLfloat u2) {
  if (un < 1) return record_error(ctx, GL_INVALID_VALUE);
  EvaluatorGrid& g = ctx.evaluators.grid;
  g.un1 = un;
  g.u1_1 = u1;
  g.u2_1 = u2;
  g.du1 = (u2 - u1) / float(un);
}

void glMapGrid1d(Context& ctx, GLint un, GLdouble u1, GLdouble u2) {
  glMapGrid1f(ctx, un, float(u1), float(u2));
}

void glMapGrid2f(Context& ctx, GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2) {
  if (un < 1 || vn < 1) return record_error(ctx, GL_INVALID_VALUE);
  EvaluatorGrid& g = ctx.evaluators.grid;
  g.un2 = un;
  g.u1_2 = u1;
  g.u2_2 = u2;
  g.du2 = (u2 - u1) / float(un);
  g.vn2 = vn;
  g.v1_2 = v1;
  g.v2_2 = v2;
  g.dv2 = (v2 - v1) / float(vn);
}

void glMapGrid2d(Context& ctx, GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1,
                 GLdouble v2) {
  glMapGrid2f(ctx, un, float(u1), float(u2), vn, float(v1), float(v2));
}

void glEvalCoord1f(Context& ctx, GLfloat u) { eval_coord1(ctx, u); }
void glEvalCoord1d(Context& ctx, GLdouble u) { eval_coord1(ctx, float(u)); }
void glEvalCoord1fv(Context& ctx, const GLfloat* u) {
  if (u != nullptr) eval_coord1(ctx, u[0]);
}
void glEvalCoord1dv(Context& ctx, const GLdouble* u) {
  if (u != nullptr) eval_coord1(ctx, float(u[0]));
}
void glEvalCoord2f(Context& ctx, GLfloat u, GLfloat v) { eval_coord2(ctx, u, v); }
void glEvalCoord2d(Context& ctx, GLdouble u, GLdouble v) { eval_coord2(ctx, float(u), float(v)); }
void glEvalCoord2fv(Context& ctx, const GLfloat* u) {
  if (u != nullptr) eval_coord2(ctx, u[0], u[1]);
}
void glEvalCoord2dv(Context& ctx, const GLdouble* u) {
  if (u != nullptr) eval_coord2(ctx, float(u[0]), float(u[1]));
}

void glEvalPoint1(Context& ctx, GLint i) {
  const EvaluatorGrid& g = ctx.evaluators.grid;
  const float du = (g.u2_1 - g.u1_1) / float(g.un1);
  eval_coord1(ctx, float(i) * du + g.u1_1);
}

void glEvalPoint2(Context& ctx, GLint i, GLint j) {
  const EvaluatorGrid& g = ctx.evaluators.grid;
  const float du = (g.u2_2 - g.u1_2) / float(g.un2);
  const float dv = (g.v2_2 - g.v1_2) / float(g.vn2);
  eval_coord2(ctx, float(i) * du + g.u1_2, float(j) * dv + g.v1_2);
}

void glEvalMesh1(Context& ctx, GLenum mode, GLint i1, GLint i2) {
  if (mode != GL_POINT && mode != GL_LINE) return record_error(ctx, GL_INVALID_ENUM);
  if (!vertex_slot(ctx, 1)) return;
  const int64_t n = span(i1, i2);
  if (n > kMaxMeshVertices) return record_error(ctx, GL_OUT_OF_MEMORY);
  const EvaluatorGrid& g = ctx.evaluators.grid;
  const float du = g.du1;
  MeshPrimitives(ctx).add(mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP, n, [&] {
    float u = g.u1_1 + float(i1) * du;
    for (int64_t i = 0; i < n; ++i, u += du) eval_coord1(ctx, u);
  });
}

void glEvalMesh2(Context& ctx, GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL)
    return record_error(ctx, GL_INVALID_ENUM);
  if (!vertex_slot(ctx, 2)) return;
  const int64_t ni = span(i1, i2), nj = span(j1, j2);
  const int64_t rows = mode == GL_FILL ? std::max<int64_t>(0, nj - 1) : nj;
  // In doubles: the product of two spans can overflow.
  const double vertices = double(ni) * double(rows) * (mode == GL_POINT ? 1 : 2);
  MeshPrimitives primitives(ctx);
  if (vertices == 0) {
    // Only empty glBegin/glEnd pairs, if Mesa issues any.
    if (mode == GL_POINT) primitives.add(GL_POINTS, 0, [] {});
    if (mode == GL_LINE && ni + nj > 0) primitives.add(GL_LINE_STRIP, 0, [] {});
    if (mode == GL_FILL && rows > 0) primitives.add(GL_TRIANGLE_STRIP, 0, [] {});
    return;
  }
  if (vertices > double(kMaxMeshVertices)) return record_error(ctx, GL_OUT_OF_MEMORY);
  const EvaluatorGrid& g = ctx.evaluators.grid;
  const float du = g.du2, dv = g.dv2;
  const float u_first = g.u1_2 + float(i1) * du;
  const float v_first = g.v1_2 + float(j1) * dv;
  switch (mode) {
    case GL_POINT:
      primitives.add(GL_POINTS, ni * nj, [&] {
        float v = v_first;
        for (int64_t j = 0; j < nj; ++j, v += dv) {
          float u = u_first;
          for (int64_t i = 0; i < ni; ++i, u += du) eval_coord2(ctx, u, v);
        }
      });
      break;
    case GL_LINE: {
      float v = v_first;
      for (int64_t j = 0; j < nj; ++j, v += dv) {
        primitives.add(GL_LINE_STRIP, ni, [&] {
          float u = u_first;
          for (int64_t i = 0; i < ni; ++i, u += du) eval_coord2(ctx, u, v);
        });
      }
      float u = u_first;
      for (int64_t i = 0; i < ni; ++i, u += du) {
        primitives.add(GL_LINE_STRIP, nj, [&] {
          float vv = v_first;
          for (int64_t j = 0; j < nj; ++j, vv += dv) eval_coord2(ctx, u, vv);
        });
      }
      break;
    }
    default: {  // GL_FILL
      float v = v_first;
      for (int64_t j = 0; j < rows; ++j, v += dv) {
        primitives.add(GL_TRIANGLE_STRIP, 2 * ni, [&] {
          float u = u_first;
          for (int64_t i = 0; i < ni; ++i, u += du) {
            eval_coord2(ctx, u, v);
            eval_coord2(ctx, u, v + dv);
          }
        });
      }
      break;
    }
  }
}

void glGetMapfv(Context& ctx, GLenum target, GLenum query, GLfloat* v) {
  get_map(ctx, target, query, v, [](float f) { return f; });
}

void glGetMapdv(Context& ctx, GLenum target, GLenum query, GLdouble* v) {
  get_map(ctx, target, query, v, [](float f) { return double(f); });
}

void glGetMapiv(Context& ctx, GLenum target, GLenum query, GLint* v) {
  get_map(ctx, target, query, v, lround_to_int);
}

}  // namespace impl
}  // namespace glpt
