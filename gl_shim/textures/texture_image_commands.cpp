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
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_pack.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/pixels/pixel_unpack.hpp"
#include "gl_shim/state/out_of_memory.hpp"
#include "gl_shim/textures/internal_formats.hpp"
#include "gl_shim/textures/mipmap_generation.hpp"
#include "gl_shim/textures/s3tc.hpp"
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

// Mesa's _mesa_target_can_be_compressed for S3TC: 2-D images, cube faces and (Mesa 25 allows
// it) 3-D images of 2-D block slices; no 1-D or rectangle images.
bool s3tc_target(const ImageTarget& t) {
  return t.slot == kSlot2D || t.slot == kSlotCube || t.slot == kSlot3D;
}

// EXT_texture_compression_s3tc: sub-images of compressed images start on block edges and cover
// whole blocks, except where they reach the image's right or top edge (GL_INVALID_OPERATION).
bool block_aligned(const rec::TextureImage& img, GLint xoff, GLint yoff, GLsizei w, GLsizei h) {
  const auto fits = [](GLint off, GLsizei size, uint32_t extent) {
    return off % 4 == 0 && (size % 4 == 0 || int64_t(off) + size == int64_t(extent));
  };
  return fits(xoff, w, img.width) && fits(yoff, h, img.height);
}

// The texels sampled from an S3TC image: its blocks decoded.
void decode_compressed(rec::TextureImage& img) {
  const GLenum f = GLenum(img.internal_format);
  img.texels.assign(size_t(img.width) * img.height * img.depth * 4, 0);
  s3tc::decode_image(f, img.compressed.data(), img.width, img.height, img.depth, img.texels.data());
}

// Mesa compresses the uncompressed texels given to an S3TC image (glTexImage, glTexSubImage,
// glCopyTex*): the blocks covering x0..x1 x y0..y1 x z0..z1 (interior texel coordinates) are
// encoded anew from `img.texels`, the others keep their bytes, and the texels are decoded again.
void compress_region(rec::TextureImage& img, int64_t x0, int64_t y0, int64_t z0, int64_t x1,
                     int64_t y1, int64_t z1) {
  const GLenum f = GLenum(img.internal_format);
  img.compressed.resize(s3tc::image_bytes(f, img.width, img.height, img.depth), 0);
  x0 = std::max<int64_t>(x0, 0) / 4 * 4, y0 = std::max<int64_t>(y0, 0) / 4 * 4;
  x1 = std::min<int64_t>(x1, img.width), y1 = std::min<int64_t>(y1, img.height);
  z0 = std::max<int64_t>(z0, 0), z1 = std::min<int64_t>(z1, img.depth);
  if (x1 > x0 && y1 > y0) {
    const uint32_t bytes = s3tc::block_bytes(f), across = (img.width + 3) / 4,
                   up = (img.height + 3) / 4;
    for (int64_t z = z0; z < z1; ++z) {
      for (int64_t by = y0; by < y1; by += 4) {
        for (int64_t bx = x0; bx < x1; bx += 4) {
          // One block: its texels (as many as lie inside the image) encoded on their own.
          const uint32_t bw = uint32_t(std::min<int64_t>(4, img.width - bx)),
                         bh = uint32_t(std::min<int64_t>(4, img.height - by));
          uint8_t tile[4 * 4 * 4] = {};
          for (uint32_t j = 0; j < bh; ++j)
            std::memcpy(
                tile + j * bw * 4,
                img.texels.data() +
                    ((size_t(z) * img.height + size_t(by) + j) * img.width + size_t(bx)) * 4,
                size_t(bw) * 4);
          s3tc::encode_image(
              f, tile, bw, bh, 1,
              img.compressed.data() +
                  ((size_t(z) * up + size_t(by / 4)) * across + size_t(bx / 4)) * bytes);
        }
      }
    }
  }
  decode_compressed(img);
}

