// glClipPlane, glGetClipPlane (GL 1.5 spec 2.12). A plane is stored in eye space: the equation
// times the inverse of the modelview matrix current when it is specified, computed as Mesa does
// (its inverse, its row-vector product), so clipping matches Mesa's bit for bit.
#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/mesa_matrix.hpp"

namespace glpt {
namespace {

// The index of GL_CLIP_PLANEi, or -1 (GL_INVALID_ENUM recorded) for anything else.
int plane_index(Context& ctx, GLenum plane) {
  const int64_t p = int64_t{plane} - GL_CLIP_PLANE0;
  if (p < 0 || p >= rec::kMaxClipPlanes) {
    record_error(ctx, GL_INVALID_ENUM);
    return -1;
  }
  return static_cast<int>(p);
}

}  // namespace

namespace impl {

void glClipPlane(Context& ctx, GLenum plane, const GLdouble* equation) {
  const int p = plane_index(ctx, plane);
  if (p < 0 || equation == nullptr) return;
  const glm::vec4 object_plane(static_cast<float>(equation[0]), static_cast<float>(equation[1]),
                               static_cast<float>(equation[2]), static_cast<float>(equation[3]));
  const glm::vec4 eye_plane =
      transform_row_vector(object_plane, ctx.matrices.modelview.top_matrix().inverse());
  glm::vec4& stored = ctx.transform.clip_planes[static_cast<size_t>(p)];
  if (stored == eye_plane) return;
  stored = eye_plane;
  // Mesa re-derives an enabled plane's clip-space equation, analysing the projection matrix.
  if (ctx.transform.clip_plane_mask & (1u << p)) ctx.matrices.projection.top_matrix().analyse();
}

void glGetClipPlane(Context& ctx, GLenum plane, GLdouble* equation) {
  const int p = plane_index(ctx, plane);
  if (p < 0 || equation == nullptr) return;
  const glm::vec4& e = ctx.transform.clip_planes[static_cast<size_t>(p)];
  for (int i = 0; i < 4; ++i) equation[i] = e[i];
}

}  // namespace impl
}  // namespace glpt
