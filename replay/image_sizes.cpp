#include "replay/image_sizes.hpp"

#include <algorithm>

#include "gl/gl_enums.h"

namespace glpt::replay {
namespace {

int64_t components(GLenum format) {
  switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE:
    case GL_DEPTH_STENCIL_EXT:  // one packed group
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

// Bytes of one element, or of a whole group for the packed types (then *packed).
int64_t type_bytes(GLenum type, bool* packed) {
  *packed = false;
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
      return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
      return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT:
      return 4;
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
      *packed = true;
      return 1;
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
      *packed = true;
      return 2;
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
    case GL_UNSIGNED_INT_24_8_EXT:
      *packed = true;
      return 4;
    default:
      return 0;
  }
}

int64_t round_up(int64_t value, int64_t multiple) {
  return (value + multiple - 1) / multiple * multiple;
}

}  // namespace

std::optional<uint64_t> image_bytes(int64_t width, int64_t height, int64_t depth, GLenum format,
                                    GLenum type, bool three_d, const UnpackModes& modes) {
  // Sizes beyond this are not images (and keep the arithmetic below from overflowing).
  constexpr int64_t kMaxExtent = int64_t{1} << 20;
  if (width < 0 || height < 0 || depth < 0 || width > kMaxExtent || height > kMaxExtent ||
      depth > kMaxExtent)
    return std::nullopt;
  if (width == 0 || height == 0 || depth == 0) return 0;
  const int64_t alignment = std::clamp<int64_t>(modes.alignment, 1, 8);
  const int64_t row_pixels =
      std::clamp<int64_t>(modes.row_length > 0 ? modes.row_length : width, width, kMaxExtent) +
      std::clamp<int64_t>(modes.skip_pixels, 0, kMaxExtent);
  int64_t row_bytes = 0;
  if (type == GL_BITMAP) {
    if (format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX) return std::nullopt;
    row_bytes = round_up((row_pixels + 7) / 8, alignment);
  } else {
    bool packed = false;
    const int64_t size = type_bytes(type, &packed), n = components(format);
    if (size == 0 || n == 0) return std::nullopt;
    row_bytes = round_up(row_pixels * (packed ? size : size * n), alignment);
  }
  const int64_t skip_rows = std::clamp<int64_t>(modes.skip_rows, 0, kMaxExtent);
  int64_t rows = skip_rows + height;
  if (three_d) {
    const int64_t image_rows =
        std::clamp<int64_t>(modes.image_height > 0 ? modes.image_height : height, height,
                            kMaxExtent) +
        skip_rows;
    rows = image_rows * (std::clamp<int64_t>(modes.skip_images, 0, kMaxExtent) + depth);
  }
  const long double bytes = static_cast<long double>(row_bytes) * static_cast<long double>(rows);
  if (bytes > static_cast<long double>(INT64_MAX)) return std::nullopt;
  return static_cast<uint64_t>(row_bytes * rows);
}

}  // namespace glpt::replay
