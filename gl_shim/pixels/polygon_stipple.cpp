// glPolygonStipple, glGetPolygonStipple (GL 1.5 3.5.2, 6.1.5): the 32x32 pattern is unpacked and
// packed as a GL_COLOR_INDEX / GL_BITMAP image, without pixel transfer.
#include <vector>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/pixels/pixel_pack.hpp"
#include "gl_shim/pixels/pixel_unpack.hpp"

namespace glpt::impl {

namespace {
constexpr int kStippleSize = 32;
}

void glPolygonStipple(Context& ctx, const GLubyte* mask) {
  if (mask == nullptr) return;  // no pixel unpack buffer in GL 1.5: nothing to read
  const std::vector<uint8_t> bits =
      unpack_bitmap(ctx.framebuffer.unpack, kStippleSize, kStippleSize, mask);
  // PrimitiveState::stipple_pattern: row r bottom first, bit 31 - c is column c.
  for (int r = 0; r < kStippleSize; ++r) {
    uint32_t row = 0;
    for (int c = 0; c < kStippleSize; ++c) {
      if (bits[size_t(r * kStippleSize + c)] != 0) row |= 1u << (31 - c);
    }
    ctx.raster.primitive.stipple_pattern[size_t(r)] = row;
  }
}

void glGetPolygonStipple(Context& ctx, GLubyte* mask) {
  if (mask == nullptr) return;
  std::vector<uint8_t> bits(kStippleSize * kStippleSize);
  for (int r = 0; r < kStippleSize; ++r) {
    const uint32_t row = ctx.raster.primitive.stipple_pattern[size_t(r)];
    for (int c = 0; c < kStippleSize; ++c)
      bits[size_t(r * kStippleSize + c)] = (row >> (31 - c)) & 1u;
  }
  pack_bitmap(ctx.framebuffer.pack, kStippleSize, kStippleSize, bits, mask);
}

}  // namespace glpt::impl
