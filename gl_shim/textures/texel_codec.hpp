// Texels as glpt stores them (rec::TexelFormat): conversion of colours to an internal format's
// base format (GL 1.5 3.8.1, table 3.15), quantization to the component sizes Mesa allocates,
// and the reverse for glGetTexImage and mipmap generation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_unpack.hpp"
#include "gl_shim/textures/internal_formats.hpp"

namespace glpt {

// Stores `count` colours (RGBA, as unpacked from the client or after pixel transfer) as texels
// of `info`. Base format conversion takes L and I from R; channels the base format lacks hold GL's
// constants (rec::TexelFormat's layout: L -> (L,L,L,1), A -> (0,0,0,A), I -> (I,I,I,I), ...).
// Each channel gets Mesa's size for it and the value Mesa's format conversion gives it from the
// client's components (`source`): integers converted with integer arithmetic (bit replication
// when widening, rounding when narrowing), through a byte or float intermediate where Mesa takes
// one, floats rounded to nearest even. The stored value is that widened to 8 or 16 bits by bit
// replication, as Mesa widens narrower formats when it reads them.
// `integers` (may be null when `source` has only floats): the client's integer components
// (unpack_color_integers), which the integer conversions use.
void encode_color_texels(const InternalFormatInfo& info, const glm::vec4* rgba, size_t count,
                         uint8_t* texels,
                         const ColorSourceLayout& source = ColorSourceLayout::floats(),
                         const glm::uvec4* integers = nullptr);

// The common case without float conversion: GL_UNSIGNED_BYTE colour data into a format whose
// channels all have 8 bits, without pixel transfer (the caller checks that), where the client's
// bytes are the texels. Returns false (nothing written) when the case does not apply.
bool encode_byte_texels(const InternalFormatInfo& info, const UnpackSource& src, uint8_t* texels);

// Stores depth values in [0, 1] (kDepth32f) quantized to the format's depth bits z (as the float
// z / (2^bits - 1), what glGetTexImage returns). kTruncate: as Mesa's _mesa_unpack_depth_span
// converts client data (z = the truncated product of d and 2^bits - 1, in float for up to 24
// bits); kNearest: the nearest z (copies from the depth buffer, which Mesa blits exactly).
enum class DepthRounding : uint8_t { kTruncate, kNearest };
void encode_depth_texels(const InternalFormatInfo& info, const float* depth, size_t count,
                         uint8_t* texels, DepthRounding rounding = DepthRounding::kNearest);
// Stores the depth value z of the format's bits (an integer Mesa keeps without conversion).
void encode_depth_unorm_texel(const InternalFormatInfo& info, uint32_t z, uint8_t* texel);

// One texel as glGetTexImage sees it: the base format's components placed as GL 1.5 table 6.1 /
// Mesa do: L -> (L,0,0,1), I -> (I,0,0,1), LA -> (L,0,0,A), A -> (0,0,0,A), RGB -> (R,G,B,1),
// RGBA -> (R,G,B,A). kExact: the value of the component size Mesa stores (q / (2^b - 1));
// kStored: the 8- or 16-bit value glpt stores, which is what Mesa's integer conversion gives for
// destinations of that width (a 5-bit 7 read as a byte is 57, not round(7 * 255 / 31) = 58).
enum class TexelValue : uint8_t { kExact, kStored };
glm::vec4 decode_color_texel(const InternalFormatInfo& info, const uint8_t* texel,
                             TexelValue value = TexelValue::kExact);
float decode_depth_texel(const uint8_t* texel);

// Storage channel value (8 or 16 bits) <-> the quantized value of `bits` bits it represents.
uint32_t widen_to_storage(uint32_t value, uint32_t bits, uint32_t storage_bits);
uint32_t narrow_from_storage(uint32_t stored, uint32_t bits, uint32_t storage_bits);

}  // namespace glpt
