// glBitmap, glDrawPixels, glCopyPixels (GL 1.5 3.6.4, 3.7, 4.3.3) and glAccum (4.2.4): each
// validates as GL (and Mesa, src/mesa/main/drawpix.c, accum.c) does and records its command with
// a snapshot of the state its fragments go through. Where they land is decided here, as Mesa
// decides it: bitmaps at floor(raster position + 1e-4 - origin), images and copies at the raster
// position rounded half away from zero (Mesa's "matches SGI's OpenGL" rounding). The consumer
// draws them (rt_core/raster/pixel_commands.cpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/mesa_float.hpp"
#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/bitmap_cache.hpp"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_layout.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/pixels/pixel_unpack.hpp"
#include "gl_shim/state/out_of_memory.hpp"

namespace glpt {
namespace {

// Images larger than Mesa's largest texture are cut to it (Mesa draws pixel rectangles through
// a texture and does the same); images with more groups than kMaxGroups (a 4096 x 4096 image;
// the record holds 16 bytes per group) are GL_OUT_OF_MEMORY.
constexpr int32_t kMaxImageSide = 16384;
constexpr size_t kMaxGroups = size_t{1} << 24;

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

// The texture coordinates Mesa's fragments of pixel rectangles have (measured against OSMesa):
// current ones, untransformed (no texture matrix, no texgen), not the raster position's.
// glDrawPixels has unit 0's current coordinates; glCopyPixels unit 0's as Mesa last flushed the
// current values (usually at the glRasterPos); both (0, 0, 0, 1) on the other units. Bitmaps
// have every unit's as last flushed. (Bitmaps under a texture matrix or texgen read the quad's
// own coordinates instead: counted by the executor.)
rec::RasterPosition with_mesa_tex_coords(rec::RasterPosition p,
                                         const std::array<glm::vec4, rec::kMaxTextureUnits>& from,
                                         bool all_units) {
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    p.tex_coord[u] = u == 0 || all_units ? from[u] : glm::vec4(0, 0, 0, 1);
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

// glDrawPixels colours through pixel transfer as Mesa 25 draws them. Mesa uploads the image
// untransferred and applies scale/bias and the colour maps in its fragment shader
// (nir_lower_drawpixels): c = image * scale + bias (fused), then, with GL_MAP_COLOR, R and G from
// a 256-texel RGBA8 map texture at floor(c * 256) (entry floor(i * size / 256)), while B and A
// come from a lookup that samples the *image* at (c.b, c.a) and takes its R and G (the lookup
// has no texture source; measured, 5600 of 5600 components equal). Colour indices and stencil
// indices ignore INDEX_SHIFT / INDEX_OFFSET (and stencil MAP_STENCIL): Mesa's shaders do not
// apply them.
std::vector<glm::vec4> mesa_transfer_colors(const std::vector<glm::vec4>& image, int32_t width,
                                            int32_t height, const rec::PixelTransferState& t) {
  std::vector<glm::vec4> out(image.size());
  const rec::PixelMaps& maps = t.pixel_maps();
  auto map_texel = [&](GLenum map, float v) {
    const std::vector<float>& m = maps.maps[map - GL_PIXEL_MAP_I_TO_I];
    const int i = std::clamp(static_cast<int>(std::floor(v * 256.0f)), 0, 255);
    const float entry = m[size_t(i) * m.size() / 256];
    return float(mesa_float_to_ubyte(entry)) * (1.0f / 255.0f);  // util_pack_color
  };
  auto texel = [&](float s, float t_coord) {
    const int x = std::clamp(static_cast<int>(std::floor(s * float(width))), 0, width - 1);
    const int y = std::clamp(static_cast<int>(std::floor(t_coord * float(height))), 0, height - 1);
    return image[size_t(y) * size_t(width) + size_t(x)];
  };
  for (size_t i = 0; i < image.size(); ++i) {
    glm::vec4 c;
    for (int k = 0; k < 4; ++k) c[k] = std::fma(image[i][k], t.scale[k], t.bias[k]);
    if (t.map_color) {
      const glm::vec4 x = texel(c.b, c.a);
      c = glm::vec4(map_texel(GL_PIXEL_MAP_R_TO_R, c.r), map_texel(GL_PIXEL_MAP_G_TO_G, c.g), x.r,
                    x.g);
    }
    out[i] = glm::clamp(c, 0.0f, 1.0f);
  }
  return out;
}

// GL_DEPTH_STENCIL pixel rectangles (EXT_packed_depth_stencil) as Mesa's state tracker draws
// them (st_cb_drawpixels.c, draw_textured_quad with write_depth and write_stencil): the depth
// test always passes and writes depth under the depth write mask, the stencil index replaces the
// stencil buffer's under the stencil write mask, and nothing else of the fragment pipeline
// applies but the scissor (no colour is written). glpt records that as a stencil rectangle (which
// only writes stencil) and a depth rectangle whose state is the live one with the depth test
// forced to GL_ALWAYS and colour, alpha test, stencil test and blending off; the two write
// different buffers, so their order does not matter. An occlusion query counts the fragments of
// the depth half only, as Mesa counts its one quad.
template <typename Command>
void record_depth_stencil(Context& ctx, Command stencil, Command depth) {
  stencil.counted = false;
  record(ctx, std::move(stencil));
  const rec::FragmentOpsState live = ctx.raster.ops;
  struct Restore {
    Context& ctx;
    const rec::FragmentOpsState& ops;
    ~Restore() { ctx.raster.ops = ops; }
  } restore{ctx, live};
  rec::FragmentOpsState& ops = ctx.raster.ops;
  ops.depth_test = true;
  ops.depth_func = GL_ALWAYS;
  ops.stencil_test = ops.alpha_test = ops.blend = ops.color_logic_op = false;
  ops.color_write = {false, false, false, false};
  record(ctx, std::move(depth));
}

// A drawable has what a pixel rectangle of `kind` writes or reads.
bool drawable_has(const rec::DrawableConfig& drawable, PixelClass kind) {
  switch (kind) {
    case PixelClass::kStencilIndex:
      return drawable.stencil_bits != 0;
    case PixelClass::kDepth:
      return drawable.depth_bits != 0;
    case PixelClass::kDepthStencil:
      return drawable.depth_bits != 0 && drawable.stencil_bits != 0;
    default:
      return true;
  }
}

// glCopyPixels whose read framebuffer is not the draw framebuffer (EXT_framebuffer_blit): the
// rectangle is read from the read framebuffer (which must be complete and hold the buffer) and
// drawn into the draw framebuffer as glDrawPixels draws an image, through pixel transfer once,
// as glCopyPixels applies it.
void copy_between_framebuffers(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height,
                               PixelClass kind) {
  const uint32_t w = uint32_t(std::min(width, kMaxImageSide));
  const uint32_t h = uint32_t(std::min(height, kMaxImageSide));
  if (size_t{w} * h > kMaxGroups) return record_error(ctx, GL_OUT_OF_MEMORY);
  or_out_of_memory(ctx, [&] {
    FramebufferPixels color, depth, stencil;
    {
      const ReadFramebufferScope read(ctx);
      if (framebuffer_error(ctx) != GL_NO_ERROR || !drawable_has(ctx.drawable, kind))
        return record_error(ctx, GL_INVALID_OPERATION);
      const uint32_t buffer = ctx.raster.ops.read_buffer;
      const bool depth_kind = kind == PixelClass::kDepth || kind == PixelClass::kDepthStencil;
      const bool stencil_kind =
          kind == PixelClass::kStencilIndex || kind == PixelClass::kDepthStencil;
      if (!depth_kind && !stencil_kind &&
          !read_framebuffer(ctx, rec::PixelKind::kColor, buffer, x, y, w, h, color))
        return;
      if (depth_kind && !read_framebuffer(ctx, rec::PixelKind::kDepth, buffer, x, y, w, h, depth))
        return;
      if (stencil_kind &&
          !read_framebuffer(ctx, rec::PixelKind::kStencil, buffer, x, y, w, h, stencil))
        return;
    }
    rec::DrawPixels d;
    d.width = w;
    d.height = h;
    d.raster = with_mesa_tex_coords(rounded_raster_position(ctx), ctx.flushed_tex_coord, false);
    if (kind == PixelClass::kColor) {
      d.kind = rec::PixelKind::kColor;
      d.color = mesa_transfer_colors(color.color, int32_t(w), int32_t(h), ctx.pixel_transfer);
      return record(ctx, std::move(d));
    }
    rec::DrawPixels s = d;
    s.kind = rec::PixelKind::kStencil;
    s.stencil = std::move(stencil.stencil);
    d.kind = rec::PixelKind::kDepth;
    d.depth = std::move(depth.depth);
    transfer_depth(ctx.pixel_transfer, d.depth);
    if (kind == PixelClass::kDepthStencil)
      return record_depth_stencil(ctx, std::move(s), std::move(d));
    record(ctx, kind == PixelClass::kDepth ? std::move(d) : std::move(s));
  });
}

}  // namespace

namespace impl {

void glBitmap(Context& ctx, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig,
              GLfloat xmove, GLfloat ymove, const GLubyte* bitmap) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  rec::RasterPosition& rp = ctx.raster_position;
  if (!rp.valid) return;  // nothing drawn, and the raster position does not move (Mesa)
  validate_state(ctx);
  if (framebuffer_error(ctx) != GL_NO_ERROR) return record_error(ctx, GL_INVALID_OPERATION);
  if (ctx.render_mode.mode != GL_RENDER) {
    render_mode_pixel_rectangle(ctx, GL_BITMAP_TOKEN);  // and the raster position still moves
  } else if (width > 0 && height > 0 && bitmap != nullptr) {
    if (size_t(width) * size_t(height) > kMaxGroups) return record_error(ctx, GL_OUT_OF_MEMORY);
    rec::Bitmap b;
    b.raster = with_mesa_tex_coords(rp, ctx.flushed_tex_coord, true);
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
  ctx.flushed_tex_coord = ctx.current.tex_coord;  // Mesa's FLUSH_CURRENT
  if (framebuffer_error(ctx) != GL_NO_ERROR) return record_error(ctx, GL_INVALID_OPERATION);
  if (const GLenum error = check_format_and_type(format, type); error != GL_NO_ERROR)
    return record_error(ctx, error);
  const PixelClass kind = pixel_class(format);
  const rec::DrawableConfig& drawable = ctx.drawable;
  // Colour indices are drawn through the I_TO_R/G/B/A maps (RGBA mode); their sizes are never 0
  // in GL 1.5, so Mesa's "color index pixels into RGB buffer" error cannot happen.
  if (!drawable_has(drawable, kind)) return record_error(ctx, GL_INVALID_OPERATION);
  if (ctx.render_mode.mode != GL_RENDER) {
    if (ctx.raster_position.valid) render_mode_pixel_rectangle(ctx, GL_DRAW_PIXEL_TOKEN);
    return;
  }
  if (!ctx.raster_position.valid || width == 0 || height == 0 || pixels == nullptr) return;
  // Images larger than the largest texture are cut to it; rows keep their stride (Mesa's
  // clamp_size).
  PixelStoreModes modes = ctx.framebuffer.unpack;
  if (width > kMaxImageSide && modes.row_length == 0) modes.row_length = width;
  const ImageShape shape{std::min(width, kMaxImageSide), std::min(height, kMaxImageSide), 1, format,
                         type};
  if (shape.groups() > kMaxGroups) return record_error(ctx, GL_OUT_OF_MEMORY);
  if (!ClientImageLayout(modes, shape, false).valid()) return record_error(ctx, GL_INVALID_VALUE);
  rec::DrawPixels d;
  d.width = static_cast<uint32_t>(shape.width);
  d.height = static_cast<uint32_t>(shape.height);
  const UnpackSource source{modes, shape, false, pixels};
  or_out_of_memory(ctx, [&] {
    d.raster = with_mesa_tex_coords(rounded_raster_position(ctx), ctx.current.tex_coord, false);
    if (kind == PixelClass::kDepthStencil) {
      // Mesa stores the image as a Z24S8 texture as it is (measured: no depth scale or bias, no
      // stencil shift, offset or map) and its shader samples depth as float(z) * (1.0f /
      // 0xFFFFFF) (gallivm), which the depth buffer stores as z again.
      rec::DrawPixels stencil = d;
      stencil.kind = rec::PixelKind::kStencil;
      stencil.stencil = unpack_indices_raw(source);
      d.kind = rec::PixelKind::kDepth;
      const std::vector<uint32_t> words = unpack_depth_stencil_words(source);
      d.depth.resize(words.size());
      for (size_t i = 0; i < words.size(); ++i)
        d.depth[i] = float(words[i] >> 8) * (1.0f / float(0xFFFFFF));
      return record_depth_stencil(ctx, std::move(stencil), std::move(d));
    }
    if (kind == PixelClass::kDepth) {
      d.kind = rec::PixelKind::kDepth;
      d.depth = unpack_depth(source, ctx.pixel_transfer);
    } else if (kind == PixelClass::kStencilIndex) {
      d.kind = rec::PixelKind::kStencil;
      d.stencil = unpack_indices_raw(source);  // no shift, offset or map (Mesa)
    } else if (kind == PixelClass::kColorIndex) {
      d.kind = rec::PixelKind::kColor;
      rec::PixelTransferState t = ctx.pixel_transfer;
      t.index_shift = t.index_offset = 0;  // Mesa ignores them here
      d.color = unpack_color(source, t);
    } else {
      d.kind = rec::PixelKind::kColor;
      d.color = mesa_transfer_colors(unpack_color_raw(source), shape.width, shape.height,
                                     ctx.pixel_transfer);
    }
    record(ctx, std::move(d));
  });
}

void glCopyPixels(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL && type != GL_DEPTH_STENCIL_EXT)
    return record_error(ctx, GL_INVALID_ENUM);
  validate_state(ctx);
  if (framebuffer_error(ctx) != GL_NO_ERROR) return record_error(ctx, GL_INVALID_OPERATION);
  const PixelClass kind = type == GL_DEPTH               ? PixelClass::kDepth
                          : type == GL_STENCIL           ? PixelClass::kStencilIndex
                          : type == GL_DEPTH_STENCIL_EXT ? PixelClass::kDepthStencil
                                                         : PixelClass::kColor;
  if (!drawable_has(ctx.drawable, kind)) return record_error(ctx, GL_INVALID_OPERATION);
  if (ctx.render_mode.mode != GL_RENDER) {
    if (ctx.raster_position.valid) render_mode_pixel_rectangle(ctx, GL_COPY_PIXEL_TOKEN);
    return;
  }
  if (!ctx.raster_position.valid || width == 0 || height == 0) return;
  if (ctx.framebuffers.read_framebuffer != ctx.framebuffers.framebuffer)
    return copy_between_framebuffers(ctx, x, y, width, height, kind);
  rec::CopyPixels c;
  c.raster = with_mesa_tex_coords(rounded_raster_position(ctx), ctx.flushed_tex_coord, false);
  c.kind = type == GL_DEPTH     ? rec::PixelKind::kDepth
           : type == GL_STENCIL ? rec::PixelKind::kStencil
                                : rec::PixelKind::kColor;
  c.x = x;
  c.y = y;
  c.width = static_cast<uint32_t>(std::min(width, kMaxImageSide));
  c.height = static_cast<uint32_t>(std::min(height, kMaxImageSide));
  if (type == GL_DEPTH_STENCIL_EXT) {  // Mesa copies both through one depth-stencil quad
    rec::CopyPixels stencil = c;
    stencil.kind = rec::PixelKind::kStencil;
    c.kind = rec::PixelKind::kDepth;
    return record_depth_stencil(ctx, stencil, c);
  }
  record(ctx, c);
}

void glAccum(Context& ctx, GLenum op, GLfloat value) {
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD)
    return record_error(ctx, GL_INVALID_ENUM);
  if (ctx.drawable.accum_bits == 0) return record_error(ctx, GL_INVALID_OPERATION);
  if (ctx.render_mode.mode != GL_RENDER) return;  // selection and feedback touch no buffer
  rec::Accum a;
  a.op = op;
  a.value = value;
  a.state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  record_before_bitmap_cache(ctx, a);  // Mesa's glAccum does not flush the bitmap cache
  note_frame_content(ctx);
}

}  // namespace impl
}  // namespace glpt
