// INTERIM: glPixelZoom, so the pixel rectangle paths can be used and tested on this branch. It
// is also implemented on branch `textures` (gl_shim/pixels/pixel_transfer.cpp), with the same
// state fields: delete this file when that is merged (the linker reports the duplicate).
#include "gl_shim/context.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt::impl {

void glPixelZoom(Context& ctx, GLfloat xfactor, GLfloat yfactor) {
  ctx.pixel_transfer.zoom_x = xfactor;
  ctx.pixel_transfer.zoom_y = yfactor;
}

}  // namespace glpt::impl
