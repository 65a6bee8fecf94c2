// Client memory -> values (GL 1.5 3.6.4 "Unpacking" and "Conversion to floating-point", then
// 3.6.5 pixel transfer): what glTexImage*, glTexSubImage*, glDrawPixels, glBitmap and
// glPolygonStipple read. Every function takes the unpack modes and transfer state explicitly, so
// each step can be used and tested on its own.
//
// Values come out in group order: x fastest, then y (rows bottom to top as GL numbers them), then
// z. The format/type pair must have passed check_format_and_type, and the image must have at most
// kMaxPixelGroups groups and a valid ClientImageLayout (the callers report the GL errors).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl_shim/pixels/pixel_layout.hpp"
#include "gl_shim/state/framebuffer_state.hpp"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

struct UnpackSource {
  const PixelStoreModes& modes;
  ImageShape shape;
  bool three_d = false;  // IMAGE_HEIGHT / SKIP_IMAGES apply
  const void* data = nullptr;
};

// ---- raw values (before pixel transfer) --------------------------------------------------------

// Colour formats: RGBA floats. Unsigned integers become c / (2^b - 1), signed ones
// max(c / (2^(b-1) - 1), -1) (Mesa's rule; GL 1.5 table 2.9's (2c+1)/(2^b-1) is not what Mesa
// does), packed fields c / (2^bits - 1). Missing R, G, B are 0, missing A is 1, luminance goes to
// R, G and B (GL 1.5 3.6.4 "Conversion to RGB").
std::vector<glm::vec4> unpack_color_raw(const UnpackSource& src);

// Colour formats: each component as the integer the client stored (unsigned elements and
// packed fields as they are, signed elements sign-extended to 32 bits), luminance in R, G and B,
// 0 for components the format lacks and for float elements. For conversions that, like Mesa's,
// work on the integers themselves.
std::vector<glm::uvec4> unpack_color_integers(const UnpackSource& src);

// COLOR_INDEX and STENCIL_INDEX: integer indices. Float elements are truncated and signed ones
// taken modulo 2^32, as Mesa extracts them; GL_BITMAP groups are 0 or 1.
std::vector<uint32_t> unpack_indices_raw(const UnpackSource& src);

// DEPTH_COMPONENT: floats, integer types normalized as for colours. DEPTH_STENCIL
// (GL_UNSIGNED_INT_24_8_EXT): the depth bits d as the float d * (1.0f / 0xFFFFFF) (Mesa), while
// unpack_indices_raw gives its stencil bits; unpack_depth_stencil_words gives the words themselves.
std::vector<float> unpack_depth_raw(const UnpackSource& src);
std::vector<uint32_t> unpack_depth_stencil_words(const UnpackSource& src);

// ---- through pixel transfer ----------------------------------------------------------------

// Colour formats and COLOR_INDEX (GL_BITMAP included) to RGBA in [0, 1]: colours through
// scale/bias and the colour maps; indices through shift/offset and the I_TO_R/G/B/A maps
// (without RGBA scale/bias, as Mesa does).
std::vector<glm::vec4> unpack_color(const UnpackSource& src,
                                    const rec::PixelTransferState& transfer);

// DEPTH_COMPONENT through DEPTH_SCALE/BIAS, clamped to [0, 1].
std::vector<float> unpack_depth(const UnpackSource& src, const rec::PixelTransferState& transfer);

// STENCIL_INDEX through INDEX_SHIFT/OFFSET and, with MAP_STENCIL, the S_TO_S map.
std::vector<uint32_t> unpack_stencil(const UnpackSource& src,
                                     const rec::PixelTransferState& transfer);

// A bitmap (glBitmap, glPolygonStipple): width * height bytes, 1 where the bit is set.
std::vector<uint8_t> unpack_bitmap(const PixelStoreModes& modes, int32_t width, int32_t height,
                                   const void* data);

}  // namespace glpt
