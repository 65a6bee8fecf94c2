#include "gl_shim/pixels/pixel_pack.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/pixels/pixel_formats.hpp"

namespace glpt {
namespace {

void store_bits(uint8_t* p, int bytes, bool swap, uint32_t v) {
  switch (bytes) {
    case 1:
      *p = uint8_t(v);
      return;
    case 2: {
      uint16_t h = uint16_t(v);
      if (swap) h = __builtin_bswap16(h);
      std::memcpy(p, &h, 2);
      return;
    }
    default:
      if (swap) v = __builtin_bswap32(v);
      std::memcpy(p, &v, 4);
      return;
  }
}

// c in [0, 1] -> round(c * max) in float arithmetic, nearest even (Mesa's _mesa_float_to_unorm);
// the product of 1.0 and 2^32-1 rounds up to 2^32 in float, clamped here (Mesa wraps to 0).
uint32_t to_unorm(float c, uint32_t max) {
  const long long v = std::llrint(double(c * float(max)));
  return uint32_t(std::clamp<long long>(v, 0, max));
}
int32_t to_snorm(float c, int32_t max) {
  const long long v = std::llrint(double(c * float(max)));
  return int32_t(std::clamp<long long>(v, -max, max));
}

// A value in [0, 1] (or any float for GL_FLOAT) as the bits of one element of `type`.
uint32_t normalized_bits(float c, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
      return to_unorm(c, 0xFFu);
    case GL_BYTE:
      return uint32_t(to_snorm(c, 0x7F)) & 0xFFu;
    case GL_UNSIGNED_SHORT:
      return to_unorm(c, 0xFFFFu);
    case GL_SHORT:
      return uint32_t(to_snorm(c, 0x7FFF)) & 0xFFFFu;
    case GL_UNSIGNED_INT:
      return to_unorm(c, 0xFFFFFFFFu);
    case GL_INT:
      return uint32_t(to_snorm(c, 0x7FFFFFFF));
    case GL_FLOAT: {
      uint32_t bits;
      std::memcpy(&bits, &c, 4);
      return bits;
    }
    default:
      return 0;
  }
}

}  // namespace

void pack_color(const PackTarget& dst, const std::vector<glm::vec4>& rgba,
                LuminanceFrom luminance) {
  const ClientImageLayout layout(dst.modes, dst.shape, dst.three_d);
  if (dst.data == nullptr) return;
  auto* base = static_cast<uint8_t*>(dst.data);
  const GLenum type = dst.shape.type;
  const int components = format_components(dst.shape.format);
  const std::array<uint8_t, 4> order = format_component_order(dst.shape.format);
  const PackedLayout packed = packed_layout(type);
  const int element_bytes = type_bytes(type);
  const bool swap = layout.swap_bytes();
  for_each_group(layout, dst.shape, [&](size_t i, size_t offset, int32_t) {
    if (i >= rgba.size() || (dst.written != nullptr && dst.written[i] == 0)) return;
    const glm::vec4& px = rgba[i];
    const auto value = [&](int element) {
      if (order[element] != kLuminanceComponent) return px[order[element]];
      return luminance == LuminanceFrom::kRed ? px.r : std::min(px.r + px.g + px.b, 1.0f);
    };
    uint8_t* p = base + offset;
    if (packed.components != 0) {
      uint32_t bits = 0;
      for (int c = 0; c < packed.components; ++c) {
        const PackedField f = packed.fields[c];
        bits |= to_unorm(value(c), (1u << f.bits) - 1u) << f.shift;
      }
      store_bits(p, element_bytes, swap, bits);
      return;
    }
    for (int c = 0; c < components; ++c)
      store_bits(p + c * element_bytes, element_bytes, swap, normalized_bits(value(c), type));
  });
}

void pack_depth(const PackTarget& dst, const std::vector<float>& depth) {
  const ClientImageLayout layout(dst.modes, dst.shape, dst.three_d);
  if (dst.data == nullptr) return;
  auto* base = static_cast<uint8_t*>(dst.data);
  const GLenum type = dst.shape.type;
  const int element_bytes = type_bytes(type);
  for_each_group(layout, dst.shape, [&](size_t i, size_t offset, int32_t) {
    if (i >= depth.size() || (dst.written != nullptr && dst.written[i] == 0)) return;
    // 32-bit depth keeps the depth buffer's precision (computed in double).
    const uint32_t bits =
        type == GL_UNSIGNED_INT
            ? uint32_t(std::clamp(std::llrint(double(depth[i]) * 4294967295.0), 0LL, 0xFFFFFFFFLL))
            : normalized_bits(depth[i], type);
    store_bits(base + offset, element_bytes, layout.swap_bytes(), bits);
  });
}

void pack_indices(const PackTarget& dst, const std::vector<uint32_t>& values) {
  const ClientImageLayout layout(dst.modes, dst.shape, dst.three_d);
  if (dst.data == nullptr) return;
  auto* base = static_cast<uint8_t*>(dst.data);
  const GLenum type = dst.shape.type;
  const int element_bytes = type_bytes(type);
  for_each_group(layout, dst.shape, [&](size_t i, size_t offset, int32_t x) {
    if (i >= values.size() || (dst.written != nullptr && dst.written[i] == 0)) return;
    const uint32_t v = values[i];
    uint8_t* p = base + offset;
    uint32_t bits = v;
    switch (type) {
      case GL_BITMAP:
        *p = (v & 1u) != 0 ? uint8_t(*p | layout.bit_mask(x)) : uint8_t(*p & ~layout.bit_mask(x));
        return;
      case GL_BYTE:
        bits = v & 0x7Fu;
        break;
      case GL_SHORT:
        bits = v & 0x7FFFu;
        break;
      case GL_INT:
        bits = v & 0x7FFFFFFFu;
        break;
      case GL_FLOAT: {
        const float f = float(v);
        std::memcpy(&bits, &f, 4);
        break;
      }
      default:  // unsigned types: store_bits keeps the low bits
        break;
    }
    store_bits(p, element_bytes, layout.swap_bytes(), bits);
  });
}

void pack_bitmap(const PixelStoreModes& modes, int32_t width, int32_t height,
                 const std::vector<uint8_t>& bits, void* data) {
  std::vector<uint32_t> values(bits.size());
  std::transform(bits.begin(), bits.end(), values.begin(),
                 [](uint8_t b) { return b != 0 ? 1u : 0u; });
  pack_indices(PackTarget{modes, ImageShape{width, height, 1, GL_COLOR_INDEX, GL_BITMAP}, false,
                          data, nullptr},
               values);
}

}  // namespace glpt
