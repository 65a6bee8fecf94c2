// Where the groups of a client image lie in memory, given the pixel store modes (GL 1.5 3.6.4
// "Unpacking", 4.3.2 "Placement in client memory", 3.8.1 for three-dimensional images).
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>

#include "gl_shim/gl_types.h"
#include "gl_shim/state/framebuffer_state.hpp"

namespace glpt {

struct ImageShape {
  int32_t width = 0, height = 1, depth = 1;
  GLenum format = 0, type = 0;

  // Groups in the image; 0 when a dimension is not positive, SIZE_MAX when absurdly many.
  size_t groups() const {
    if (width <= 0 || height <= 0 || depth <= 0) return 0;
    const unsigned __int128 n =
        (unsigned __int128)(width) * (unsigned __int128)(height) * (unsigned __int128)(depth);
    return n > (unsigned __int128)(SIZE_MAX) ? SIZE_MAX : size_t(n);
  }
};

// The most groups glpt converts in one call (2^28: 4 GiB of RGBA floats); larger images are
// GL_OUT_OF_MEMORY.
inline constexpr size_t kMaxPixelGroups = size_t{1} << 28;

class ClientImageLayout {
 public:
  // `three_d`: IMAGE_HEIGHT and SKIP_IMAGES apply (TexImage3D, TexSubImage3D, GetTexImage of a
  // 3-D texture); two- and one-dimensional transfers ignore them. The format and type must have
  // passed check_format_and_type.
  ClientImageLayout(const PixelStoreModes& modes, const ImageShape& shape, bool three_d);

  // False when the addresses do not fit in 63 bits (absurd row lengths or skips).
  bool valid() const { return valid_; }
  bool is_bitmap() const { return bitmap_; }
  // Bytes of one group (0 for bitmaps).
  size_t group_bytes() const { return group_bytes_; }
  // Byte offset of the group at (x, y, z) from the client pointer; for bitmaps, of the byte
  // holding it.
  size_t group_offset(int64_t x, int64_t y, int64_t z) const {
    if (bitmap_) return size_t(row_start(y, z) + (skip_pixels_ + x) / 8);
    return size_t(row_start(y, z) + (skip_pixels_ + x) * int64_t(group_bytes_));
  }
  // Bitmaps: the mask of the group's bit within its byte (GL_UNPACK_LSB_FIRST decides the order).
  uint8_t bit_mask(int64_t x) const {
    const int bit = int((skip_pixels_ + x) % 8);
    return lsb_first_ ? uint8_t(1u << bit) : uint8_t(0x80u >> bit);
  }
  size_t row_stride() const { return size_t(row_stride_); }
  // One past the last byte the image touches (0 for an empty image).
  size_t end_offset() const { return size_t(end_); }
  bool swap_bytes() const { return swap_bytes_; }

 private:
  int64_t row_start(int64_t y, int64_t z) const {
    return (skip_images_ + z) * image_stride_ + (skip_rows_ + y) * row_stride_;
  }
  bool valid_ = true, bitmap_ = false, lsb_first_ = false, swap_bytes_ = false;
  size_t group_bytes_ = 0;
  int64_t skip_pixels_ = 0, skip_rows_ = 0, skip_images_ = 0;
  int64_t row_stride_ = 0, image_stride_ = 0, end_ = 0;
};

// Calls visit(group index, byte offset of the group, x) for every group of `shape` in group order
// (x fastest, then y, then z). Nothing for an invalid layout.
template <typename Visit>
void for_each_group(const ClientImageLayout& layout, const ImageShape& shape, Visit&& visit) {
  if (!layout.valid()) return;
  size_t i = 0;
  for (int32_t z = 0; z < shape.depth; ++z) {
    for (int32_t y = 0; y < shape.height; ++y) {
      for (int32_t x = 0; x < shape.width; ++x, ++i) visit(i, layout.group_offset(x, y, z), x);
    }
  }
}

}  // namespace glpt