// The format an image of a requested internal format is stored in. Mesa 25.0.7 (llvmpipe,
// st_ChooseTextureFormat) compresses the generic GL_COMPRESSED_RGB and GL_COMPRESSED_RGBA as
// DXT1 and DXT5 on every target but 1-D (there it keeps them uncompressed): the image reports
// the S3TC format, its texels are what Mesa's encoder leaves of the data (lossy), and it takes
// compressed sub-images and reads like any S3TC image (measured with OSMesa: 2-D, cube, 3-D and
// rectangle images, glCopyTexImage2D, proxies and images with a border). The generic luminance
// formats (LATC in Mesa) stay uncompressed here.
GLint stored_internal_format(GLint requested, const ImageTarget& t) {
  if (t.slot == kSlot1D) return requested;
  if (requested == GL_COMPRESSED_RGB) return GL_COMPRESSED_RGB_S3TC_DXT1_EXT;
  if (requested == GL_COMPRESSED_RGBA) return GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
  return requested;
}

void tex_image(Context& ctx, int dims, GLenum target, GLint level, GLint internal_format, GLsizei w,
               GLsizei h, GLsizei d, GLint border, GLenum format, GLenum type, const void* pixels) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  sync_framebuffer_textures(ctx);
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kAccepted);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  if (!legal_border(*t, border) || w < 0 || h < 0 || d < 0)
    return record_error(ctx, GL_INVALID_VALUE);
  if (internal_format_info(internal_format) == nullptr) return record_error(ctx, GL_INVALID_VALUE);
  if (const GLenum e = check_format_and_type(format, type); e != GL_NO_ERROR)
    return record_error(ctx, e);
  GLint sized = sized_format_for(internal_format, format, type);
  const InternalFormatInfo* info = stored_format_info(uint32_t(internal_format), uint32_t(sized));
  if (info->block_bytes != 0 && !s3tc_target(*t)) return record_error(ctx, GL_INVALID_ENUM);
  if (info->block_bytes != 0 && border != 0) return record_error(ctx, GL_INVALID_OPERATION);
  if (!formats_agree(*info, format)) return record_error(ctx, GL_INVALID_OPERATION);
  // Mesa's _mesa_legal_texture_base_format_for_target: no three-dimensional depth textures.
  if (info->is_depth() && t->slot == kSlot3D) return record_error(ctx, GL_INVALID_OPERATION);
  if (const GLint stored = stored_internal_format(internal_format, *t); stored != internal_format) {
    internal_format = sized = stored;  // validated as requested, stored (and reported) compressed
    info = internal_format_info(stored);
  }
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
    if (info->block_bytes != 0) compress_region(*img, 0, 0, 0, img->width, img->height, img->depth);
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
  sync_framebuffer_textures(ctx);
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
  if (info->block_bytes != 0 && !block_aligned(*img, xoff, yoff, w, h))
    return record_error(ctx, GL_INVALID_OPERATION);
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
    if (info->block_bytes != 0)
      compress_region(*object.image_for_update(t->face, level), xoff, yoff, zoff, int64_t(xoff) + w,
                      int64_t(yoff) + h, int64_t(zoff) + d);
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
  const ReadFramebufferScope read(ctx);
  sync_framebuffer_textures(ctx);
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kRejected);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  if (const GLenum e = framebuffer_error(ctx); e != GL_NO_ERROR) return record_error(ctx, e);
  if (!legal_border(*t, border) || w < 0 || h < 0) return record_error(ctx, GL_INVALID_VALUE);
  // GL 1.5 3.8.2: not 1..4. Mesa reports a bad internal format here as GL_INVALID_ENUM.
  const InternalFormatInfo* info = internal_format_info(GLint(internal_format));
  if (info == nullptr || internal_format <= 4) return record_error(ctx, GL_INVALID_ENUM);
  if (info->block_bytes != 0 && !s3tc_target(*t)) return record_error(ctx, GL_INVALID_ENUM);
  if (info->block_bytes != 0 && border != 0) return record_error(ctx, GL_INVALID_OPERATION);
  if (!legal_dimensions(*t, level, w, h, 1, border)) return record_error(ctx, GL_INVALID_VALUE);
  if (!framebuffer_has_source(ctx, *info))
    return record_error(ctx, GL_INVALID_OPERATION);  // nothing to copy depth (stencil) from
  if (const GLint stored = stored_internal_format(GLint(internal_format), *t);
      stored != GLint(internal_format)) {
    internal_format = GLenum(stored);
    info = internal_format_info(stored);
  }
  TextureObject& object = target_object(ctx, *t);
  or_out_of_memory(ctx, [&] {
    std::shared_ptr<rec::TextureImage> img = new_image(*t, GLint(internal_format), w, h, 1, border);
    // The border texels are read from the framebuffer's edge of the rectangle and dropped.
    ImageContents contents =
        texels_from_framebuffer(ctx, *info, x + border, dims >= 2 ? y + border : y,
                                GLsizei(img->width), GLsizei(img->height));
    img->texels = std::move(contents.texels);
    img->stencil = std::move(contents.stencil);
    if (info->block_bytes != 0) compress_region(*img, 0, 0, 0, img->width, img->height, 1);
    object.set_image(t->face, level, std::move(img));
    image_changed(object, *t, level);
  });
}

