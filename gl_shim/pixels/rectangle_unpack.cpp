// SEAM: the interim unpacker of rectangle_unpack.hpp (replaced by branch `textures`' unpacker).
#include "gl_shim/pixels/rectangle_unpack.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"

namespace glpt {
namespace {

bool is_packed_type(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
      return true;
    default:
      return false;
  }
}

// Bytes of one element of an unpacked type; 0 for GL_BITMAP, packed and unknown types.
int element_bytes(GLenum type) {
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
    default:
      return 0;
  }
}

// For each element of a colour format's group, the RGBA component it is (4: luminance, which
// goes to R, G and B). Empty for non-colour formats.
struct Components {
  int count = 0;
  std::array<int, 4> component{};
};
constexpr int kLuminance = 4;

Components color_components(GLenum format) {
  switch (format) {
    case GL_RED:
      return {1, {0}};
    case GL_GREEN:
      return {1, {1}};
    case GL_BLUE:
      return {1, {2}};
    case GL_ALPHA:
      return {1, {3}};
    case GL_LUMINANCE:
      return {1, {kLuminance}};
    case GL_LUMINANCE_ALPHA:
      return {2, {kLuminance, 3}};
    case GL_RGB:
      return {3, {0, 1, 2}};
    case GL_BGR:
      return {3, {2, 1, 0}};
    case GL_RGBA:
      return {4, {0, 1, 2, 3}};
    case GL_BGRA:
      return {4, {2, 1, 0, 3}};
    case GL_ABGR_EXT:
      return {4, {3, 2, 1, 0}};
    default:
      return {};
  }
}

bool is_valid_format(GLenum format) {
  return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT ||
         color_components(format).count > 0;
}

bool is_valid_type(GLenum type) {
  return type == GL_BITMAP || element_bytes(type) > 0 || is_packed_type(type);
}

// One element as the unsigned bits it holds (byte-swapped when asked).
uint32_t load_bits(const uint8_t* p, int bytes, bool swap) {
  uint8_t b[4] = {0, 0, 0, 0};
  for (int i = 0; i < bytes; ++i) b[i] = p[swap ? bytes - 1 - i : i];
  uint32_t v = 0;
  std::memcpy(&v, b, 4);
  return bytes == 1 ? (v & 0xFFu) : bytes == 2 ? (v & 0xFFFFu) : v;
}

// An element converted to float the way Mesa unpacks pixels: unsigned c / (2^b - 1), signed
// max(c / (2^(b-1) - 1), -1), floats as they are.
float to_float(uint32_t bits, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
      return static_cast<float>(bits) / 255.0f;
    case GL_BYTE:
      return std::max(static_cast<float>(static_cast<int8_t>(bits)) / 127.0f, -1.0f);
    case GL_UNSIGNED_SHORT:
      return static_cast<float>(bits) / 65535.0f;
    case GL_SHORT:
      return std::max(static_cast<float>(static_cast<int16_t>(bits)) / 32767.0f, -1.0f);
    case GL_UNSIGNED_INT:
      return static_cast<float>(bits / 4294967295.0);
    case GL_INT:
      return std::max(static_cast<float>(static_cast<int32_t>(bits) / 2147483647.0), -1.0f);
    default: {
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
  }
}

// An index element: integers as they are (signed ones modulo 2^32), floats truncated.
uint32_t to_index(uint32_t bits, GLenum type) {
  switch (type) {
    case GL_BYTE:
      return static_cast<uint32_t>(static_cast<int32_t>(static_cast<int8_t>(bits)));
    case GL_SHORT:
      return static_cast<uint32_t>(static_cast<int32_t>(static_cast<int16_t>(bits)));
    case GL_FLOAT: {
      float f;
      std::memcpy(&f, &bits, 4);
      if (!std::isfinite(f)) return 0;
      return static_cast<uint32_t>(
          static_cast<int64_t>(std::clamp(f, -2147483648.0f, 4294967295.0f)));
    }
    default:
      return bits;
  }
}

// GL 1.5 3.6.4 "Unpacking": the address of element 0 of group (x, y).
class Layout {
 public:
  Layout(const PixelStoreModes& m, int32_t width, int elements, int bytes)
      : elements_(elements), bytes_(bytes) {
    const int64_t row = m.row_length > 0 ? m.row_length : width;
    const int64_t a = m.alignment;
    // Elements per row: GL's k, rounded up to whole alignment units when elements are smaller.
    const int64_t k =
        bytes >= a ? elements * row : (a / bytes) * ((bytes * elements * row + a - 1) / a);
    row_bytes_ = k * bytes;
    start_ = int64_t{m.skip_rows} * row_bytes_ + int64_t{m.skip_pixels} * elements * bytes;
  }
  size_t offset(int64_t x, int64_t y) const {
    return static_cast<size_t>(start_ + y * row_bytes_ + x * elements_ * bytes_);
  }

 private:
  int64_t elements_, bytes_, row_bytes_ = 0, start_ = 0;
};

}  // namespace

