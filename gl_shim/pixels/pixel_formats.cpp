#include "gl_shim/pixels/pixel_formats.hpp"

#include "gl/gl_enums.h"

namespace glpt {

PixelClass pixel_class(GLenum format) {
  switch (format) {
    case GL_COLOR_INDEX:
      return PixelClass::kColorIndex;
    case GL_STENCIL_INDEX:
      return PixelClass::kStencilIndex;
    case GL_DEPTH_COMPONENT:
      return PixelClass::kDepth;
    case GL_DEPTH_STENCIL_EXT:
      return PixelClass::kDepthStencil;
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_RGB:
    case GL_BGR:
    case GL_RGBA:
    case GL_BGRA:
    case GL_ABGR_EXT:
    case GL_LUMINANCE:
    case GL_LUMINANCE_ALPHA:
      return PixelClass::kColor;
    default:
      return PixelClass::kInvalid;
  }
}

int format_components(GLenum format) {
  switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_STENCIL_EXT:  // one packed GL_UNSIGNED_INT_24_8_EXT word
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE:
      return 1;
    case GL_LUMINANCE_ALPHA:
      return 2;
    case GL_RGB:
    case GL_BGR:
      return 3;
    case GL_RGBA:
    case GL_BGRA:
    case GL_ABGR_EXT:
      return 4;
    default:
      return 0;
  }
}

std::array<uint8_t, 4> format_component_order(GLenum format) {
  constexpr uint8_t R = 0, G = 1, B = 2, A = 3, L = kLuminanceComponent;
  switch (format) {
    case GL_GREEN:
      return {G, 0, 0, 0};
    case GL_BLUE:
      return {B, 0, 0, 0};
    case GL_ALPHA:
      return {A, 0, 0, 0};
    case GL_LUMINANCE:
      return {L, 0, 0, 0};
    case GL_LUMINANCE_ALPHA:
      return {L, A, 0, 0};
    case GL_BGR:
      return {B, G, R, 0};
    case GL_BGRA:
      return {B, G, R, A};
    case GL_ABGR_EXT:
      return {A, B, G, R};
    default:  // GL_RED, GL_RGB, GL_RGBA (and the single element of index/depth formats)
      return {R, G, B, A};
  }
}

PackedLayout packed_layout(GLenum type) {
  // Fields listed from the format's first component to its last (GL 1.5 tables 3.11-3.13).
  using F = PackedField;
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2:
      return {3, {F{5, 3}, F{2, 3}, F{0, 2}}};
    case GL_UNSIGNED_BYTE_2_3_3_REV:
      return {3, {F{0, 3}, F{3, 3}, F{6, 2}}};
    case GL_UNSIGNED_SHORT_5_6_5:
      return {3, {F{11, 5}, F{5, 6}, F{0, 5}}};
    case GL_UNSIGNED_SHORT_5_6_5_REV:
      return {3, {F{0, 5}, F{5, 6}, F{11, 5}}};
    case GL_UNSIGNED_SHORT_4_4_4_4:
      return {4, {F{12, 4}, F{8, 4}, F{4, 4}, F{0, 4}}};
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
      return {4, {F{0, 4}, F{4, 4}, F{8, 4}, F{12, 4}}};
    case GL_UNSIGNED_SHORT_5_5_5_1:
      return {4, {F{11, 5}, F{6, 5}, F{1, 5}, F{0, 1}}};
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
      return {4, {F{0, 5}, F{5, 5}, F{10, 5}, F{15, 1}}};
    case GL_UNSIGNED_INT_8_8_8_8:
      return {4, {F{24, 8}, F{16, 8}, F{8, 8}, F{0, 8}}};
    case GL_UNSIGNED_INT_8_8_8_8_REV:
      return {4, {F{0, 8}, F{8, 8}, F{16, 8}, F{24, 8}}};
    case GL_UNSIGNED_INT_10_10_10_2:
      return {4, {F{22, 10}, F{12, 10}, F{2, 10}, F{0, 2}}};
    case GL_UNSIGNED_INT_2_10_10_10_REV:
      return {4, {F{0, 10}, F{10, 10}, F{20, 10}, F{30, 2}}};
    default:
      return {};
  }
}

bool is_packed_type(GLenum type) { return packed_layout(type).components != 0; }

int type_bytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
      return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
      return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
    case GL_UNSIGNED_INT_24_8_EXT:
      return 4;
    default:
      return 0;
  }
}

ColorSourceLayout ColorSourceLayout::floats() {
  ColorSourceLayout l;
  l.kind.fill(Kind::kFloat);
  l.rgba_floats = true;
  return l;
}

