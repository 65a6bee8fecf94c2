#include "replay/image_sizes.hpp"

#include "gl/gl_enums.h"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_layout.hpp"

namespace glpt::replay {

std::optional<uint64_t> image_bytes(int64_t width, int64_t height, int64_t depth, GLenum format,
                                    GLenum type, bool three_d, const PixelStoreModes& modes) {
  if (width < 0 || height < 0 || depth < 0 || width > INT32_MAX || height > INT32_MAX ||
      depth > INT32_MAX)
    return std::nullopt;
  if (check_format_and_type(format, type) != GL_NO_ERROR) return std::nullopt;
  ImageShape shape;
  shape.width = static_cast<int32_t>(width);
  shape.height = static_cast<int32_t>(height);
  shape.depth = static_cast<int32_t>(depth);
  shape.format = format;
  shape.type = type;
  if (shape.groups() == 0) return 0;
  if (shape.groups() > kMaxPixelGroups) return std::nullopt;
  const ClientImageLayout layout(modes, shape, three_d);
  if (!layout.valid()) return std::nullopt;
  return layout.end_offset();
}

}  // namespace glpt::replay