GLenum check_pixel_format_and_type(GLenum format, GLenum type) {
  if (!is_valid_format(format) || !is_valid_type(type)) return GL_INVALID_ENUM;
  if (type == GL_BITMAP)
    return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? GL_NO_ERROR : GL_INVALID_ENUM;
  if (!is_packed_type(type)) return GL_NO_ERROR;
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
      return format == GL_RGB ? GL_NO_ERROR : GL_INVALID_OPERATION;
    default:  // the four-component packed types
      return format == GL_RGBA || format == GL_BGRA || format == GL_ABGR_EXT ? GL_NO_ERROR
                                                                             : GL_INVALID_OPERATION;
  }
}

rec::PixelKind pixel_kind_of(GLenum format) {
  return format == GL_DEPTH_COMPONENT ? rec::PixelKind::kDepth
         : format == GL_STENCIL_INDEX ? rec::PixelKind::kStencil
                                      : rec::PixelKind::kColor;
}

bool unpack_image(const Context& ctx, int32_t width, int32_t height, GLenum format, GLenum type,
                  const void* pixels, rec::DrawPixels& out) {
  const rec::PixelTransferState& t = ctx.pixel_transfer;
  const int bytes = element_bytes(type);
  const Components colors = color_components(format);
  const bool depth = format == GL_DEPTH_COMPONENT, stencil = format == GL_STENCIL_INDEX;
  if (bytes == 0 || (colors.count == 0 && !depth && !stencil)) return false;
  if ((colors.count > 0 && t.map_color) || (stencil && t.map_stencil)) return false;
  const PixelStoreModes& modes = ctx.framebuffer.unpack;
  const int elements = colors.count > 0 ? colors.count : 1;
  const Layout layout(modes, width, elements, bytes);
  const auto* base = static_cast<const uint8_t*>(pixels);
  const size_t n = size_t(width) * size_t(height);
  auto element = [&](int32_t x, int32_t y, int e) {
    return load_bits(base + layout.offset(x, y) + size_t(e) * bytes, bytes, modes.swap_bytes);
  };
  out.kind = pixel_kind_of(format);
  out.width = static_cast<uint32_t>(width);
  out.height = static_cast<uint32_t>(height);
  if (colors.count > 0) {
    out.color.resize(n);
    for (int32_t y = 0; y < height; ++y) {
      for (int32_t x = 0; x < width; ++x) {
        glm::vec4 c(0.0f, 0.0f, 0.0f, 1.0f);
        for (int e = 0; e < colors.count; ++e) {
          const float v = to_float(element(x, y, e), type);
          if (colors.component[e] == kLuminance)
            c.r = c.g = c.b = v;
          else
            c[colors.component[e]] = v;
        }
        out.color[size_t(y) * width + x] = glm::clamp(c * t.scale + t.bias, 0.0f, 1.0f);
      }
    }
  } else if (depth) {
    out.depth.resize(n);
    for (int32_t y = 0; y < height; ++y)
      for (int32_t x = 0; x < width; ++x)
        out.depth[size_t(y) * width + x] =
            std::clamp(to_float(element(x, y, 0), type) * t.depth_scale + t.depth_bias, 0.0f, 1.0f);
  } else {
    out.stencil.resize(n);
    for (int32_t y = 0; y < height; ++y) {
      for (int32_t x = 0; x < width; ++x) {
        uint32_t s = to_index(element(x, y, 0), type);
        // INDEX_SHIFT: left for positive, right for negative; then INDEX_OFFSET (modulo 2^32).
        if (t.index_shift > 0)
          s = t.index_shift < 32 ? s << t.index_shift : 0u;
        else if (t.index_shift < 0)
          s = -t.index_shift < 32 ? s >> -t.index_shift : 0u;
        out.stencil[size_t(y) * width + x] = s + static_cast<uint32_t>(t.index_offset);
      }
    }
  }
  return true;
}

std::vector<uint8_t> unpack_bitmap(const PixelStoreModes& modes, int32_t width, int32_t height,
                                   const uint8_t* bitmap) {
  std::vector<uint8_t> bits(size_t(width) * size_t(height), 0);
  if (bitmap == nullptr) return bits;
  // GL 1.5 3.6.4: a row of a bitmap is ceil(l / 8) bytes rounded up to the alignment.
  const int64_t row = modes.row_length > 0 ? modes.row_length : width;
  const int64_t a = modes.alignment;
  const int64_t row_bytes = a * ((row + 8 * a - 1) / (8 * a));
  for (int32_t y = 0; y < height; ++y) {
    const uint8_t* line = bitmap + (int64_t{modes.skip_rows} + y) * row_bytes;
    for (int32_t x = 0; x < width; ++x) {
      const int64_t bit = int64_t{modes.skip_pixels} + x;
      const uint8_t byte = line[bit / 8];
      const uint8_t mask = modes.lsb_first ? uint8_t(1u << (bit % 8)) : uint8_t(0x80u >> (bit % 8));
      bits[size_t(y) * width + x] = (byte & mask) != 0 ? 1 : 0;
    }
  }
  return bits;
}

}  // namespace glpt
