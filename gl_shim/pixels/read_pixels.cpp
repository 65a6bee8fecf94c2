// glReadPixels (GL 1.5 4.3.2): the framebuffer through read_framebuffer, pixel transfer and pack.
#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_pack.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/state/out_of_memory.hpp"

namespace glpt::impl {

void glReadPixels(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                  GLenum type, void* pixels) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (const GLenum e = check_format_and_type(format, type); e != GL_NO_ERROR)
    return record_error(ctx, e);
  const PixelClass kind_of_format = pixel_class(format);
  // glpt's contexts are RGBA: colour indices cannot be read (GL 1.5 4.3.2), nor can depth or
  // stencil values of a drawable without those buffers.
  if (kind_of_format == PixelClass::kColorIndex ||
      (kind_of_format == PixelClass::kDepth && ctx.drawable.depth_bits == 0) ||
      (kind_of_format == PixelClass::kStencilIndex && ctx.drawable.stencil_bits == 0))
    return record_error(ctx, GL_INVALID_OPERATION);
  const ImageShape shape{width, height, 1, format, type};
  if (shape.groups() > kMaxPixelGroups) return record_error(ctx, GL_OUT_OF_MEMORY);
  const ClientImageLayout layout(ctx.framebuffer.pack, shape, false);
  if (!layout.valid()) return record_error(ctx, GL_INVALID_VALUE);
  // Without a pixel pack buffer (GL 2.1) a null pointer has nowhere to go: nothing is read.
  if (shape.groups() == 0 || pixels == nullptr) return;

  const rec::PixelKind kind = kind_of_format == PixelClass::kDepth ? rec::PixelKind::kDepth
                              : kind_of_format == PixelClass::kStencilIndex
                                  ? rec::PixelKind::kStencil
                                  : rec::PixelKind::kColor;
  or_out_of_memory(ctx, [&] {
    FramebufferPixels fb;
    if (!read_framebuffer(ctx, kind, ctx.raster.ops.read_buffer, x, y, uint32_t(width),
                          uint32_t(height), fb))
      return;
    const PackTarget dst{ctx.framebuffer.pack, shape, false, pixels,
                         fb.inside.size() == shape.groups() ? fb.inside.data() : nullptr};
    switch (kind) {
      case rec::PixelKind::kColor:
        transfer_rgba(ctx.pixel_transfer, fb.color);
        pack_color(dst, fb.color, LuminanceFrom::kSumRgb);
        break;
      case rec::PixelKind::kDepth:
        transfer_depth(ctx.pixel_transfer, fb.depth);
        pack_depth(dst, fb.depth);
        break;
      case rec::PixelKind::kStencil:
        transfer_stencil(ctx.pixel_transfer, fb.stencil);
        pack_indices(dst, fb.stencil);
        break;
    }
  });
}

}  // namespace glpt::impl
