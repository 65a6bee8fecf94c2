#include "gl_shim/pixels/pixel_unpack.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"

namespace glpt {
namespace {

// One element of `bytes` bytes at p, as an unsigned integer, byte-swapped if asked
// (GL_UNPACK_SWAP_BYTES swaps every element of 2 or 4 bytes, packed groups included).
uint32_t load_bits(const uint8_t* p, int bytes, bool swap) {
  switch (bytes) {
    case 1:
      return *p;
    case 2: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return swap ? __builtin_bswap16(v) : v;
    }
    default: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return swap ? __builtin_bswap32(v) : v;
    }
  }
}

// Mesa's _mesa_unorm_to_float / _mesa_snorm_to_float: multiply by the reciprocal in float.
float unorm(uint32_t v, uint32_t max) { return float(v) * (1.0f / float(max)); }
float snorm(int32_t v, int32_t max) { return v <= -max ? -1.0f : float(v) * (1.0f / float(max)); }

// A colour / depth element of a non-packed type as a float (GL 1.5 3.6.4, table 2.9 as Mesa
// applies it).
float normalized_element(uint32_t bits, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
      return unorm(bits, 0xFFu);
    case GL_BYTE:
      return snorm(int8_t(bits), 0x7F);
    case GL_UNSIGNED_SHORT:
      return unorm(bits, 0xFFFFu);
    case GL_SHORT:
      return snorm(int16_t(bits), 0x7FFF);
    case GL_UNSIGNED_INT:
      return float(double(bits) / 4294967295.0);
    case GL_INT:
      return std::max(float(double(int32_t(bits)) / 2147483647.0), -1.0f);
    case GL_FLOAT: {
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
    case GL_UNSIGNED_INT_24_8_EXT:  // the depth bits, as _mesa_unpack_depth_span converts them
      return float(bits >> 8) * (1.0f / float(0xFFFFFF));
    default:
      return 0.0f;
  }
}

// An index element as Mesa's extract_uint_indexes takes it.
uint32_t index_element(uint32_t bits, GLenum type) {
  switch (type) {
    case GL_BYTE:
      return uint32_t(int32_t(int8_t(bits)));
    case GL_SHORT:
      return uint32_t(int32_t(int16_t(bits)));
    case GL_FLOAT: {
      float f;
      std::memcpy(&f, &bits, 4);
      if (!std::isfinite(f) || std::fabs(f) >= 9.0e18f) return 0;
      return uint32_t(uint64_t(int64_t(f)));
    }
    case GL_UNSIGNED_INT_24_8_EXT:  // the stencil bits
      return bits & 0xFFu;
    default:  // unsigned types and GL_INT: the bits themselves
      return bits;
  }
}

}  // namespace

namespace {

// The components of every group of a colour image, placed in RGBA order (luminance in R, G and
// B) into pixels that start as `initial`. value(raw, field_bits) gives a component from its bits:
// a packed field of `field_bits` bits, or an element as loaded (field_bits 0).
template <typename Pixel, typename Value>
std::vector<Pixel> unpack_color_components(const UnpackSource& src, Pixel initial, Value&& value) {
  const ClientImageLayout layout(src.modes, src.shape, src.three_d);
  std::vector<Pixel> out(src.shape.groups(), initial);
  if (src.data == nullptr || out.empty()) return out;
  const auto* base = static_cast<const uint8_t*>(src.data);
  const int components = format_components(src.shape.format);
  const std::array<uint8_t, 4> order = format_component_order(src.shape.format);
  const PackedLayout packed = packed_layout(src.shape.type);
  const int element_bytes = type_bytes(src.shape.type);
  const bool swap = layout.swap_bytes();
  const auto put = [&](Pixel& px, int element, auto component) {
    if (order[size_t(element)] == kLuminanceComponent) {
      px.r = px.g = px.b = component;
    } else {
      px[order[size_t(element)]] = component;
    }
  };
  for_each_group(layout, src.shape, [&](size_t i, size_t offset, int32_t) {
    const uint8_t* p = base + offset;
    if (packed.components != 0) {
      const uint32_t bits = load_bits(p, element_bytes, swap);
      for (int c = 0; c < packed.components; ++c) {
        const PackedField f = packed.fields[size_t(c)];
        put(out[i], c, value((bits >> f.shift) & ((1u << f.bits) - 1u), f.bits));
      }
      return;
    }
    for (int c = 0; c < components; ++c)
      put(out[i], c, value(load_bits(p + c * element_bytes, element_bytes, swap), 0));
  });
  return out;
}

}  // namespace

