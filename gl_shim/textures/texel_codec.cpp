#include "gl_shim/textures/texel_codec.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/gl_enums.h"

namespace glpt {
namespace {

uint32_t max_of(uint32_t bits) { return bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1u; }

// Mesa's _mesa_float_to_unorm: nearest even of c * (2^b - 1) in float.
uint32_t quantize(float c, uint32_t bits) {
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return max_of(bits);
  return uint32_t(std::lrint(c * float(max_of(bits))));
}

// The colour a texel's channel takes before quantization (rec::TexelFormat's layout).
glm::vec4 to_base_format(GLenum base, const glm::vec4& c) {
  switch (base) {
    case GL_ALPHA:
      return {0.0f, 0.0f, 0.0f, c.a};
    case GL_LUMINANCE:
      return {c.r, c.r, c.r, 1.0f};
    case GL_LUMINANCE_ALPHA:
      return {c.r, c.r, c.r, c.a};
    case GL_INTENSITY:
      return {c.r, c.r, c.r, c.r};
    case GL_RGB:
      return {c.r, c.g, c.b, 1.0f};
    default:
      return c;
  }
}

}  // namespace

uint32_t bytes_per_texel(rec::TexelFormat format) {
  switch (format) {
    case rec::TexelFormat::kRgba8:
    case rec::TexelFormat::kDepth32f:
      return 4;
    case rec::TexelFormat::kRgba16:
      return 8;
    case rec::TexelFormat::kRgba32f:
      return 16;
  }
  return 4;
}

uint32_t widen_to_storage(uint32_t value, uint32_t bits, uint32_t storage_bits) {
  if (bits == 0 || bits >= storage_bits) return value;
  // Mesa's EXTEND_NORMALIZED_INT: bit replication.
  const uint32_t factor = max_of(storage_bits) / max_of(bits);
  const uint32_t rest = storage_bits % bits;
  return value * factor + (rest != 0 ? value >> (bits - rest) : 0);
}

uint32_t narrow_from_storage(uint32_t stored, uint32_t bits, uint32_t storage_bits) {
  if (bits == 0 || bits >= storage_bits) return stored;
  // Mesa's _mesa_unorm_to_unorm, narrowing: rounds to nearest.
  const uint64_t half = (uint64_t{1} << (storage_bits - 1)) - 1;
  return uint32_t((uint64_t{stored} * max_of(bits) + half) / max_of(storage_bits));
}

void encode_color_texels(const InternalFormatInfo& info, const glm::vec4* rgba, size_t count,
                         uint8_t* texels, uint32_t source_bits) {
  const bool wide = info.texel_format() == rec::TexelFormat::kRgba16;
  const uint32_t storage_bits = wide ? 16 : 8;
  uint32_t bits[4];
  for (int c = 0; c < 4; ++c) bits[c] = info.channel_bits(c);
  for (size_t i = 0; i < count; ++i) {
    const glm::vec4 v = to_base_format(info.base_format, rgba[i]);
    for (int c = 0; c < 4; ++c) {
      // Channels the base format fills with a constant (0 or 1) are stored at full width.
      const uint32_t b = bits[c] != 0 ? bits[c] : storage_bits;
      const uint32_t q = source_bits != 0 && b > source_bits
                             ? widen_to_storage(quantize(v[c], source_bits), source_bits, b)
                             : quantize(v[c], b);
      const uint32_t stored = widen_to_storage(q, b, storage_bits);
      if (wide) {
        const uint16_t h = uint16_t(stored);
        std::memcpy(texels + i * 8 + size_t(c) * 2, &h, 2);
      } else {
        texels[i * 4 + size_t(c)] = uint8_t(stored);
      }
    }
  }
}

void encode_depth_texels(const InternalFormatInfo& info, const float* depth, size_t count,
                         uint8_t* texels) {
  const double max = double(max_of(info.depth));
  for (size_t i = 0; i < count; ++i) {
    const double d = std::clamp(double(depth[i]), 0.0, 1.0);
    const float stored = float(std::nearbyint(d * max) / max);
    std::memcpy(texels + i * 4, &stored, 4);
  }
}

glm::vec4 decode_color_texel(const InternalFormatInfo& info, const uint8_t* texel) {
  const bool wide = info.texel_format() == rec::TexelFormat::kRgba16;
  const uint32_t storage_bits = wide ? 16 : 8;
  glm::vec4 c;
  for (int ch = 0; ch < 4; ++ch) {
    uint32_t stored;
    if (wide) {
      uint16_t h;
      std::memcpy(&h, texel + ch * 2, 2);
      stored = h;
    } else {
      stored = texel[ch];
    }
    const uint32_t bits = info.channel_bits(ch) != 0 ? info.channel_bits(ch) : storage_bits;
    // Mesa's _mesa_unorm_to_float of the value it stored.
    c[ch] = float(narrow_from_storage(stored, bits, storage_bits)) * (1.0f / float(max_of(bits)));
  }
  switch (info.base_format) {
    case GL_ALPHA:
      return {0.0f, 0.0f, 0.0f, c.a};
    case GL_LUMINANCE:
    case GL_INTENSITY:
      return {c.r, 0.0f, 0.0f, 1.0f};
    case GL_LUMINANCE_ALPHA:
      return {c.r, 0.0f, 0.0f, c.a};
    case GL_RGB:
      return {c.r, c.g, c.b, 1.0f};
    default:
      return c;
  }
}

float decode_depth_texel(const uint8_t* texel) {
  float d;
  std::memcpy(&d, texel, 4);
  return d;
}

}  // namespace glpt
