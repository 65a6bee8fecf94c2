// glTexImage1D/2D/3D, glTexSubImage1D/2D/3D, glCopyTexImage1D/2D, glCopyTexSubImage1D/2D/3D,
// glGetTexImage (GL 1.5 3.8.1-3.8.3, 3.8.11 proxies, 6.1.4).
//
// Errors are checked in Mesa's order. Sizes need not be powers of two (Mesa exposes
// ARB_texture_non_power_of_two, and programs rely on it). Borders are validated and reported, but
// the stored texels exclude them, as in Mesa's gallium drivers.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/frame/framebuffer_access.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_pack.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/pixels/pixel_unpack.hpp"
#include "gl_shim/state/out_of_memory.hpp"
#include "gl_shim/textures/internal_formats.hpp"
#include "gl_shim/textures/mipmap_generation.hpp"
#include "gl_shim/textures/texel_codec.hpp"
#include "gl_shim/textures/texture_targets.hpp"

namespace glpt {
namespace {

// Whether a client format carries depth values (DEPTH_COMPONENT, or DEPTH_STENCIL's depth).
bool depth_data(GLenum format) {
  const PixelClass c = pixel_class(format);
  return c == PixelClass::kDepth || c == PixelClass::kDepthStencil;
}

// GL 1.5 3.8.1 with EXT_packed_depth_stencil (Mesa's texture_formats_agree): depth and
// depth-stencil internal formats take DEPTH_COMPONENT or DEPTH_STENCIL data, colour ones colour
// (or colour index) data; STENCIL_INDEX never names texels.
bool formats_agree(const InternalFormatInfo& info, GLenum format) {
  if (format == GL_STENCIL_INDEX) return false;
  return info.is_depth() == depth_data(format);
}

// Mesa's _mesa_image_transfer_state: whether Mesa's texture stores run pixel transfer on the
// stencil indices they unpack (RGBA scale/bias, index shift/offset or colour maps set).
bool stencil_transfer_applies(const rec::PixelTransferState& t) {
  return t.scale != glm::vec4(1.0f) || t.bias != glm::vec4(0.0f) || t.index_shift != 0 ||
         t.index_offset != 0 || t.map_color;
}

// GL 1.5 3.8.1: a border of 0 or 1 texels; rectangle textures have none (ARB_texture_rectangle,
// GL_INVALID_VALUE in Mesa, proxies included).
bool legal_border(const ImageTarget& t, GLint border) {
  return border >= 0 && border <= (t.slot == kSlotRect ? 0 : 1);
}

// Whether GL (with Mesa's non-power-of-two sizes) supports an image of this size at `level`.
bool legal_dimensions(const ImageTarget& t, GLint level, GLsizei w, GLsizei h, GLsizei d,
                      GLint border) {
  const int64_t max = int64_t(t.slot == kSlot3D     ? kMax3DTextureSize
                              : t.slot == kSlotRect ? kMaxRectangleTextureSize
                                                    : kMaxTextureSize) >>
                      level;
  const auto fits = [&](GLsizei s) { return s >= 2 * border && s <= max + 2 * border; };
  if (!fits(w)) return false;
  if (t.dims >= 2 && !fits(h)) return false;
  if (t.dims == 3 && !fits(d)) return false;
  return t.slot != kSlotCube || w == h;
}

// An image of w x h x d texels as specified (border included), with the border stripped.
std::shared_ptr<rec::TextureImage> new_image(const ImageTarget& t, GLint internal_format, GLsizei w,
                                             GLsizei h, GLsizei d, GLint border) {
  auto img = std::make_shared<rec::TextureImage>();
  img->border = uint32_t(border);
  img->internal_format = uint32_t(internal_format);
  img->width = uint32_t(w - 2 * border);
  img->height = t.dims >= 2 ? uint32_t(h - 2 * border) : 1u;
  img->depth = t.dims == 3 ? uint32_t(d - 2 * border) : 1u;
  return img;
}

// The unpack modes that read the interior of a bordered client image (Mesa's
// strip_texture_border): skip the border, keep the full row and image lengths.
PixelStoreModes without_border(PixelStoreModes m, int dims, GLsizei w, GLsizei h, GLint border) {
  if (border == 0) return m;
  if (m.row_length == 0) m.row_length = w;
  m.skip_pixels += border;
  if (dims >= 2) {
    if (m.image_height == 0) m.image_height = h;
    m.skip_rows += border;
  }
  if (dims == 3) m.skip_images += border;
  return m;
}

// Depth texels from client data as Mesa stores them: unsigned integers of the texture's own
// width are copied (texstore's memcpy), and _mesa_unpack_depth_span's integer shortcuts
// (32 -> 16 bits: >> 16; 16 -> 32 bits: replicated) apply without depth scale and bias; anything
// else goes through floats and truncates.
// GL_UNSIGNED_INT_24_8 data keeps its 24 depth bits in a 24-bit format (Mesa's shortcut) and
// goes through floats into the others.
void encode_client_depth(const Context& ctx, const InternalFormatInfo& info,
                         const UnpackSource& src, size_t n, uint8_t* texels) {
  const GLenum type = src.shape.type;
  const bool plain =
      ctx.pixel_transfer.depth_scale == 1.0f && ctx.pixel_transfer.depth_bias == 0.0f;
  if (plain && type == GL_UNSIGNED_INT_24_8_EXT && info.depth == 24) {
    const std::vector<uint32_t> words = unpack_depth_stencil_words(src);
    for (size_t i = 0; i < n && i < words.size(); ++i)
      encode_depth_unorm_texel(info, words[i] >> 8, texels + i * 4);
    return;
  }
  const bool ushort = type == GL_UNSIGNED_SHORT, uint = type == GL_UNSIGNED_INT;
  if (plain && ((ushort && (info.depth == 16 || info.depth == 32)) ||
                (uint && (info.depth == 16 || info.depth == 32)))) {
    const std::vector<uint32_t> values = unpack_indices_raw(src);
    for (size_t i = 0; i < n && i < values.size(); ++i) {
      uint32_t z = values[i];
      if (uint && info.depth == 16) z >>= 16;
      if (ushort && info.depth == 32) z |= z << 16;
      encode_depth_unorm_texel(info, z, texels + i * 4);
    }
    return;
  }
  const std::vector<float> depth = unpack_depth(src, ctx.pixel_transfer);
  encode_depth_texels(info, depth.data(), n, texels, DepthRounding::kTruncate);
}

// The stencil indices of a depth-stencil image from GL_DEPTH_STENCIL data (Mesa's
// _mesa_texstore_z24_s8: the low 8 bits, through stencil pixel transfer when Mesa runs any).
// Other data leaves them zero (GL: undefined).
std::vector<uint8_t> stencil_from_client(const Context& ctx, const UnpackSource& src, size_t n) {
  std::vector<uint8_t> stencil(n, 0);
  if (src.shape.format != GL_DEPTH_STENCIL_EXT) return stencil;
  std::vector<uint32_t> indices = unpack_indices_raw(src);
  if (stencil_transfer_applies(ctx.pixel_transfer)) transfer_stencil(ctx.pixel_transfer, indices);
  for (size_t i = 0; i < n && i < indices.size(); ++i) stencil[i] = uint8_t(indices[i]);
  return stencil;
}

// An image's contents: texels, and the stencil indices of depth-stencil formats.
struct ImageContents {
  std::vector<uint8_t> texels, stencil;
};

// Contents of `info` from a client image (unpack, pixel transfer, base format conversion,
// quantization). Null data leaves them zero (GL: undefined).
ImageContents texels_from_client(const Context& ctx, const InternalFormatInfo& info,
                                 const PixelStoreModes& modes, const ImageShape& shape,
                                 bool three_d, const void* pixels) {
  const size_t n = shape.groups();
  ImageContents contents;
  contents.texels.assign(n * rec::texel_bytes(info.texel_format()), 0);
  if (info.stencil != 0) contents.stencil.assign(n, 0);
  if (pixels == nullptr || n == 0) return contents;
  const UnpackSource src{modes, shape, three_d, pixels};
  std::vector<uint8_t>& texels = contents.texels;
  if (info.is_depth()) {
    encode_client_depth(ctx, info, src, n, texels.data());
    if (info.stencil != 0) contents.stencil = stencil_from_client(ctx, src, n);
  } else {
    // Mesa converts from the client's own components unless pixel transfer ran (then from RGBA
    // floats) or they are colour indices (then from the RGBA bytes it looks them up as).
    const rec::PixelTransferState& t = ctx.pixel_transfer;
    const bool transfer = t.map_color || t.scale != glm::vec4(1.0f) || t.bias != glm::vec4(0.0f);
    if (!transfer && encode_byte_texels(info, src, texels.data())) return contents;
    const std::vector<glm::vec4> rgba = unpack_color(src, ctx.pixel_transfer);
    if (shape.format == GL_COLOR_INDEX || transfer) {
      encode_color_texels(info, rgba.data(), n, texels.data(),
                          shape.format == GL_COLOR_INDEX ? ColorSourceLayout::bytes()
                                                         : ColorSourceLayout::floats());
    } else {
      const std::vector<glm::uvec4> integers = unpack_color_integers(src);
      encode_color_texels(info, rgba.data(), n, texels.data(),
                          color_source_layout(shape.format, shape.type), integers.data());
    }
  }
  return contents;
}

// Contents of `info` from a rectangle of the read buffer (depth buffer for depth formats, and the
// stencil buffer for depth-stencil ones, which Mesa blits unchanged), through pixel transfer
// (GL 1.5 3.8.2: as glCopyPixels up to the final conversion).
ImageContents texels_from_framebuffer(Context& ctx, const InternalFormatInfo& info, GLint x,
                                      GLint y, GLsizei w, GLsizei h) {
  const size_t n = size_t(std::max(w, 0)) * size_t(std::max(h, 0));
  ImageContents contents;
  contents.texels.assign(n * rec::texel_bytes(info.texel_format()), 0);
  if (info.stencil != 0) contents.stencil.assign(n, 0);
  if (n == 0) return contents;
  const bool depth = info.is_depth();
  FramebufferPixels fb;
  if (!read_framebuffer(ctx, depth ? rec::PixelKind::kDepth : rec::PixelKind::kColor,
                        ctx.raster.ops.read_buffer, x, y, uint32_t(w), uint32_t(h), fb))
    return contents;  // nothing to read from: undefined contents
  if (depth && fb.depth.size() == n) {
    transfer_depth(ctx.pixel_transfer, fb.depth);
    encode_depth_texels(info, fb.depth.data(), n, contents.texels.data());
  } else if (!depth && fb.color.size() == n) {
    transfer_rgba(ctx.pixel_transfer, fb.color);
    encode_color_texels(info, fb.color.data(), n, contents.texels.data());
  }
  FramebufferPixels stencil;
  if (info.stencil != 0 &&
      read_framebuffer(ctx, rec::PixelKind::kStencil, ctx.raster.ops.read_buffer, x, y, uint32_t(w),
                       uint32_t(h), stencil) &&
      stencil.stencil.size() == n) {
    for (size_t i = 0; i < n; ++i) contents.stencil[i] = uint8_t(stencil.stencil[i]);
  }
  return contents;
}

// GL 1.5 3.8.2: a sub-image must lie inside the image, border included.
bool region_fits(const rec::TextureImage& img, int dims, GLint xoff, GLint yoff, GLint zoff,
                 GLsizei w, GLsizei h, GLsizei d) {
  const int64_t b = img.border;
  const auto fits = [&](int64_t off, int64_t size, int64_t interior) {
    return off >= -b && off + size <= interior + b;
  };
  if (!fits(xoff, w, img.width)) return false;
  if (dims >= 2 && !fits(yoff, h, img.height)) return false;
  return dims < 3 || fits(zoff, d, img.depth);
}

// Copies a w x h x d block of elements of `bytes` bytes into `dst`, an array laid out as the
// image's texels, at (xoff, yoff, zoff) (interior coordinates); the parts that fall on the
// (unstored) border are dropped.
void write_block(const rec::TextureImage* img, std::vector<uint8_t>& dst, GLint xoff, GLint yoff,
                 GLint zoff, GLsizei w, GLsizei h, GLsizei d, const std::vector<uint8_t>& src_block,
                 uint32_t texel) {
  const int64_t x0 = std::max<int64_t>(xoff, 0);
  const int64_t x1 = std::min<int64_t>(int64_t(xoff) + w, img->width);
  if (x1 <= x0) return;
  for (int64_t k = 0; k < d; ++k) {
    const int64_t z = int64_t(zoff) + k;
    if (z < 0 || z >= img->depth) continue;
    for (int64_t j = 0; j < h; ++j) {
      const int64_t y = int64_t(yoff) + j;
      if (y < 0 || y >= img->height) continue;
      const uint8_t* from = src_block.data() + ((k * h + j) * w + (x0 - xoff)) * texel;
      uint8_t* to = dst.data() + ((z * img->height + y) * img->width + x0) * texel;
      std::memcpy(to, from, size_t(x1 - x0) * texel);
    }
  }
}

// Writes a w x h x d block of contents at (xoff, yoff, zoff) (interior coordinates).
void write_region(TextureObject& object, const ImageTarget& t, GLint level, GLint xoff, GLint yoff,
                  GLint zoff, GLsizei w, GLsizei h, GLsizei d, const ImageContents& contents,
                  uint32_t texel) {
  rec::TextureImage* img = object.image_for_update(t.face, level);
  if (img == nullptr) return;
  write_block(img, img->texels, xoff, yoff, zoff, w, h, d, contents.texels, texel);
  if (!contents.stencil.empty()) {
    img->stencil.resize(img->texels.size() / texel, 0);
    write_block(img, img->stencil, xoff, yoff, zoff, w, h, d, contents.stencil, 1);
  }
}

// After any change to an image: GL_GENERATE_MIPMAP recomputes the levels above a changed base.
void image_changed(TextureObject& object, const ImageTarget& t, GLint level) {
  // Rectangle textures have no levels to generate (Mesa skips them too).
  if (!t.proxy && t.slot != kSlotRect && object.generate_mipmap &&
      level == object.sampler().base_level)
    generate_mipmaps(object, t.face);
}

void tex_image(Context& ctx, int dims, GLenum target, GLint level, GLint internal_format, GLsizei w,
               GLsizei h, GLsizei d, GLint border, GLenum format, GLenum type, const void* pixels) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kAccepted);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  if (!legal_border(*t, border) || w < 0 || h < 0 || d < 0)
    return record_error(ctx, GL_INVALID_VALUE);
  if (internal_format_info(internal_format) == nullptr) return record_error(ctx, GL_INVALID_VALUE);
  if (const GLenum e = check_format_and_type(format, type); e != GL_NO_ERROR)
    return record_error(ctx, e);
  const GLint sized = sized_format_for(internal_format, format, type);
  const InternalFormatInfo* info = stored_format_info(uint32_t(internal_format), uint32_t(sized));
  if (!formats_agree(*info, format)) return record_error(ctx, GL_INVALID_OPERATION);
  // Mesa's _mesa_legal_texture_base_format_for_target: no three-dimensional depth textures.
  if (info->is_depth() && t->slot == kSlot3D) return record_error(ctx, GL_INVALID_OPERATION);
  const bool legal = legal_dimensions(*t, level, w, h, d, border);
  TextureObject& object = target_object(ctx, *t);
  if (t->proxy) {
    // GL 1.5 3.8.11: an unsupported proxy image is no error; its state becomes all zero (it
    // reads as an undefined image, as in Mesa).
    std::shared_ptr<rec::TextureImage> img;
    if (legal) {
      img = new_image(*t, internal_format, w, h, d, border);
      img->sized_format = sized != internal_format ? uint32_t(sized) : 0u;
    }
    return object.set_image(t->face, level, std::move(img));
  }
  if (!legal) return record_error(ctx, GL_INVALID_VALUE);
  const ImageShape full{w, dims >= 2 ? h : 1, dims == 3 ? d : 1, format, type};
  if (!ClientImageLayout(ctx.framebuffer.unpack, full, dims == 3).valid())
    return record_error(ctx, GL_INVALID_VALUE);
  or_out_of_memory(ctx, [&] {
    std::shared_ptr<rec::TextureImage> img = new_image(*t, internal_format, w, h, d, border);
    img->sized_format = sized != internal_format ? uint32_t(sized) : 0u;
    const ImageShape inner{GLsizei(img->width), GLsizei(img->height), GLsizei(img->depth), format,
                           type};
    ImageContents contents =
        texels_from_client(ctx, *info, without_border(ctx.framebuffer.unpack, dims, w, h, border),
                           inner, dims == 3, pixels);
    img->texels = std::move(contents.texels);
    img->stencil = std::move(contents.stencil);
    object.set_image(t->face, level, std::move(img));
    image_changed(object, *t, level);
  });
}

