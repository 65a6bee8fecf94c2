// glReadPixels (GL 1.5 4.3.2): the framebuffer through read_framebuffer, pixel transfer and pack.
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_pack.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/state/out_of_memory.hpp"

namespace glpt {
namespace {

// GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil) as Mesa's
// read_depth_stencil_pixels: without depth scale/bias, stencil transfer or byte swapping it copies
// the Z24S8 words; otherwise depth goes through floats (z = the truncated float product of the
// transferred depth and 0xFFFFFF) and stencil through shift, offset and map.
void read_depth_stencil(Context& ctx, GLint x, GLint y, const PackTarget& dst) {
  const uint32_t w = uint32_t(dst.shape.width), h = uint32_t(dst.shape.height);
  FramebufferPixels depth, stencil;
  const GLenum buffer = ctx.raster.ops.read_buffer;
  if (!read_framebuffer(ctx, rec::PixelKind::kDepth, buffer, x, y, w, h, depth) ||
      !read_framebuffer(ctx, rec::PixelKind::kStencil, buffer, x, y, w, h, stencil))
    return;
  const size_t n = dst.shape.groups();
  if (depth.depth.size() != n || stencil.stencil.size() != n) return;
  const rec::PixelTransferState& t = ctx.pixel_transfer;
  const bool exact = t.depth_scale == 1.0f && t.depth_bias == 0.0f && t.index_shift == 0 &&
                     t.index_offset == 0 && !t.map_stencil && !dst.modes.swap_bytes;
  if (!exact) {
    transfer_depth(t, depth.depth);
    transfer_stencil(t, stencil.stencil);
  }
  std::vector<uint32_t> words(n);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t z = exact ? uint32_t(std::nearbyint(double(depth.depth[i]) * 16777215.0))
                             : uint32_t(depth.depth[i] * float(0xFFFFFF));
    words[i] = z << 8 | (stencil.stencil[i] & 0xFFu);
  }
  const PackTarget target{dst.modes, dst.shape, false, dst.data,
                          depth.inside.size() == n ? depth.inside.data() : nullptr};
  pack_indices(target, words);
}

}  // namespace

namespace impl {

void glReadPixels(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                  GLenum type, void* pixels) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  const ReadFramebufferScope read(ctx);
  if (const GLenum e = framebuffer_error(ctx); e != GL_NO_ERROR) return record_error(ctx, e);
  if (const GLenum e = check_format_and_type(format, type); e != GL_NO_ERROR)
    return record_error(ctx, e);
  const PixelClass kind_of_format = pixel_class(format);
  // glpt's contexts are RGBA: colour indices cannot be read (GL 1.5 4.3.2), nor can depth or
  // stencil values of a drawable without those buffers.
  const bool depth =
      kind_of_format == PixelClass::kDepth || kind_of_format == PixelClass::kDepthStencil;
  const bool stencil =
      kind_of_format == PixelClass::kStencilIndex || kind_of_format == PixelClass::kDepthStencil;
  if (kind_of_format == PixelClass::kColorIndex || (depth && ctx.drawable.depth_bits == 0) ||
      (stencil && ctx.drawable.stencil_bits == 0))
    return record_error(ctx, GL_INVALID_OPERATION);
  const ImageShape shape{width, height, 1, format, type};
  if (shape.groups() > kMaxPixelGroups) return record_error(ctx, GL_OUT_OF_MEMORY);
  const ClientImageLayout layout(ctx.framebuffer.pack, shape, false);
  if (!layout.valid()) return record_error(ctx, GL_INVALID_VALUE);
  // Without a pixel pack buffer (GL 2.1) a null pointer has nowhere to go: nothing is read.
  if (shape.groups() == 0 || pixels == nullptr) return;
  // Replayed by glpt-replay: what the program read goes nowhere (the trace holds what it did
  // next), so nothing is rendered to answer it.
  if (ctx.replayed) return;
  if (kind_of_format == PixelClass::kDepthStencil) {
    return or_out_of_memory(ctx, [&] {
      read_depth_stencil(ctx, x, y,
                         PackTarget{ctx.framebuffer.pack, shape, false, pixels, nullptr});
    });
  }

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
        if (type == GL_UNSIGNED_INT && ctx.pixel_transfer.depth_scale == 1.0f &&
            ctx.pixel_transfer.depth_bias == 0.0f) {
          // Mesa's path for 32-bit integers without scale or bias (read_depth_pixels): the
          // 24-bit values, widened by repeating their top bits below them (z24 -> z32 unorm).
          std::vector<uint32_t> words(fb.depth.size());
          for (size_t i = 0; i < words.size(); ++i) {
            const auto z24 = uint32_t(std::nearbyint(double(fb.depth[i]) * 16777215.0));
            words[i] = (z24 << 8) | (z24 >> 16);
          }
          pack_indices(dst, words);
          break;
        }
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

}  // namespace impl
}  // namespace glpt
