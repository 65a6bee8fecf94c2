#include "gl_shim/state/hints.hpp"

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt {

GLenum* HintState::target(GLenum hint_target) {
  switch (hint_target) {
    case GL_PERSPECTIVE_CORRECTION_HINT:
      return &perspective_correction;
    case GL_POINT_SMOOTH_HINT:
      return &point_smooth;
    case GL_LINE_SMOOTH_HINT:
      return &line_smooth;
    case GL_POLYGON_SMOOTH_HINT:
      return &polygon_smooth;
    case GL_FOG_HINT:
      return &fog;
    case GL_TEXTURE_COMPRESSION_HINT:
      return &texture_compression;
    case GL_GENERATE_MIPMAP_HINT:
      return &generate_mipmap;
    default:
      return nullptr;
  }
}

namespace impl {

void glHint(Context& ctx, GLenum target, GLenum mode) {
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE)
    return record_error(ctx, GL_INVALID_ENUM);
  GLenum* hint = ctx.hints.target(target);
  if (hint == nullptr) return record_error(ctx, GL_INVALID_ENUM);
  *hint = mode;
}

}  // namespace impl
}  // namespace glpt
