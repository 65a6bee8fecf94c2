#include "gl_shim/pixels/pixel_layout.hpp"

#include "gl/gl_enums.h"
#include "gl_shim/pixels/pixel_formats.hpp"

namespace glpt {

ClientImageLayout::ClientImageLayout(const PixelStoreModes& modes, const ImageShape& shape,
                                     bool three_d) {
  using Wide = __int128;
  constexpr Wide kLimit = Wide{1} << 62;
  bitmap_ = shape.type == GL_BITMAP;
  lsb_first_ = modes.lsb_first;
  swap_bytes_ = modes.swap_bytes;
  const int64_t element_bytes = type_bytes(shape.type);
  group_bytes_ = bitmap_ ? 0
                         : size_t(is_packed_type(shape.type)
                                      ? element_bytes
                                      : element_bytes * format_components(shape.format));
  skip_pixels_ = modes.skip_pixels;
  skip_rows_ = modes.skip_rows;
  const int64_t alignment = modes.alignment > 0 ? modes.alignment : 1;
  const Wide row_groups = modes.row_length > 0 ? modes.row_length : shape.width;
  // GL 1.5 3.6.4: rows start at multiples of the alignment (bitmaps: in bytes of 8 groups).
  const Wide row_bytes =
      bitmap_ ? (row_groups + 8 * alignment - 1) / (8 * alignment) * alignment
              : (row_groups * Wide(group_bytes_) + alignment - 1) / alignment * alignment;
  Wide image_bytes = 0;
  if (three_d) {
    skip_images_ = modes.skip_images;
    const Wide rows = modes.image_height > 0 ? modes.image_height : shape.height;
    image_bytes = rows * row_bytes;
  }
  Wide end = 0;
  if (shape.width > 0 && shape.height > 0 && shape.depth > 0) {
    const Wide last_row = (skip_images_ + Wide(shape.depth) - 1) * image_bytes +
                          (skip_rows_ + Wide(shape.height) - 1) * row_bytes;
    end = bitmap_ ? last_row + (skip_pixels_ + Wide(shape.width) - 1) / 8 + 1
                  : last_row + (skip_pixels_ + Wide(shape.width)) * Wide(group_bytes_);
  }
  valid_ = row_bytes < kLimit && image_bytes < kLimit && end < kLimit;
  if (!valid_) return;
  row_stride_ = int64_t(row_bytes);
  image_stride_ = int64_t(image_bytes);
  end_ = int64_t(end);
}

}  // namespace glpt
