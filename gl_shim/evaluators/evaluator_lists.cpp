#include "gl_shim/evaluators/evaluator_lists.hpp"

#include <cstdint>
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/evaluators/evaluator_state.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {
namespace {

// One compiled glMap1 or glMap2 (v1, v2, vstride, vorder unused for glMap1).
struct CompiledMap {
  uint32_t target;
  float u1, u2, v1, v2;
  int32_t ustride, uorder, vstride, vorder;
  uint32_t has_points;
  uint32_t points_offset;
};

bool order_valid(GLint order) { return order >= 1 && order <= kMaxEvalOrder; }

// The control points packed as floats, or nothing if they cannot be read.
template <typename T>
std::vector<float> packed_points(GLenum target, const T* points, GLint ustride, GLint uorder,
                                 GLint vstride, GLint vorder) {
  const std::optional<EvaluatorTarget> t = evaluator_target(target);
  std::vector<float> out;
  if (points == nullptr || !t || !order_valid(uorder) || !order_valid(vorder) || ustride < 0 ||
      vstride < 0)
    return out;
  out.reserve(size_t(uorder) * size_t(vorder) * size_t(t->components));
  for (int64_t i = 0; i < uorder; ++i)
    for (int64_t j = 0; j < vorder; ++j)
      for (int k = 0; k < t->components; ++k)
        out.push_back(float(points[i * int64_t(ustride) + j * int64_t(vstride) + k]));
  return out;
}

void write(ListStream& list, CommandId command, CompiledMap rec, const std::vector<float>& points) {
  ListStream::Writer w(list, command, sizeof(CompiledMap));
  rec.has_points = points.empty() ? 0u : 1u;
  if (!points.empty()) rec.points_offset = w.append_array(points.data(), uint32_t(points.size()));
  w.set_record(rec);
}

template <typename T>
void compile_map1(ListStream& list, GLenum target, float u1, float u2, GLint stride, GLint order,
                  const T* points) {
  const std::vector<float> packed = packed_points(target, points, stride, order, 0, 1);
  CompiledMap rec{};
  rec.target = target;
  rec.u1 = u1;
  rec.u2 = u2;
  rec.uorder = order;
  rec.ustride = packed.empty() ? stride : evaluator_target(target)->components;
  write(list, CommandId::glMap1f, rec, packed);
}

template <typename T>
void compile_map2(ListStream& list, GLenum target, float u1, float u2, GLint ustride, GLint uorder,
                  float v1, float v2, GLint vstride, GLint vorder, const T* points) {
  const std::vector<float> packed = packed_points(target, points, ustride, uorder, vstride, vorder);
  CompiledMap rec{};
  rec.target = target;
  rec.u1 = u1;
  rec.u2 = u2;
  rec.v1 = v1;
  rec.v2 = v2;
  rec.uorder = uorder;
  rec.vorder = vorder;
  if (packed.empty()) {
    rec.ustride = ustride;
    rec.vstride = vstride;
  } else {
    rec.vstride = evaluator_target(target)->components;
    rec.ustride = rec.vstride * vorder;
  }
  write(list, CommandId::glMap2f, rec, packed);
}

// What the generated exec_glMap*f checks before the implementation.
bool outside_begin_end(Context& ctx) {
  if (!ctx.inside_begin_end()) return true;
  record_error(ctx, GL_INVALID_OPERATION);
  return false;
}

}  // namespace

void compile_map1f(Context&, ListStream& list, GLenum target, GLfloat u1, GLfloat u2, GLint stride,
                   GLint order, const GLfloat* points) {
  compile_map1(list, target, u1, u2, stride, order, points);
}

void compile_map1d(Context&, ListStream& list, GLenum target, GLdouble u1, GLdouble u2,
                   GLint stride, GLint order, const GLdouble* points) {
  compile_map1(list, target, float(u1), float(u2), stride, order, points);
}

void compile_map2f(Context&, ListStream& list, GLenum target, GLfloat u1, GLfloat u2, GLint ustride,
                   GLint uorder, GLfloat v1, GLfloat v2, GLint vstride, GLint vorder,
                   const GLfloat* points) {
  compile_map2(list, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

void compile_map2d(Context&, ListStream& list, GLenum target, GLdouble u1, GLdouble u2,
                   GLint ustride, GLint uorder, GLdouble v1, GLdouble v2, GLint vstride,
                   GLint vorder, const GLdouble* points) {
  compile_map2(list, target, float(u1), float(u2), ustride, uorder, float(v1), float(v2), vstride,
               vorder, points);
}

void replay_map1(Context& ctx, const ListStream::Reader& r) {
  const auto rec = r.record<CompiledMap>();
  if (!outside_begin_end(ctx)) return;
  impl::glMap1f(ctx, rec.target, rec.u1, rec.u2, rec.ustride, rec.uorder,
                rec.has_points ? r.payload<float>(rec.points_offset) : nullptr);
}

void replay_map2(Context& ctx, const ListStream::Reader& r) {
  const auto rec = r.record<CompiledMap>();
  if (!outside_begin_end(ctx)) return;
  impl::glMap2f(ctx, rec.target, rec.u1, rec.u2, rec.ustride, rec.uorder, rec.v1, rec.v2,
                rec.vstride, rec.vorder,
                rec.has_points ? r.payload<float>(rec.points_offset) : nullptr);
}

}  // namespace glpt
