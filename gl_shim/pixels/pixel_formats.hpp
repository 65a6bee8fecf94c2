// Client pixel formats and types (GL 1.5 tables 3.5, 3.6, 3.8, 3.11-3.13; EXT_bgra, EXT_abgr,
// GL 1.2 packed pixels): what a group holds and how its elements are laid out in memory.
#pragma once

#include <array>
#include <cstdint>

#include "gl_shim/gl_types.h"

namespace glpt {

// What the groups of a format are (GL 1.5 table 3.8, "target buffer").
// kDepthStencil: GL_DEPTH_STENCIL_EXT (EXT_packed_depth_stencil), whose only type is
// GL_UNSIGNED_INT_24_8_EXT: 24 bits of depth above 8 bits of stencil index in one 32-bit word.
enum class PixelClass : uint8_t {
  kInvalid,
  kColor,
  kColorIndex,
  kStencilIndex,
  kDepth,
  kDepthStencil
};

PixelClass pixel_class(GLenum format);

// Elements per group (1..4), 0 for a format GL 1.5 does not know.
int format_components(GLenum format);

// For each element of a colour format's group, which RGBA component it is (0 R, 1 G, 2 B, 3 A;
// 4 luminance, whose value goes to R, G and B). Only the first format_components() entries are
// meaningful.
std::array<uint8_t, 4> format_component_order(GLenum format);
inline constexpr uint8_t kLuminanceComponent = 4;

bool is_packed_type(GLenum type);

// Bytes of one element, or of the whole group for packed types; 0 for GL_BITMAP and unknown types.
int type_bytes(GLenum type);

// One field of a packed type: the n-th component of the format sits at bits [shift, shift+bits).
struct PackedField {
  uint8_t shift = 0, bits = 0;
};
struct PackedLayout {
  int components = 0;  // 3 or 4; 0 if `type` is not packed
  std::array<PackedField, 4> fields{};
};
PackedLayout packed_layout(GLenum type);

// How a colour group of a format/type carries each RGBA component, as Mesa's format conversion
// (_mesa_format_convert) sees the client's image: it converts integer components with integer
// arithmetic, and which intermediate it takes depends on whether the client format is an array
// of components and whether it is exactly RGBA bytes or floats.
struct ColorSourceLayout {
  enum class Kind : uint8_t { kMissing, kUnsigned, kSigned, kFloat };
  std::array<Kind, 4> kind{};     // per RGBA component (luminance counts for R, G and B)
  std::array<uint8_t, 4> bits{};  // integer bits (kUnsigned, kSigned)
  bool packed = false;            // a packed type that is no byte array (5_6_5, 10_10_10_2, ...)
  bool rgba_bytes = false;        // R, G, B, A unsigned bytes in this order
  bool rgba_floats = false;       // R, G, B, A floats in this order

  // What Mesa converts from once pixel transfer has run: RGBA floats.
  static ColorSourceLayout floats();
  // What Mesa converts colour indices to before storing them: RGBA bytes.
  static ColorSourceLayout bytes();
};
// For a colour format (not COLOR_INDEX) and a valid type.
ColorSourceLayout color_source_layout(GLenum format, GLenum type);

// GL_NO_ERROR, or the error GL (and Mesa) report for this format/type pair: an unknown format or
// type, or GL_BITMAP with a format other than COLOR_INDEX / STENCIL_INDEX, is GL_INVALID_ENUM; a
// packed type whose component count does not match the format's is GL_INVALID_OPERATION.
// EXT_packed_depth_stencil as Mesa checks it (_mesa_error_check_format_and_type):
// GL_DEPTH_STENCIL_EXT with any type but GL_UNSIGNED_INT_24_8_EXT is GL_INVALID_ENUM,
// GL_UNSIGNED_INT_24_8_EXT with another known format GL_INVALID_OPERATION (measured with OSMesa: an
// unknown format is GL_INVALID_ENUM first).
GLenum check_format_and_type(GLenum format, GLenum type);

}  // namespace glpt