// The checks every sub-image command starts with; false when an error was recorded.
bool valid_sub_image_args(Context& ctx, const std::optional<ImageTarget>& t, GLint level, GLsizei w,
                          GLsizei h, GLsizei d) {
  if (!t) {
    record_error(ctx, GL_INVALID_ENUM);
    return false;
  }
  if (level < 0 || level >= max_texture_levels(t->slot) || w < 0 || h < 0 || d < 0) {
    record_error(ctx, GL_INVALID_VALUE);
    return false;
  }
  return true;
}

void tex_sub_image(Context& ctx, int dims, GLenum target, GLint level, GLint xoff, GLint yoff,
                   GLint zoff, GLsizei w, GLsizei h, GLsizei d, GLenum format, GLenum type,
                   const void* pixels) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kRejected);
  if (!valid_sub_image_args(ctx, t, level, w, h, d)) return;
  if (const GLenum e = check_format_and_type(format, type); e != GL_NO_ERROR)
    return record_error(ctx, e);
  const rec::TextureImage* img = target_object(ctx, *t).image(t->face, level);
  if (img == nullptr) return record_error(ctx, GL_INVALID_OPERATION);  // undefined image
  const InternalFormatInfo* info = stored_format_info(img->internal_format, img->sized_format);
  if (info == nullptr || !formats_agree(*info, format))
    return record_error(ctx, GL_INVALID_OPERATION);
  if (!region_fits(*img, dims, xoff, yoff, zoff, w, h, d))
    return record_error(ctx, GL_INVALID_VALUE);
  const ImageShape shape{w, h, d, format, type};
  if (shape.groups() == 0 || pixels == nullptr) return;
  if (!ClientImageLayout(ctx.framebuffer.unpack, shape, dims == 3).valid())
    return record_error(ctx, GL_INVALID_VALUE);
  TextureObject& object = target_object(ctx, *t);
  or_out_of_memory(ctx, [&] {
    const ImageContents contents =
        texels_from_client(ctx, *info, ctx.framebuffer.unpack, shape, dims == 3, pixels);
    write_region(object, *t, level, xoff, yoff, zoff, w, h, d, contents,
                 rec::texel_bytes(info->texel_format()));
    image_changed(object, *t, level);
  });
}

