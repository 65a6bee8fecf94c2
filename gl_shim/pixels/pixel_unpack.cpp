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
    default:  // unsigned types and GL_INT: the bits themselves
      return bits;
  }
}

}  // namespace

std::vector<glm::vec4> unpack_color_raw(const UnpackSource& src) {
  const ClientImageLayout layout(src.modes, src.shape, src.three_d);
  std::vector<glm::vec4> out(src.shape.groups(), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  if (src.data == nullptr || out.empty()) return out;
  const auto* base = static_cast<const uint8_t*>(src.data);
  const GLenum type = src.shape.type;
  const int components = format_components(src.shape.format);
  const std::array<uint8_t, 4> order = format_component_order(src.shape.format);
  const PackedLayout packed = packed_layout(type);
  const int element_bytes = type_bytes(type);
  const bool swap = layout.swap_bytes();
  const auto put = [&](glm::vec4& px, int element, float value) {
    if (order[element] == kLuminanceComponent) {
      px.r = px.g = px.b = value;
    } else {
      px[order[element]] = value;
    }
  };
  for_each_group(layout, src.shape, [&](size_t i, size_t offset, int32_t) {
    const uint8_t* p = base + offset;
    glm::vec4& px = out[i];
    if (packed.components != 0) {
      const uint32_t bits = load_bits(p, element_bytes, swap);
      for (int c = 0; c < packed.components; ++c) {
        const PackedField f = packed.fields[c];
        const uint32_t max = (1u << f.bits) - 1u;
        put(px, c, unorm((bits >> f.shift) & max, max));
      }
      return;
    }
    for (int c = 0; c < components; ++c)
      put(px, c, normalized_element(load_bits(p + c * element_bytes, element_bytes, swap), type));
  });
  return out;
}

std::vector<glm::uvec4> unpack_color_integers(const UnpackSource& src) {
  const ClientImageLayout layout(src.modes, src.shape, src.three_d);
  std::vector<glm::uvec4> out(src.shape.groups(), glm::uvec4(0u));
  if (src.data == nullptr || out.empty()) return out;
  const auto* base = static_cast<const uint8_t*>(src.data);
  const GLenum type = src.shape.type;
  const int components = format_components(src.shape.format);
  const std::array<uint8_t, 4> order = format_component_order(src.shape.format);
  const PackedLayout packed = packed_layout(type);
  const int element_bytes = type_bytes(type);
  const bool swap = layout.swap_bytes();
  const auto put = [&](glm::uvec4& px, int element, uint32_t value) {
    if (order[size_t(element)] == kLuminanceComponent) {
      px.r = px.g = px.b = value;
    } else {
      px[order[size_t(element)]] = value;
    }
  };
  for_each_group(layout, src.shape, [&](size_t i, size_t offset, int32_t) {
    const uint8_t* p = base + offset;
    if (packed.components != 0) {
      const uint32_t bits = load_bits(p, element_bytes, swap);
      for (int c = 0; c < packed.components; ++c) {
        const PackedField f = packed.fields[size_t(c)];
        put(out[i], c, (bits >> f.shift) & ((1u << f.bits) - 1u));
      }
      return;
    }
    for (int c = 0; c < components; ++c) {
      const uint32_t bits = load_bits(p + c * element_bytes, element_bytes, swap);
      uint32_t v = 0;
      switch (type) {
        case GL_BYTE:
          v = uint32_t(int32_t(int8_t(bits)));
          break;
        case GL_SHORT:
          v = uint32_t(int32_t(int16_t(bits)));
          break;
        case GL_FLOAT:
          break;
        default:
          v = bits;
          break;
      }
      put(out[i], c, v);
    }
  });
  return out;
}

std::vector<uint32_t> unpack_indices_raw(const UnpackSource& src) {
  const ClientImageLayout layout(src.modes, src.shape, src.three_d);
  std::vector<uint32_t> out(src.shape.groups(), 0u);
  if (src.data == nullptr || out.empty()) return out;
  const auto* base = static_cast<const uint8_t*>(src.data);
  const GLenum type = src.shape.type;
  const int element_bytes = type_bytes(type);
  const bool swap = layout.swap_bytes();
  for_each_group(layout, src.shape, [&](size_t i, size_t offset, int32_t x) {
    const uint8_t* p = base + offset;
    out[i] = type == GL_BITMAP ? ((*p & layout.bit_mask(x)) != 0 ? 1u : 0u)
                               : index_element(load_bits(p, element_bytes, swap), type);
  });
  return out;
}

std::vector<float> unpack_depth_raw(const UnpackSource& src) {
  const ClientImageLayout layout(src.modes, src.shape, src.three_d);
  std::vector<float> out(src.shape.groups(), 0.0f);
  if (src.data == nullptr || out.empty()) return out;
  const auto* base = static_cast<const uint8_t*>(src.data);
  const GLenum type = src.shape.type;
  const int element_bytes = type_bytes(type);
  const bool swap = layout.swap_bytes();
  for_each_group(layout, src.shape, [&](size_t i, size_t offset, int32_t) {
    const uint8_t* p = base + offset;
    out[i] = normalized_element(load_bits(p, element_bytes, swap), type);
  });
  return out;
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
