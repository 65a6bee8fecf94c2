// SEAM: client pixel rectangles for glDrawPixels and glBitmap, unpacked from client memory and
// through pixel transfer (GL 1.5 3.6.4, 3.6.5).
//
// The full unpacker (every packed type, colour indices, the pixel maps; shared with glTexImage)
// is being written on branch `textures` (gl_shim/pixels/pixel_unpack.hpp: unpack_color,
// unpack_depth, unpack_stencil, unpack_bitmap; pixel_formats.hpp: check_format_and_type). Until
// it is merged, this interim unpacker serves the pixel commands: it validates every format/type
// pair as GL does, and unpacks the unpacked component types (UNSIGNED_BYTE ... FLOAT) of the
// colour, depth and stencil formats, with scale/bias and index shift/offset. Everything else
// (packed types, COLOR_INDEX, MAP_COLOR / MAP_STENCIL) reports "unsupported". Replace the bodies
// with calls to the full unpacker once it is in main; the callers need not change.
#pragma once

#include <cstdint>
#include <vector>

#include "gl_shim/gl_types.h"
#include "gl_shim/state/framebuffer_state.hpp"
#include "rt_core/record/frame_record.hpp"

namespace glpt {

class Context;

// GL_NO_ERROR, or the error GL names for a glDrawPixels format/type pair: an unknown format or
// type, or GL_BITMAP with a format other than COLOR_INDEX / STENCIL_INDEX, is GL_INVALID_ENUM; a
// packed type whose layout does not fit the format is GL_INVALID_OPERATION.
GLenum check_pixel_format_and_type(GLenum format, GLenum type);

// What a valid format draws into: colour, depth or stencil.
rec::PixelKind pixel_kind_of(GLenum format);

// Fills out.kind, out.color / out.depth / out.stencil (width * height values, rows bottom to
// top) from `pixels` with ctx's unpack modes and pixel transfer state. False when this interim
// unpacker does not support the pair (see above); `out` is then unchanged. The pair must have
// passed check_pixel_format_and_type; width and height are positive.
bool unpack_image(const Context& ctx, int32_t width, int32_t height, GLenum format, GLenum type,
                  const void* pixels, rec::DrawPixels& out);

// A glBitmap image: width * height bytes, 1 where the bit is set, rows bottom to top.
std::vector<uint8_t> unpack_bitmap(const PixelStoreModes& modes, int32_t width, int32_t height,
                                   const uint8_t* bitmap);

}  // namespace glpt