// Mesa's copytexture_error_check: depth formats need a depth buffer to copy from, depth-stencil
// ones a stencil buffer too.
bool framebuffer_has_source(const Context& ctx, const InternalFormatInfo& info) {
  if (!info.is_depth()) return true;
  return ctx.drawable.depth_bits != 0 && (info.stencil == 0 || ctx.drawable.stencil_bits != 0);
}

void copy_tex_image(Context& ctx, int dims, GLenum target, GLint level, GLenum internal_format,
                    GLint x, GLint y, GLsizei w, GLsizei h, GLint border) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kRejected);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot) || !legal_border(*t, border) || w < 0 ||
      h < 0)
    return record_error(ctx, GL_INVALID_VALUE);
  // GL 1.5 3.8.2: not 1..4. Mesa reports a bad internal format here as GL_INVALID_ENUM.
  const InternalFormatInfo* info = internal_format_info(GLint(internal_format));
  if (info == nullptr || internal_format <= 4) return record_error(ctx, GL_INVALID_ENUM);
  if (!legal_dimensions(*t, level, w, h, 1, border)) return record_error(ctx, GL_INVALID_VALUE);
  if (!framebuffer_has_source(ctx, *info))
    return record_error(ctx, GL_INVALID_OPERATION);  // nothing to copy depth (stencil) from
  TextureObject& object = target_object(ctx, *t);
  or_out_of_memory(ctx, [&] {
    std::shared_ptr<rec::TextureImage> img = new_image(*t, GLint(internal_format), w, h, 1, border);
    // The border texels are read from the framebuffer's edge of the rectangle and dropped.
    ImageContents contents =
        texels_from_framebuffer(ctx, *info, x + border, dims >= 2 ? y + border : y,
                                GLsizei(img->width), GLsizei(img->height));
    img->texels = std::move(contents.texels);
    img->stencil = std::move(contents.stencil);
    object.set_image(t->face, level, std::move(img));
    image_changed(object, *t, level);
  });
}

