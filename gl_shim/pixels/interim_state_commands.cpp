// INTERIM: glPixelZoom and glClearAccum, so the pixel rectangle and accumulation paths can be
// used and tested on this branch. Both are also implemented on other branches, with the same
// state fields: glPixelZoom in gl_shim/pixels/pixel_transfer.cpp (branch `textures`),
// glClearAccum in gl_shim/state/fragment_ops.cpp (branch `ffstate`). Delete this file when either
// is merged (the linker reports the duplicate definition).

#include "gl_shim/context.hpp"
#include "gl_shim/gl_impl_decls.hpp"

namespace glpt::impl {

void glPixelZoom(Context& ctx, GLfloat xfactor, GLfloat yfactor) {
  ctx.pixel_transfer.zoom_x = xfactor;
  ctx.pixel_transfer.zoom_y = yfactor;
}

// Clamped to [-1, 1] when specified (GL 1.5 4.2.3); NaN stays NaN, as in Mesa.
void glClearAccum(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  auto clamp = [](float v) { return v < -1.0f ? -1.0f : (v > 1.0f ? 1.0f : v); };
  ctx.framebuffer.clear_accum = {clamp(r), clamp(g), clamp(b), clamp(a)};
}

}  // namespace glpt::impl