void copy_tex_sub_image(Context& ctx, int dims, GLenum target, GLint level, GLint xoff, GLint yoff,
                        GLint zoff, GLint x, GLint y, GLsizei w, GLsizei h) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  const ReadFramebufferScope read(ctx);
  sync_framebuffer_textures(ctx);
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kRejected);
  if (!valid_sub_image_args(ctx, t, level, w, h, 1)) return;
  if (const GLenum e = framebuffer_error(ctx); e != GL_NO_ERROR) return record_error(ctx, e);
  const rec::TextureImage* img = target_object(ctx, *t).image(t->face, level);
  if (img == nullptr) return record_error(ctx, GL_INVALID_OPERATION);  // undefined image
  if (!region_fits(*img, dims, xoff, yoff, zoff, w, dims >= 2 ? h : 1, 1))
    return record_error(ctx, GL_INVALID_VALUE);
  const InternalFormatInfo* info = stored_format_info(img->internal_format, img->sized_format);
  if (info == nullptr) return;
  if (!framebuffer_has_source(ctx, *info)) return record_error(ctx, GL_INVALID_OPERATION);
  if (info->block_bytes != 0 && !block_aligned(*img, xoff, yoff, w, h))
    return record_error(ctx, GL_INVALID_OPERATION);
  if (w == 0 || h == 0) return;
  TextureObject& object = target_object(ctx, *t);
  or_out_of_memory(ctx, [&] {
    const ImageContents contents = texels_from_framebuffer(ctx, *info, x, y, w, h);
    write_region(object, *t, level, xoff, yoff, zoff, w, h, 1, contents,
                 rec::texel_bytes(info->texel_format()));
    if (info->block_bytes != 0)
      compress_region(*object.image_for_update(t->face, level), xoff, yoff, zoff, int64_t(xoff) + w,
                      int64_t(yoff) + h, int64_t(zoff) + 1);
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
  sync_framebuffer_textures(ctx);
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

// Mesa's generic compressed formats (GL_COMPRESSED_ALPHA .. GL_COMPRESSED_RGBA): glTexImage
// accepts them, the glCompressedTex* commands do not (GL_INVALID_ENUM, ARB_texture_compression).
bool generic_compressed(GLenum f) { return f >= GL_COMPRESSED_ALPHA && f <= GL_COMPRESSED_RGBA; }

// glCompressedTexImage1D/2D/3D (ARB_texture_compression, EXT_texture_compression_s3tc): the
// blocks are kept as given and decoded for sampling. Errors in Mesa's order (measured with
// OSMesa 25.0.7: compressed_texture_error_check).
void compressed_tex_image(Context& ctx, int dims, GLenum target, GLint level, GLenum format,
                          GLsizei w, GLsizei h, GLsizei d, GLint border, GLsizei image_size,
                          const void* data) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  sync_framebuffer_textures(ctx);
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kAccepted);
  if (!t || !s3tc_target(*t) || !s3tc::is_s3tc(format)) return record_error(ctx, GL_INVALID_ENUM);
  if (border != 0) return record_error(ctx, GL_INVALID_OPERATION);  // no format has borders
  if (w < 0 || h < 0 || d < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  if (dims < 3) d = 1;
  if (!legal_dimensions(*t, level, w, h, d, 0)) return record_error(ctx, GL_INVALID_VALUE);
  if (image_size < 0 ||
      size_t(image_size) != s3tc::image_bytes(format, uint32_t(w), uint32_t(h), uint32_t(d)))
    return record_error(ctx, GL_INVALID_VALUE);  // "not consistent with the format" (ARB)
  TextureObject& object = target_object(ctx, *t);
  or_out_of_memory(ctx, [&] {
    std::shared_ptr<rec::TextureImage> img = new_image(*t, GLint(format), w, h, d, 0);
    if (!t->proxy) {
      // Null data: defined contents are undefined (zero blocks decode to black).
      img->compressed.assign(size_t(image_size), 0);
      if (data != nullptr && image_size > 0)
        std::memcpy(img->compressed.data(), data, size_t(image_size));
      decode_compressed(*img);
    }
    object.set_image(t->face, level, std::move(img));
    if (!t->proxy) image_changed(object, *t, level);
  });
}

// glCompressedTexSubImage1D/2D/3D: whole blocks replaced in an image of the same format.
void compressed_tex_sub_image(Context& ctx, int dims, GLenum target, GLint level, GLint xoff,
                              GLint yoff, GLint zoff, GLsizei w, GLsizei h, GLsizei d,
                              GLenum format, GLsizei image_size, const void* data) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  sync_framebuffer_textures(ctx);
  const std::optional<ImageTarget> t = image_target(target, dims, ProxyTargets::kRejected);
  if (!t || !s3tc_target(*t)) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  if (generic_compressed(format)) return record_error(ctx, GL_INVALID_ENUM);
  const rec::TextureImage* img = target_object(ctx, *t).image(t->face, level);
  // No image, or one of another format (uncompressed ones included): GL_INVALID_OPERATION.
  if (img == nullptr || img->internal_format != format || !s3tc::is_s3tc(format))
    return record_error(ctx, GL_INVALID_OPERATION);
  if (dims < 3) zoff = 0, d = 1;
  if (dims < 2) yoff = 0, h = 1;
  if (w < 0 || h < 0 || d < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (!region_fits(*img, dims, xoff, yoff, zoff, w, h, d))
    return record_error(ctx, GL_INVALID_VALUE);
  if (!block_aligned(*img, xoff, yoff, w, h)) return record_error(ctx, GL_INVALID_OPERATION);
  if (image_size < 0 ||
      size_t(image_size) != s3tc::image_bytes(format, uint32_t(w), uint32_t(h), uint32_t(d)))
    return record_error(ctx, GL_INVALID_VALUE);
  if (w == 0 || h == 0 || d == 0 || data == nullptr) return;
  TextureObject& object = target_object(ctx, *t);
  or_out_of_memory(ctx, [&] {
    rec::TextureImage* target_img = object.image_for_update(t->face, level);
    const uint32_t bytes = s3tc::block_bytes(format), across = (target_img->width + 3) / 4,
                   up = (target_img->height + 3) / 4;
    const uint32_t src_across = (uint32_t(w) + 3) / 4, src_up = (uint32_t(h) + 3) / 4;
    const auto* src = static_cast<const uint8_t*>(data);
    for (uint32_t z = 0; z < uint32_t(d); ++z) {
      for (uint32_t by = 0; by < src_up; ++by) {
        const size_t to =
            ((size_t(zoff) + z) * up + size_t(yoff / 4) + by) * across + size_t(xoff / 4);
        std::memcpy(target_img->compressed.data() + to * bytes,
                    src + ((size_t(z) * src_up + by) * src_across) * bytes,
                    size_t(src_across) * bytes);
      }
    }
    decode_compressed(*target_img);
    image_changed(object, *t, level);
  });
}

// glGetCompressedTexImage: the blocks byte for byte (GL 1.x has no compressed pack state).
void get_compressed_tex_image(Context& ctx, GLenum target, GLint level, void* pixels) {
  flush_bitmap_cache(ctx);  // as Mesa's texture uploads and reads
  sync_framebuffer_textures(ctx);
  const std::optional<ImageTarget> t = image_target(target, 0, ProxyTargets::kRejected);
  if (!t) return record_error(ctx, GL_INVALID_ENUM);
  if (level < 0 || level >= max_texture_levels(t->slot)) return record_error(ctx, GL_INVALID_VALUE);
  const rec::TextureImage* img = target_object(ctx, *t).image(t->face, level);
  if (img == nullptr) return record_error(ctx, GL_INVALID_VALUE);  // Mesa: no image to read
  if (!s3tc::is_s3tc(img->internal_format)) return record_error(ctx, GL_INVALID_OPERATION);
  if (pixels != nullptr && !img->compressed.empty())
    std::memcpy(pixels, img->compressed.data(), img->compressed.size());
}

}  // namespace