ColorSourceLayout ColorSourceLayout::bytes() {
  ColorSourceLayout l;
  l.kind.fill(Kind::kUnsigned);
  l.bits.fill(8);
  l.rgba_bytes = true;
  return l;
}

ColorSourceLayout color_source_layout(GLenum format, GLenum type) {
  using Kind = ColorSourceLayout::Kind;
  ColorSourceLayout l;
  const PackedLayout packed = packed_layout(type);
  const bool byte_array_packed =
      type == GL_UNSIGNED_INT_8_8_8_8 || type == GL_UNSIGNED_INT_8_8_8_8_REV;
  l.packed = packed.components != 0 && !byte_array_packed;
  Kind kind = Kind::kFloat;
  uint8_t bits = 0;
  switch (type) {
    case GL_UNSIGNED_BYTE:
      kind = Kind::kUnsigned, bits = 8;
      break;
    case GL_UNSIGNED_SHORT:
      kind = Kind::kUnsigned, bits = 16;
      break;
    case GL_BYTE:
      kind = Kind::kSigned, bits = 8;
      break;
    case GL_SHORT:
      kind = Kind::kSigned, bits = 16;
      break;
    case GL_UNSIGNED_INT:
      kind = Kind::kUnsigned, bits = 32;
      break;
    case GL_INT:
      kind = Kind::kSigned, bits = 32;
      break;
    default:
      if (packed.components != 0) kind = Kind::kUnsigned;
      break;
  }
  const std::array<uint8_t, 4> order = format_component_order(format);
  const int components = packed.components != 0 ? packed.components : format_components(format);
  for (int e = 0; e < components; ++e) {
    const uint8_t b = packed.components != 0 ? packed.fields[size_t(e)].bits : bits;
    const auto set = [&](int c) {
      l.kind[size_t(c)] = kind;
      l.bits[size_t(c)] = b;
    };
    if (order[size_t(e)] == kLuminanceComponent) {
      set(0), set(1), set(2);
    } else {
      set(order[size_t(e)]);
    }
  }
  // Little-endian: UNSIGNED_INT_8_8_8_8_REV with RGBA is the bytes R, G, B, A.
  l.rgba_bytes =
      format == GL_RGBA && (type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_INT_8_8_8_8_REV);
  l.rgba_floats = format == GL_RGBA && type == GL_FLOAT;
  return l;
}

namespace {

// Formats of later GL versions (ARB_texture_rg, EXT_texture_integer) that glpt does not
// implement but Mesa knows: Mesa checks a packed type against them before it looks at the
// format, so a mismatch is GL_INVALID_OPERATION there (piglit draw-pixels expects it for GL_RG).
bool later_format_known_to_mesa(GLenum format) {
  constexpr GLenum kRg = 0x8227, kRgInteger = 0x8228;
  constexpr GLenum kFirstInteger = 0x8D94;  // GL_RED_INTEGER .. GL_BGRA_INTEGER
  constexpr GLenum kLastInteger = 0x8D9B;
  constexpr GLenum kLuminanceInteger = 0x8D9C, kLuminanceAlphaInteger = 0x8D9D;
  return format == kRg || format == kRgInteger ||
         (format >= kFirstInteger && format <= kLastInteger) || format == kLuminanceInteger ||
         format == kLuminanceAlphaInteger;
}

}  // namespace

GLenum check_format_and_type(GLenum format, GLenum type) {
  const bool known = pixel_class(format) != PixelClass::kInvalid;
  if (!known && !later_format_known_to_mesa(format)) return GL_INVALID_ENUM;
  if (format == GL_DEPTH_STENCIL_EXT)
    return type == GL_UNSIGNED_INT_24_8_EXT ? GL_NO_ERROR : GL_INVALID_ENUM;
  if (type == GL_UNSIGNED_INT_24_8_EXT) return GL_INVALID_OPERATION;
  if (type == GL_BITMAP) {
    return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? GL_NO_ERROR : GL_INVALID_ENUM;
  }
  // Mesa's order (_mesa_error_check_format_and_type): the packed type's format first.
  const PackedLayout packed = packed_layout(type);
  if (packed.components == 3 && format != GL_RGB) return GL_INVALID_OPERATION;
  if (packed.components == 4 && format != GL_RGBA && format != GL_BGRA && format != GL_ABGR_EXT)
    return GL_INVALID_OPERATION;
  if (!known || type_bytes(type) == 0) return GL_INVALID_ENUM;
  return GL_NO_ERROR;
}

}  // namespace glpt
