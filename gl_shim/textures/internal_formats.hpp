// Texture internal formats (GL 1.5 tables 3.15, 3.16, plus 1..4): their base format, and the
// component sizes Mesa 25 (llvmpipe) actually allocates for them, which glpt both reports through
// glGetTexLevelParameter and quantizes texels to, so that sampling sees Mesa's values.
#pragma once

#include <cstdint>

#include "gl_shim/gl_types.h"
#include "rt_core/record/texture.hpp"

namespace glpt {

struct InternalFormatInfo {
  // GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY, GL_RGB, GL_RGBA, GL_DEPTH_COMPONENT,
  // GL_DEPTH_STENCIL_EXT (EXT_packed_depth_stencil).
  GLenum base_format = 0;
  // Bits per component as Mesa chooses them (0: the base format has no such component).
  uint8_t red = 0, green = 0, blue = 0, alpha = 0, luminance = 0, intensity = 0, depth = 0;
  // What GL_TEXTURE_INTERNAL_FORMAT reports: the requested format, except the generic
  // compressed formats, which glpt (like Mesa for GL_COMPRESSED_ALPHA/INTENSITY) stores
  // uncompressed and reports as their base format.
  GLint reported = 0;
  uint8_t stencil = 0;  // GL_DEPTH_STENCIL_EXT: the stencil index's bits
  // EXT_texture_compression_s3tc formats: bytes per 4x4 block (0: not compressed). The component
  // sizes above are what Mesa reports for them (4 bits); the texels glpt samples are the blocks
  // decoded to 8 bits per channel (channel_bits).
  uint8_t block_bytes = 0;

  // GL_DEPTH_COMPONENT or GL_DEPTH_STENCIL_EXT: texels are depth values (the stencil indices of
  // depth-stencil images are kept beside them, rec::TextureImage::stencil).
  bool is_depth() const {
    return base_format == GL_DEPTH_COMPONENT || base_format == GL_DEPTH_STENCIL_EXT;
  }
  rec::TexelFormat texel_format() const;
  // Bits of the stored RGBA channels (luminance and intensity replicated into R, G, B (and A)).
  // 0 for channels the base format fills with a constant. Compressed formats: 8 (decoded texels).
  uint8_t channel_bits(int channel) const;
};

// Null when `internal_format` is not a GL 1.5 texture internal format.
const InternalFormatInfo* internal_format_info(GLint internal_format);

// The sized format Mesa 25 (llvmpipe) stores an image as: `internal_format` itself, except for
// the unsized GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_RGB and GL_RGBA given data whose
// type has another precision (measured: GL_RGBA from GL_RGBA/GL_UNSIGNED_SHORT is GL_RGBA16,
// GL_RGB from GL_UNSIGNED_SHORT_5_6_5 is 5-6-5, from GL_UNSIGNED_INT_10_10_10_2 GL_RGB10, ...).
GLint sized_format_for(GLint internal_format, GLenum format, GLenum type);

// The sizes of an image's texels: its sized format's (TextureImage::sized_format, or
// internal_format when that is 0). Includes the 5-6-5 format only Mesa's choice produces.
const InternalFormatInfo* stored_format_info(uint32_t internal_format, uint32_t sized_format);

}  // namespace glpt
