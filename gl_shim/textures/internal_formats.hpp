// Texture internal formats (GL 1.5 tables 3.15, 3.16, plus 1..4): their base format, and the
// component sizes Mesa 25 (llvmpipe) actually allocates for them, which glpt both reports through
// glGetTexLevelParameter and quantizes texels to, so that sampling sees Mesa's values.
#pragma once

#include <cstdint>

#include "gl_shim/gl_types.h"
#include "rt_core/record/texture.hpp"

namespace glpt {

struct InternalFormatInfo {
  // GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY, GL_RGB, GL_RGBA, GL_DEPTH_COMPONENT.
  GLenum base_format = 0;
  // Bits per component as Mesa chooses them (0: the base format has no such component).
  uint8_t red = 0, green = 0, blue = 0, alpha = 0, luminance = 0, intensity = 0, depth = 0;
  // What GL_TEXTURE_INTERNAL_FORMAT reports: the requested format, except the generic
  // compressed formats, which glpt (like Mesa for GL_COMPRESSED_ALPHA/INTENSITY) stores
  // uncompressed and reports as their base format.
  GLint reported = 0;

  rec::TexelFormat texel_format() const;
  // Bits of the stored RGBA channels (luminance and intensity replicated into R, G, B (and A)).
  // 0 for channels the base format fills with a constant.
  uint8_t channel_bits(int channel) const;
};

// Null when `internal_format` is not a GL 1.5 texture internal format.
const InternalFormatInfo* internal_format_info(GLint internal_format);

}  // namespace glpt