void copy_tex_sub_image(Context& ctx, int dims, GLenum target, GLint level, GLint xoff, GLint yoff,
                        GLint zoff, GLint x, GLint y, GLsizei w, GLsizei h) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kRejected);
  if (!valid_sub_image_args(ctx, t, level, w, h, 1)) return;
  const rec::TextureImage* img = target_object(ctx, *t).image(t->face, level);
  if (img == nullptr) return record_error(ctx, GL_INVALID_OPERATION);  // undefined image
  if (!region_fits(*img, dims, xoff, yoff, zoff, w, dims >= 2 ? h : 1, 1))
    return record_error(ctx, GL_INVALID_VALUE);
  const InternalFormatInfo* info = stored_format_info(img->internal_format, img->sized_format);
  if (info == nullptr) return;
  if (!framebuffer_has_source(ctx, *info)) return record_error(ctx, GL_INVALID_OPERATION);
  if (w == 0 || h == 0) return;
  TextureObject& object = target_object(ctx, *t);
  or_out_of_memory(ctx, [&] {
    const ImageContents contents = texels_from_framebuffer(ctx, *info, x, y, w, h);
    write_region(object, *t, level, xoff, yoff, zoff, w, h, 1, contents,
                 rec::texel_bytes(info->texel_format()));
    image_changed(object, *t, level);
  });
}