void write_back_framebuffer_image(Context& ctx, TextureObject& object, GLenum texture_target,
                                  int level, int zoffset, uint32_t width, uint32_t height,
                                  bool depth) {
  const std::optional<ImageTarget> t = image_target(texture_target, 0, ProxyTargets::kRejected);
  const rec::TextureImage* img = t ? object.image(t->face, level) : nullptr;
  if (img == nullptr) return;
  const InternalFormatInfo* info = stored_format_info(img->internal_format, img->sized_format);
  if (info == nullptr || info->block_bytes != 0 || info->is_depth() != depth) return;
  const uint32_t w = std::min(width, img->width), h = std::min(height, img->height);
  const size_t n = size_t{w} * h;
  if (n == 0) return;
  FramebufferPixels fb;
  if (!read_framebuffer(ctx, depth ? rec::PixelKind::kDepth : rec::PixelKind::kColor, GL_FRONT, 0,
                        0, w, h, fb))
    return;
  ImageContents contents;
  contents.texels.assign(n * rec::texel_bytes(info->texel_format()), 0);
  if (depth && fb.depth.size() == n)
    encode_depth_texels(*info, fb.depth.data(), n, contents.texels.data());
  else if (!depth && fb.color.size() == n)
    encode_color_texels(*info, fb.color.data(), n, contents.texels.data());
  else
    return;
  write_region(object, *t, level, 0, 0, zoffset, GLsizei(w), GLsizei(h), 1, contents,
               rec::texel_bytes(info->texel_format()));
  image_changed(object, *t, level);
}

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

