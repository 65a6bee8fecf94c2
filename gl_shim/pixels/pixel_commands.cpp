// glBitmap, glDrawPixels, glCopyPixels (GL 1.5 3.6.4, 3.7, 4.3.3) and glAccum (4.2.4): each
// validates as GL (and Mesa, src/mesa/main/drawpix.c, accum.c) does and records its command with
// a snapshot of the state its fragments go through. Where they land is decided here, as Mesa
// decides it: bitmaps at floor(raster position + 1e-4 - origin), images and copies at the raster
// position rounded half away from zero (Mesa's "matches SGI's OpenGL" rounding). The consumer
// draws them (rt_core/raster/pixel_commands.cpp).
#include <algorithm>
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/bitmap_cache.hpp"
#include "gl_shim/pixels/rectangle_unpack.hpp"

namespace glpt {
namespace {

// Images larger than Mesa's largest texture are cut to it (Mesa draws pixel rectangles through
// a texture and does the same); images with more groups than kMaxGroups (a 4096 x 4096 image;
// the record holds 16 bytes per group) are GL_OUT_OF_MEMORY.
constexpr int32_t kMaxImageSide = 16384;
constexpr int64_t kMaxGroups = int64_t{1} << 24;

// The raster position of a pixel command, its x and y rounded as Mesa rounds them (lroundf).
// (A non-finite position stays as it is; nothing is drawn at it.)
rec::RasterPosition rounded_raster_position(const Context& ctx) {
  rec::RasterPosition p = ctx.raster_position;
  if (std::isfinite(p.window.x) && std::isfinite(p.window.y)) {
    p.window.x = static_cast<float>(std::llround(double{p.window.x}));
    p.window.y = static_cast<float>(std::llround(double{p.window.y}));
  }
  return p;
}

// Mesa validates its state (_mesa_update_state, which analyses the matrices) at these points of
// glBitmap, glDrawPixels and glCopyPixels; analysis decides later matrix arithmetic.
void validate_state(Context& ctx) { ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask); }

template <typename Command>
void record(Context& ctx, Command command) {
  command.state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  ctx.recorder.add(std::move(command));
  note_frame_content(ctx);
}

}  // namespace

namespace impl {

void glBitmap(Context& ctx, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig,
              GLfloat xmove, GLfloat ymove, const GLubyte* bitmap) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  rec::RasterPosition& rp = ctx.raster_position;
  if (!rp.valid) return;  // nothing drawn, and the raster position does not move (Mesa)
  validate_state(ctx);
  if (width > 0 && height > 0 && bitmap != nullptr) {
    if (int64_t{width} * height > kMaxGroups) return record_error(ctx, GL_OUT_OF_MEMORY);
    rec::Bitmap b;
    b.raster = rp;
    const float epsilon = 0.0001f;
    b.origin = glm::vec2(std::floor(rp.window.x + epsilon - xorig),
                         std::floor(rp.window.y + epsilon - yorig));
    b.width = static_cast<uint32_t>(width);
    b.height = static_cast<uint32_t>(height);
    b.bits = unpack_bitmap(ctx.framebuffer.unpack, width, height, bitmap);
    record_bitmap(ctx, std::move(b));
    note_frame_content(ctx);
  }
  rp.window.x += xmove;
  rp.window.y += ymove;
}

void glDrawPixels(Context& ctx, GLsizei width, GLsizei height, GLenum format, GLenum type,
                  const void* pixels) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  validate_state(ctx);
  if (const GLenum error = check_pixel_format_and_type(format, type); error != GL_NO_ERROR)
    return record_error(ctx, error);
  const rec::DrawableConfig& drawable = ctx.drawable;
  if ((format == GL_STENCIL_INDEX && drawable.stencil_bits == 0) ||
      (format == GL_DEPTH_COMPONENT && drawable.depth_bits == 0))
    return record_error(ctx, GL_INVALID_OPERATION);
  if (!ctx.raster_position.valid || width == 0 || height == 0 || pixels == nullptr) return;
  rec::DrawPixels d;
  // Rows wider than the largest image keep their stride (Mesa's clamp_size).
  const PixelStoreModes saved = ctx.framebuffer.unpack;
  if (width > kMaxImageSide && ctx.framebuffer.unpack.row_length == 0)
    ctx.framebuffer.unpack.row_length = width;
  const int32_t w = std::min(width, kMaxImageSide), h = std::min(height, kMaxImageSide);
  if (int64_t{w} * h > kMaxGroups) {
    ctx.framebuffer.unpack = saved;
    return record_error(ctx, GL_OUT_OF_MEMORY);
  }
  const bool unpacked = unpack_image(ctx, w, h, format, type, pixels, d);
  ctx.framebuffer.unpack = saved;
  if (!unpacked) return unimplemented(ctx, CommandId::glDrawPixels);
  d.raster = rounded_raster_position(ctx);
  record(ctx, std::move(d));
}

void glCopyPixels(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL)
    return record_error(ctx, GL_INVALID_ENUM);
  validate_state(ctx);
  const rec::DrawableConfig& drawable = ctx.drawable;
  if ((type == GL_DEPTH && drawable.depth_bits == 0) ||
      (type == GL_STENCIL && drawable.stencil_bits == 0))
    return record_error(ctx, GL_INVALID_OPERATION);
  if (!ctx.raster_position.valid || width == 0 || height == 0) return;
  rec::CopyPixels c;
  c.raster = rounded_raster_position(ctx);
  c.kind = type == GL_DEPTH     ? rec::PixelKind::kDepth
           : type == GL_STENCIL ? rec::PixelKind::kStencil
                                : rec::PixelKind::kColor;
  c.x = x;
  c.y = y;
  c.width = static_cast<uint32_t>(std::min(width, kMaxImageSide));
  c.height = static_cast<uint32_t>(std::min(height, kMaxImageSide));
  record(ctx, c);
}

void glAccum(Context& ctx, GLenum op, GLfloat value) {
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD)
    return record_error(ctx, GL_INVALID_ENUM);
  if (ctx.drawable.accum_bits == 0) return record_error(ctx, GL_INVALID_OPERATION);
  rec::Accum a;
  a.op = op;
  a.value = value;
  a.state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  record_before_bitmap_cache(ctx, a);  // Mesa's glAccum does not flush the bitmap cache
  note_frame_content(ctx);
}

}  // namespace impl
}  // namespace glpt