// GL 1.5 6.1.4 (+ ARB_depth_texture, EXT_abgr, EXT_packed_depth_stencil): the formats
// glGetTexImage writes. STENCIL_INDEX reads a depth-stencil texture's stencil indices, as Mesa
// allows (it exposes ARB_texture_stencil8).
bool get_tex_image_format(GLenum format) {
  const PixelClass c = pixel_class(format);
  return c == PixelClass::kColor || c == PixelClass::kDepth || c == PixelClass::kDepthStencil ||
         c == PixelClass::kStencilIndex;
}

// Mesa's teximage_error_check: whether glGetTexImage may read an image of `info` as `format`.
bool get_tex_image_formats_agree(const InternalFormatInfo& info, GLenum format) {
  switch (pixel_class(format)) {
    case PixelClass::kDepth:
      return info.is_depth();
    case PixelClass::kDepthStencil:
    case PixelClass::kStencilIndex:
      return info.base_format == GL_DEPTH_STENCIL_EXT;
    default:
      return !info.is_depth();
  }
}

void get_tex_image(Context& ctx, GLenum target, GLint level, GLenum format, GLenum type,
                   void* pixels) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  const std::optional<ImageTarget> t = image_target(target, 0, ProxyTargets::kRejected);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  if (!get_tex_image_format(format)) return record_error(ctx, GL_INVALID_ENUM);
  if (const GLenum e = check_format_and_type(format, type); e != GL_NO_ERROR)
    return record_error(ctx, e);
  const rec::TextureImage* img = target_object(ctx, *t).image(t->face, level);
  if (img == nullptr) return;  // nothing defined, nothing written (not an error)
  const InternalFormatInfo* info = stored_format_info(img->internal_format, img->sized_format);
  if (info == nullptr) return;
  if (!get_tex_image_formats_agree(*info, format)) return record_error(ctx, GL_INVALID_OPERATION);
  // The image as GL reports it, border included; the stripped border texels repeat the edge.
  const int32_t b = int32_t(img->border);
  const ImageShape shape{int32_t(img->width) + 2 * b,
                         t->dims >= 2 ? int32_t(img->height) + 2 * b : 1,
                         t->dims == 3 ? int32_t(img->depth) + 2 * b : 1, format, type};
  if (shape.groups() == 0 || pixels == nullptr || img->texels.empty()) return;
  if (!ClientImageLayout(ctx.framebuffer.pack, shape, t->dims == 3).valid())
    return record_error(ctx, GL_INVALID_VALUE);
  or_out_of_memory(ctx, [&] {
    const uint32_t texel = rec::texel_bytes(info->texel_format());
    const auto source = [&](int32_t x, int32_t y, int32_t z) {
      const auto inside = [](int32_t v, int32_t border, uint32_t n) {
        return size_t(std::clamp(v - border, 0, int32_t(n) - 1));
      };
      const size_t i = (inside(z, t->dims == 3 ? b : 0, img->depth) * img->height +
                        inside(y, t->dims >= 2 ? b : 0, img->height)) *
                           img->width +
                       inside(x, b, img->width);
      return img->texels.data() + i * texel;
    };
    const PackTarget dst{ctx.framebuffer.pack, shape, t->dims == 3, pixels, nullptr};
    const auto stencil_at = [&](int32_t x, int32_t y, int32_t z) -> uint32_t {
      const size_t i = size_t(source(x, y, z) - img->texels.data()) / texel;
      return i < img->stencil.size() ? img->stencil[i] : 0u;
    };
    // No pixel transfer: Mesa's glGetTexImage applies none (measured: not even to stencil).
    if (format == GL_DEPTH_STENCIL_EXT || format == GL_STENCIL_INDEX) {
      // Depth as the 24-bit value Mesa stores, above the stencil index (Mesa copies Z24S8).
      std::vector<uint32_t> values;
      values.reserve(shape.groups());
      for (int32_t z = 0; z < shape.depth; ++z)
        for (int32_t y = 0; y < shape.height; ++y)
          for (int32_t x = 0; x < shape.width; ++x) {
            const uint32_t z24 =
                uint32_t(std::nearbyint(double(decode_depth_texel(source(x, y, z))) * 0xFFFFFF));
            values.push_back(format == GL_STENCIL_INDEX ? stencil_at(x, y, z)
                                                        : z24 << 8 | stencil_at(x, y, z));
          }
      pack_indices(dst, values);
    } else if (format == GL_DEPTH_COMPONENT) {
      std::vector<float> depth;
      depth.reserve(shape.groups());
      for (int32_t z = 0; z < shape.depth; ++z)
        for (int32_t y = 0; y < shape.height; ++y)
          for (int32_t x = 0; x < shape.width; ++x)
            depth.push_back(decode_depth_texel(source(x, y, z)));
      pack_depth(dst, depth);
    } else {
      // Bytes come out as Mesa's integer conversion gives them: glpt's stored 8-bit values.
      const bool bytes = type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_INT_8_8_8_8 ||
                         type == GL_UNSIGNED_INT_8_8_8_8_REV;
      const TexelValue value = bytes && info->texel_format() == rec::TexelFormat::kRgba8
                                   ? TexelValue::kStored
                                   : TexelValue::kExact;
      std::vector<glm::vec4> rgba;
      rgba.reserve(shape.groups());
      for (int32_t z = 0; z < shape.depth; ++z)
        for (int32_t y = 0; y < shape.height; ++y)
          for (int32_t x = 0; x < shape.width; ++x)
            rgba.push_back(decode_color_texel(*info, source(x, y, z), value));
      pack_color(dst, rgba, LuminanceFrom::kRed);
    }
  });
}