std::vector<glm::vec4> unpack_color_raw(const UnpackSource& src) {
  const GLenum type = src.shape.type;
  return unpack_color_components(src, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f),
                                 [type](uint32_t raw, int field_bits) {
                                   return field_bits != 0 ? unorm(raw, (1u << field_bits) - 1u)
                                                          : normalized_element(raw, type);
                                 });
}

std::vector<glm::uvec4> unpack_color_integers(const UnpackSource& src) {
  const GLenum type = src.shape.type;
  return unpack_color_components(src, glm::uvec4(0u), [type](uint32_t raw, int field_bits) {
    if (field_bits != 0) return raw;
    switch (type) {
      case GL_BYTE:
        return uint32_t(int32_t(int8_t(raw)));
      case GL_SHORT:
        return uint32_t(int32_t(int16_t(raw)));
      case GL_FLOAT:
        return 0u;
      default:
        return raw;
    }
  });
}

namespace {

// One value per group of a single-element format: convert(element bits, x), the bits loaded with
// GL_UNPACK_SWAP_BYTES applied (bitmaps: the byte holding the group).
template <typename Value, typename Convert>
std::vector<Value> unpack_single_elements(const UnpackSource& src, Convert&& convert) {
  const ClientImageLayout layout(src.modes, src.shape, src.three_d);
  std::vector<Value> out(src.shape.groups(), Value{});
  if (src.data == nullptr || out.empty()) return out;
  const auto* base = static_cast<const uint8_t*>(src.data);
  const int element_bytes = src.shape.type == GL_BITMAP ? 1 : type_bytes(src.shape.type);
  const bool swap = layout.swap_bytes();
  for_each_group(layout, src.shape, [&](size_t i, size_t offset, int32_t x) {
    out[i] = convert(load_bits(base + offset, element_bytes, swap), x, layout);
  });
  return out;
}

}  // namespace

std::vector<uint32_t> unpack_indices_raw(const UnpackSource& src) {
  const GLenum type = src.shape.type;
  return unpack_single_elements<uint32_t>(
      src, [type](uint32_t bits, int32_t x, const ClientImageLayout& layout) {
        if (type == GL_BITMAP) return (bits & layout.bit_mask(x)) != 0 ? 1u : 0u;
        return index_element(bits, type);
      });
}

std::vector<float> unpack_depth_raw(const UnpackSource& src) {
  const GLenum type = src.shape.type;
  return unpack_single_elements<float>(src,
                                       [type](uint32_t bits, int32_t, const ClientImageLayout&) {
                                         return normalized_element(bits, type);
                                       });
}

std::vector<uint32_t> unpack_depth_stencil_words(const UnpackSource& src) {
  return unpack_single_elements<uint32_t>(
      src, [](uint32_t bits, int32_t, const ClientImageLayout&) { return bits; });
}

std::vector<glm::vec4> unpack_color(const UnpackSource& src,
                                    const rec::PixelTransferState& transfer) {
  if (src.shape.format == GL_COLOR_INDEX)
    return transfer_index_to_rgba(transfer, unpack_indices_raw(src));
  std::vector<glm::vec4> rgba = unpack_color_raw(src);
  transfer_rgba(transfer, rgba);
  return rgba;
}

std::vector<float> unpack_depth(const UnpackSource& src, const rec::PixelTransferState& transfer) {
  std::vector<float> depth = unpack_depth_raw(src);
  transfer_depth(transfer, depth);
  return depth;
}

std::vector<uint32_t> unpack_stencil(const UnpackSource& src,
                                     const rec::PixelTransferState& transfer) {
  std::vector<uint32_t> stencil = unpack_indices_raw(src);
  transfer_stencil(transfer, stencil);
  return stencil;
}

std::vector<uint8_t> unpack_bitmap(const PixelStoreModes& modes, int32_t width, int32_t height,
                                   const void* data) {
  const UnpackSource src{modes, ImageShape{width, height, 1, GL_COLOR_INDEX, GL_BITMAP}, false,
                         data};
  const std::vector<uint32_t> bits = unpack_indices_raw(src);
  return std::vector<uint8_t>(bits.begin(), bits.end());
}

}  // namespace glpt
