#include "gl_shim/textures/internal_formats.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>

#include "gl/gl_enums.h"

namespace glpt {
namespace {

struct Entry {
  GLint format;
  InternalFormatInfo info;
};

constexpr InternalFormatInfo A(uint8_t a) { return {GL_ALPHA, 0, 0, 0, a, 0, 0, 0, 0}; }
constexpr InternalFormatInfo L(uint8_t l) { return {GL_LUMINANCE, 0, 0, 0, 0, l, 0, 0, 0}; }
constexpr InternalFormatInfo LA(uint8_t l, uint8_t a) {
  return {GL_LUMINANCE_ALPHA, 0, 0, 0, a, l, 0, 0, 0};
}
constexpr InternalFormatInfo I(uint8_t i) { return {GL_INTENSITY, 0, 0, 0, 0, 0, i, 0, 0}; }
constexpr InternalFormatInfo RGB(uint8_t r, uint8_t g, uint8_t b) {
  return {GL_RGB, r, g, b, 0, 0, 0, 0, 0};
}
constexpr InternalFormatInfo RGBA(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
  return {GL_RGBA, r, g, b, a, 0, 0, 0, 0};
}
constexpr InternalFormatInfo D(uint8_t d) { return {GL_DEPTH_COMPONENT, 0, 0, 0, 0, 0, 0, d, 0}; }
// EXT_packed_depth_stencil: Mesa stores both GL_DEPTH_STENCIL_EXT and GL_DEPTH24_STENCIL8_EXT as
// Z24S8.
constexpr InternalFormatInfo DS() { return {GL_DEPTH_STENCIL_EXT, 0, 0, 0, 0, 0, 0, 24, 0, 8}; }
// An S3TC format: Mesa reports 4 bits per component it has.
constexpr InternalFormatInfo S3TC(GLenum base, uint8_t block_bytes) {
  InternalFormatInfo info = base == GL_RGB ? RGB(4, 4, 4) : RGBA(4, 4, 4, 4);
  info.block_bytes = block_bytes;
  return info;
}
// A generic compressed format stored uncompressed, reported as `base`.
constexpr InternalFormatInfo reported_as(InternalFormatInfo info, GLint base) {
  info.reported = base;
  return info;
}

// Sizes measured with Mesa 25.0.7 llvmpipe (OSMesa, glGetTexLevelParameteriv): Mesa rounds
// ALPHA4, LUMINANCE4, LUMINANCE6_ALPHA2 and INTENSITY4 up to 8 bits, 12-bit formats up to 16,
// RGBA2 up to 4444; it keeps R3_G3_B2, RGB4 (as 4444), RGB5, RGB10, RGB5_A1, RGB10_A2 and
// LUMINANCE4_ALPHA4 exact. Mesa compresses GL_COMPRESSED_RGB/RGBA with S3TC, and so does glpt
// (stored_internal_format in texture_image_commands.cpp: the entries below are for 1-D images,
// which Mesa keeps uncompressed), and GL_COMPRESSED_LUMINANCE/LUMINANCE_ALPHA with LATC, which
// glpt keeps uncompressed (GL allows it), reporting their base format.
constexpr Entry kEntries[] = {
    {1, L(8)},
    {2, LA(8, 8)},
    {3, RGB(8, 8, 8)},
    {4, RGBA(8, 8, 8, 8)},
    {GL_ALPHA, A(8)},
    {GL_LUMINANCE, L(8)},
    {GL_LUMINANCE_ALPHA, LA(8, 8)},
    {GL_INTENSITY, I(8)},
    {GL_RGB, RGB(8, 8, 8)},
    {GL_RGBA, RGBA(8, 8, 8, 8)},
    // Mesa accepts GL_BGRA as an internal format (programs pass it by mistake): RGBA8.
    {GL_BGRA, RGBA(8, 8, 8, 8)},
    {GL_ALPHA4, A(8)},
    {GL_ALPHA8, A(8)},
    {GL_ALPHA12, A(16)},
    {GL_ALPHA16, A(16)},
    {GL_LUMINANCE4, L(8)},
    {GL_LUMINANCE8, L(8)},
    {GL_LUMINANCE12, L(16)},
    {GL_LUMINANCE16, L(16)},
    {GL_LUMINANCE4_ALPHA4, LA(4, 4)},
    {GL_LUMINANCE6_ALPHA2, LA(8, 8)},
    {GL_LUMINANCE8_ALPHA8, LA(8, 8)},
    {GL_LUMINANCE12_ALPHA4, LA(16, 16)},
    {GL_LUMINANCE12_ALPHA12, LA(16, 16)},
    {GL_LUMINANCE16_ALPHA16, LA(16, 16)},
    {GL_INTENSITY4, I(8)},
    {GL_INTENSITY8, I(8)},
    {GL_INTENSITY12, I(16)},
    {GL_INTENSITY16, I(16)},
    {GL_R3_G3_B2, RGB(3, 3, 2)},
    {GL_RGB4, RGB(4, 4, 4)},
    {GL_RGB5, RGB(5, 5, 5)},
    {GL_RGB8, RGB(8, 8, 8)},
    {GL_RGB10, RGB(10, 10, 10)},
    {GL_RGB12, RGB(16, 16, 16)},
    {GL_RGB16, RGB(16, 16, 16)},
    {GL_RGBA2, RGBA(4, 4, 4, 4)},
    {GL_RGBA4, RGBA(4, 4, 4, 4)},
    {GL_RGB5_A1, RGBA(5, 5, 5, 1)},
    {GL_RGBA8, RGBA(8, 8, 8, 8)},
    {GL_RGB10_A2, RGBA(10, 10, 10, 2)},
    {GL_RGBA12, RGBA(16, 16, 16, 16)},
    {GL_RGBA16, RGBA(16, 16, 16, 16)},
    {GL_DEPTH_COMPONENT, D(24)},
    {GL_DEPTH_COMPONENT16, D(16)},
    {GL_DEPTH_COMPONENT24, D(24)},
    {GL_DEPTH_COMPONENT32, D(32)},
    {GL_DEPTH_STENCIL_EXT, DS()},
    {GL_DEPTH24_STENCIL8_EXT, DS()},
    {GL_COMPRESSED_ALPHA, reported_as(A(8), GL_ALPHA)},
    {GL_COMPRESSED_LUMINANCE, reported_as(L(8), GL_LUMINANCE)},
    {GL_COMPRESSED_LUMINANCE_ALPHA, reported_as(LA(8, 8), GL_LUMINANCE_ALPHA)},
    {GL_COMPRESSED_INTENSITY, reported_as(I(8), GL_INTENSITY)},
    {GL_COMPRESSED_RGB, reported_as(RGB(8, 8, 8), GL_RGB)},
    {GL_COMPRESSED_RGBA, reported_as(RGBA(8, 8, 8, 8), GL_RGBA)},
    {GL_COMPRESSED_RGB_S3TC_DXT1_EXT, S3TC(GL_RGB, 8)},
    {GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, S3TC(GL_RGBA, 8)},
    {GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, S3TC(GL_RGBA, 16)},
    {GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, S3TC(GL_RGBA, 16)},
};

constexpr auto kSorted = [] {
  std::array<Entry, std::size(kEntries)> sorted{};
  std::copy(std::begin(kEntries), std::end(kEntries), sorted.begin());
  std::sort(sorted.begin(), sorted.end(),
            [](const Entry& a, const Entry& b) { return a.format < b.format; });
  for (Entry& e : sorted) {
    if (e.info.reported == 0) e.info.reported = e.format;
  }
  return sorted;
}();

// GL_RGB565 (GL 4.1): not a GL 1.5 internal format, but what Mesa stores GL_RGB as when it is
// given GL_UNSIGNED_SHORT_5_6_5 data.
constexpr GLint kRgb565 = 0x8D62;
constexpr InternalFormatInfo kRgb565Info = {GL_RGB, 5, 6, 5, 0, 0, 0, 0, GL_RGB};

bool is_any(GLenum v, std::initializer_list<GLenum> set) {
  return std::find(set.begin(), set.end(), v) != set.end();
}

}  // namespace

GLint sized_format_for(GLint internal_format, GLenum format, GLenum type) {
  const bool rgba_or_bgra = format == GL_RGBA || format == GL_BGRA;
  switch (internal_format) {
    case GL_ALPHA:
      return format == GL_ALPHA && type == GL_UNSIGNED_SHORT ? GL_ALPHA16 : internal_format;
    case GL_LUMINANCE:
      return format == GL_LUMINANCE && type == GL_UNSIGNED_SHORT ? GL_LUMINANCE16 : internal_format;
    case GL_LUMINANCE_ALPHA:
      return format == GL_LUMINANCE_ALPHA && type == GL_UNSIGNED_SHORT ? GL_LUMINANCE16_ALPHA16
                                                                       : internal_format;
    case GL_RGB:
      if (format == GL_RGB && is_any(type, {GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_BYTE_2_3_3_REV}))
        return GL_R3_G3_B2;
      if (format == GL_RGB && is_any(type, {GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_SHORT_5_6_5_REV}))
        return kRgb565;
      if (rgba_or_bgra && type == GL_UNSIGNED_SHORT_5_5_5_1) return GL_RGB5;
      if (rgba_or_bgra &&
          is_any(type, {GL_UNSIGNED_INT_10_10_10_2, GL_UNSIGNED_INT_2_10_10_10_REV}))
        return GL_RGB10;
      return internal_format;
    case GL_RGBA:
      if (format == GL_RGBA && type == GL_UNSIGNED_SHORT) return GL_RGBA16;
      if ((rgba_or_bgra || format == GL_ABGR_EXT) &&
          is_any(type, {GL_UNSIGNED_SHORT_4_4_4_4, GL_UNSIGNED_SHORT_4_4_4_4_REV}))
        return GL_RGBA4;
      if (rgba_or_bgra && is_any(type, {GL_UNSIGNED_SHORT_5_5_5_1, GL_UNSIGNED_SHORT_1_5_5_5_REV}))
        return GL_RGB5_A1;
      if (rgba_or_bgra &&
          is_any(type, {GL_UNSIGNED_INT_10_10_10_2, GL_UNSIGNED_INT_2_10_10_10_REV}))
        return GL_RGB10_A2;
      return internal_format;
    default:
      return internal_format;
  }
}

const InternalFormatInfo* stored_format_info(uint32_t internal_format, uint32_t sized_format) {
  const GLint f = GLint(sized_format != 0 ? sized_format : internal_format);
  return f == kRgb565 ? &kRgb565Info : internal_format_info(f);
}

const InternalFormatInfo* internal_format_info(GLint internal_format) {
  const auto it = std::lower_bound(kSorted.begin(), kSorted.end(), internal_format,
                                   [](const Entry& e, GLint f) { return e.format < f; });
  return it != kSorted.end() && it->format == internal_format ? &it->info : nullptr;
}

rec::TexelFormat InternalFormatInfo::texel_format() const {
  if (is_depth()) return rec::TexelFormat::kDepth32f;
  const uint8_t widest = std::max({red, green, blue, alpha, luminance, intensity});
  return widest > 8 ? rec::TexelFormat::kRgba16 : rec::TexelFormat::kRgba8;
}

uint8_t InternalFormatInfo::channel_bits(int channel) const {
  if (block_bytes != 0) {
    const uint8_t bits[4] = {red, green, blue, alpha};
    return bits[channel] != 0 ? 8 : 0;
  }
  switch (base_format) {
    case GL_LUMINANCE:
      return channel < 3 ? luminance : 0;
    case GL_LUMINANCE_ALPHA:
      return channel < 3 ? luminance : alpha;
    case GL_INTENSITY:
      return intensity;
    case GL_ALPHA:
      return channel == 3 ? alpha : 0;
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_STENCIL_EXT:
      return channel == 0 ? depth : 0;
    default: {
      const uint8_t bits[4] = {red, green, blue, alpha};
      return bits[channel];
    }
  }
}

}  // namespace glpt