// glCompressedTex*: glpt supports no specific compressed format (GL_NUM_COMPRESSED_TEXTURE_FORMATS
// is 0, and the generic ones are not accepted by these commands, GL 1.5 3.8.3), so every call
// that gets past the target and level checks is an error.
void compressed_tex_image(Context& ctx, int dims, GLenum target, GLint level) {
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kAccepted);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  record_error(ctx, GL_INVALID_ENUM);  // not a compressed internal format glpt supports
}

void compressed_tex_sub_image(Context& ctx, int dims, GLenum target, GLint level) {
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kRejected);
  if (!valid_sub_image_args(ctx, t, level, 0, 0, 0)) return;
  record_error(ctx, GL_INVALID_OPERATION);  // no image is compressed
}

}  // namespace

namespace impl {

void glTexImage1D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width,
                  GLint border, GLenum format, GLenum type, const void* pixels) {
  tex_image(ctx, 1, target, level, internalformat, width, 1, 1, border, format, type, pixels);
}
void glTexImage2D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width,
                  GLsizei height, GLint border, GLenum format, GLenum type, const void* pixels) {
  tex_image(ctx, 2, target, level, internalformat, width, height, 1, border, format, type, pixels);
}
void glTexImage3D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width,
                  GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type,
                  const void* pixels) {
  tex_image(ctx, 3, target, level, internalformat, width, height, depth, border, format, type,
            pixels);
}