void glCompressedTexImage1D(Context& ctx, GLenum target, GLint level, GLenum internalformat,
                            GLsizei width, GLint border, GLsizei imageSize, const void* data) {
  compressed_tex_image(ctx, 1, target, level, internalformat, width, 1, 1, border, imageSize, data);
}
void glCompressedTexImage2D(Context& ctx, GLenum target, GLint level, GLenum internalformat,
                            GLsizei width, GLsizei height, GLint border, GLsizei imageSize,
                            const void* data) {
  compressed_tex_image(ctx, 2, target, level, internalformat, width, height, 1, border, imageSize,
                       data);
}
void glCompressedTexImage3D(Context& ctx, GLenum target, GLint level, GLenum internalformat,
                            GLsizei width, GLsizei height, GLsizei depth, GLint border,
                            GLsizei imageSize, const void* data) {
  compressed_tex_image(ctx, 3, target, level, internalformat, width, height, depth, border,
                       imageSize, data);
}
void glCompressedTexSubImage1D(Context& ctx, GLenum target, GLint level, GLint xoffset,
                               GLsizei width, GLenum format, GLsizei imageSize, const void* data) {
  compressed_tex_sub_image(ctx, 1, target, level, xoffset, 0, 0, width, 1, 1, format, imageSize,
                           data);
}
void glCompressedTexSubImage2D(Context& ctx, GLenum target, GLint level, GLint xoffset,
                               GLint yoffset, GLsizei width, GLsizei height, GLenum format,
                               GLsizei imageSize, const void* data) {
  compressed_tex_sub_image(ctx, 2, target, level, xoffset, yoffset, 0, width, height, 1, format,
                           imageSize, data);
}
void glCompressedTexSubImage3D(Context& ctx, GLenum target, GLint level, GLint xoffset,
                               GLint yoffset, GLint zoffset, GLsizei width, GLsizei height,
                               GLsizei depth, GLenum format, GLsizei imageSize, const void* data) {
  compressed_tex_sub_image(ctx, 3, target, level, xoffset, yoffset, zoffset, width, height, depth,
                           format, imageSize, data);
}

void glGetCompressedTexImage(Context& ctx, GLenum target, GLint level, void* img) {
  get_compressed_tex_image(ctx, target, level, img);
}

}  // namespace impl
}  // namespace glpt
