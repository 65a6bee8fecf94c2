#include "gl_shim/textures/texel_codec.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/pixels/pixel_formats.hpp"

namespace glpt {
namespace {

uint32_t max_of(uint32_t bits) { return bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1u; }

// Mesa's _mesa_float_to_unorm: nearest even of c * (2^b - 1) in float.
uint32_t quantize(float c, uint32_t bits) {
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return max_of(bits);
  return uint32_t(std::lrint(c * float(max_of(bits))));
}

// Which incoming RGBA component a stored channel takes (rec::TexelFormat's layout, GL 1.5 table
// 3.15), or -1 for GL's constant (0 for R, G, B and 1 for A).
int source_component(GLenum base, int channel) {
  switch (base) {
    case GL_ALPHA:
      return channel == 3 ? 3 : -1;
    case GL_LUMINANCE:
      return channel < 3 ? 0 : -1;
    case GL_LUMINANCE_ALPHA:
      return channel < 3 ? 0 : 3;
    case GL_INTENSITY:
      return 0;
    case GL_RGB:
      return channel < 3 ? channel : -1;
    default:
      return channel;
  }
}

}  // namespace

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

namespace {

// Mesa's _mesa_unorm_to_unorm.
uint32_t unorm_to_unorm(uint32_t x, uint32_t from, uint32_t to) {
  if (to > from) return widen_to_storage(x, from, to);
  if (to < from) return narrow_from_storage(x, to, from);
  return x;
}

// How _mesa_format_convert gets from the client's components to the texture's format.
enum class Route : uint8_t {
  kDirect,    // component by component (array formats, or RGBA bytes/floats into packed ones)
  kViaBytes,  // through RGBA bytes (packed formats of at most 8 bits per channel)
  kViaFloat   // through RGBA floats (wider packed formats)
};

Route conversion_route(const InternalFormatInfo& info, const ColorSourceLayout& source) {
  const uint32_t storage_bits = info.texel_format() == rec::TexelFormat::kRgba16 ? 16 : 8;
  bool array = true;  // Mesa's format for it is an array of 8- or 16-bit channels
  uint32_t max_bits = 0;
  for (int c = 0; c < 4; ++c) {
    const uint32_t bits = info.channel_bits(c);
    if (bits != 0 && bits != storage_bits) array = false;
    max_bits = std::max(max_bits, bits);
  }
  if (array) {
    if (!source.packed) return Route::kDirect;
    return storage_bits <= 8 ? Route::kViaBytes : Route::kViaFloat;
  }
  if (source.rgba_bytes || source.rgba_floats) return Route::kDirect;
  return max_bits > 8 ? Route::kViaFloat : Route::kViaBytes;
}

// One component as `bits` bits: `v` its value as a float, `raw` (when `has_raw`) the client's
// integer, of `kind` and `from_bits` bits.
uint32_t convert_component(float v, uint32_t raw, bool has_raw, ColorSourceLayout::Kind kind,
                           uint32_t from_bits, uint32_t bits, Route route) {
  using Kind = ColorSourceLayout::Kind;
  if (route == Route::kViaFloat || kind == Kind::kFloat || kind == Kind::kMissing) {
    if (route != Route::kViaBytes) return quantize(v, bits);
    return unorm_to_unorm(quantize(v, 8), 8, bits);
  }
  const uint32_t to = route == Route::kViaBytes ? 8 : bits;
  uint32_t x;
  if (kind == Kind::kUnsigned) {
    const uint32_t u = has_raw ? raw : uint32_t(std::lrint(double(v) * max_of(from_bits)));
    x = unorm_to_unorm(u, from_bits, to);
  } else {  // signed: negative values are 0, the rest has one bit less (_mesa_snorm_to_unorm)
    const int64_t s =
        has_raw ? int64_t(int32_t(raw)) : std::llrint(double(v) * max_of(from_bits - 1));
    x = s <= 0 ? 0 : unorm_to_unorm(uint32_t(s), from_bits - 1, to);
  }
  return route == Route::kViaBytes ? unorm_to_unorm(x, 8, bits) : x;
}

}  // namespace

void encode_color_texels(const InternalFormatInfo& info, const glm::vec4* rgba, size_t count,
                         uint8_t* texels, const ColorSourceLayout& source,
                         const glm::uvec4* integers) {
  const bool wide = info.texel_format() == rec::TexelFormat::kRgba16;
  const uint32_t storage_bits = wide ? 16 : 8;
  const Route route = conversion_route(info, source);
  struct Channel {
    int source;     // RGBA component, or -1 for a constant
    uint32_t bits;  // Mesa's size for it (storage width for constants)
  };
  std::array<Channel, 4> channels;
  for (int c = 0; c < 4; ++c) {
    const uint32_t bits = info.channel_bits(c) != 0 ? info.channel_bits(c) : storage_bits;
    channels[size_t(c)] = {source_component(info.base_format, c), bits};
  }
  for (size_t i = 0; i < count; ++i) {
    for (int c = 0; c < 4; ++c) {
      const Channel& ch = channels[size_t(c)];
      uint32_t q;
      if (ch.source < 0) {
        q = c == 3 ? max_of(ch.bits) : 0;
      } else {
        const size_t s = size_t(ch.source);
        q = convert_component(rgba[i][ch.source], integers ? integers[i][ch.source] : 0u,
                              integers != nullptr, source.kind[s], source.bits[s], ch.bits, route);
      }
      const uint32_t stored = widen_to_storage(q, ch.bits, storage_bits);
      if (wide) {
        const uint16_t h = uint16_t(stored);
        std::memcpy(texels + i * 8 + size_t(c) * 2, &h, 2);
      } else {
        texels[i * 4 + size_t(c)] = uint8_t(stored);
      }
    }
  }
}

bool encode_byte_texels(const InternalFormatInfo& info, const UnpackSource& src, uint8_t* texels) {
  if (src.shape.type != GL_UNSIGNED_BYTE || pixel_class(src.shape.format) != PixelClass::kColor ||
      info.texel_format() != rec::TexelFormat::kRgba8 || src.data == nullptr)
    return false;
  for (int c = 0; c < 4; ++c) {
    if (info.channel_bits(c) != 0 && info.channel_bits(c) != 8) return false;
  }
  const ClientImageLayout layout(src.modes, src.shape, src.three_d);
  const int components = format_components(src.shape.format);
  const std::array<uint8_t, 4> order = format_component_order(src.shape.format);
  std::array<int, 4> source;
  for (int c = 0; c < 4; ++c) source[size_t(c)] = source_component(info.base_format, c);
  const auto* base = static_cast<const uint8_t*>(src.data);
  for_each_group(layout, src.shape, [&](size_t i, size_t offset, int32_t) {
    const uint8_t* p = base + offset;
    uint8_t rgba[4] = {0, 0, 0, 255};  // GL's defaults for missing components
    for (int e = 0; e < components; ++e) {
      if (order[size_t(e)] == kLuminanceComponent) {
        rgba[0] = rgba[1] = rgba[2] = p[e];
      } else {
        rgba[order[size_t(e)]] = p[e];
      }
    }
    uint8_t* out = texels + i * 4;
    for (int c = 0; c < 4; ++c)
      out[c] = source[size_t(c)] >= 0 ? rgba[source[size_t(c)]] : c == 3 ? 255 : 0;
  });
  return true;
}

void encode_depth_texels(const InternalFormatInfo& info, const float* depth, size_t count,
                         uint8_t* texels, DepthRounding rounding) {
  const uint32_t max = max_of(info.depth);
  for (size_t i = 0; i < count; ++i) {
    const float d = std::isnan(depth[i]) ? 0.0f : std::clamp(depth[i], 0.0f, 1.0f);
    uint32_t z;
    if (rounding == DepthRounding::kNearest) {
      z = uint32_t(std::nearbyint(double(d) * double(max)));
    } else if (max <= 0xFFFFFFu) {
      z = uint32_t(d * float(max));  // _mesa_unpack_depth_span: float product, truncated
    } else {
      const double product = double(d) * double(max);  // double: no overflow
      z = product >= double(max) ? max : uint32_t(product);
    }
    encode_depth_unorm_texel(info, z, texels + i * 4);
  }
}

void encode_depth_unorm_texel(const InternalFormatInfo& info, uint32_t z, uint8_t* texel) {
  const float stored = float(double(z) / double(max_of(info.depth)));
  std::memcpy(texel, &stored, 4);
}

glm::vec4 decode_color_texel(const InternalFormatInfo& info, const uint8_t* texel,
                             TexelValue value) {
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
    const uint32_t bits = value == TexelValue::kStored || info.channel_bits(ch) == 0
                              ? storage_bits
                              : info.channel_bits(ch);
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