void glTexSubImage1D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLsizei width,
                     GLenum format, GLenum type, const void* pixels) {
  tex_sub_image(ctx, 1, target, level, xoffset, 0, 0, width, 1, 1, format, type, pixels);
}
void glTexSubImage2D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                     GLsizei width, GLsizei height, GLenum format, GLenum type,
                     const void* pixels) {
  tex_sub_image(ctx, 2, target, level, xoffset, yoffset, 0, width, height, 1, format, type, pixels);
}
void glTexSubImage3D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                     GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format,
                     GLenum type, const void* pixels) {
  tex_sub_image(ctx, 3, target, level, xoffset, yoffset, zoffset, width, height, depth, format,
                type, pixels);
}

void glCopyTexImage1D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLint x,
                      GLint y, GLsizei width, GLint border) {
  copy_tex_image(ctx, 1, target, level, internalformat, x, y, width, 1, border);
}
void glCopyTexImage2D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLint x,
                      GLint y, GLsizei width, GLsizei height, GLint border) {
  copy_tex_image(ctx, 2, target, level, internalformat, x, y, width, height, border);
}

void glCopyTexSubImage1D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                         GLsizei width) {
  copy_tex_sub_image(ctx, 1, target, level, xoffset, 0, 0, x, y, width, 1);
}
void glCopyTexSubImage2D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                         GLint x, GLint y, GLsizei width, GLsizei height) {
  copy_tex_sub_image(ctx, 2, target, level, xoffset, yoffset, 0, x, y, width, height);
}
void glCopyTexSubImage3D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                         GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height) {
  copy_tex_sub_image(ctx, 3, target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

void glGetTexImage(Context& ctx, GLenum target, GLint level, GLenum format, GLenum type,
                   void* pixels) {
  get_tex_image(ctx, target, level, format, type, pixels);
}

void glCompressedTexImage1D(Context& ctx, GLenum target, GLint level, GLenum, GLsizei, GLint,
                            GLsizei, const void*) {
  compressed_tex_image(ctx, 1, target, level);
}
void glCompressedTexImage2D(Context& ctx, GLenum target, GLint level, GLenum, GLsizei, GLsizei,
                            GLint, GLsizei, const void*) {
  compressed_tex_image(ctx, 2, target, level);
}
void glCompressedTexImage3D(Context& ctx, GLenum target, GLint level, GLenum, GLsizei, GLsizei,
                            GLsizei, GLint, GLsizei, const void*) {
  compressed_tex_image(ctx, 3, target, level);
}
void glCompressedTexSubImage1D(Context& ctx, GLenum target, GLint level, GLint, GLsizei, GLenum,
                               GLsizei, const void*) {
  compressed_tex_sub_image(ctx, 1, target, level);
}
void glCompressedTexSubImage2D(Context& ctx, GLenum target, GLint level, GLint, GLint, GLsizei,
                               GLsizei, GLenum, GLsizei, const void*) {
  compressed_tex_sub_image(ctx, 2, target, level);
}
void glCompressedTexSubImage3D(Context& ctx, GLenum target, GLint level, GLint, GLint, GLint,
                               GLsizei, GLsizei, GLsizei, GLenum, GLsizei, const void*) {
  compressed_tex_sub_image(ctx, 3, target, level);
}

void glGetCompressedTexImage(Context& ctx, GLenum target, GLint level, void*) {
  const std::optional<ImageTarget> t = image_target(target, 0, ProxyTargets::kRejected);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  record_error(ctx, GL_INVALID_OPERATION);  // the image is not compressed (or not defined)
}

}  // namespace impl
}  // namespace glpt
