#include "gl_shim/pixels/list_images.hpp"

#include <algorithm>
#include <cstring>
#include <new>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/pixels/pixel_formats.hpp"
#include "gl_shim/pixels/pixel_pack.hpp"
#include "gl_shim/pixels/pixel_transfer.hpp"
#include "gl_shim/pixels/pixel_unpack.hpp"

namespace glpt {

PixelStoreModes default_unpack_modes() {
  PixelStoreModes m;
  m.alignment = 1;
  return m;
}

namespace {

ClientImageCopy copy_image(const PixelStoreModes& modes, const ImageShape& shape, bool three_d,
                           const void* data) {
  ClientImageCopy copy;
  if (data == nullptr || check_format_and_type(shape.format, shape.type) != GL_NO_ERROR)
    return copy;
  const size_t groups = shape.groups();
  if (groups > kMaxPixelGroups) return copy;
  const ClientImageLayout source(modes, shape, three_d);
  const PixelStoreModes defaults = default_unpack_modes();
  const ClientImageLayout stored(defaults, shape, three_d);
  // A list record holds at most 2 GiB (its offsets are 32-bit).
  if (!source.valid() || !stored.valid() || stored.end_offset() > (size_t{1} << 31)) return copy;
  copy.present = true;
  if (groups == 0) return copy;
  copy.bytes.resize(stored.end_offset());
  if (source.is_bitmap()) {
    // Bits are re-read in GL's order (LSB_FIRST, SKIP_PIXELS) and stored most significant first.
    const std::vector<uint32_t> bits =
        unpack_indices_raw(UnpackSource{modes, shape, three_d, data});
    pack_indices(PackTarget{defaults, shape, three_d, copy.bytes.data(), nullptr}, bits);
    return copy;
  }
  // Whole rows at a time: groups are contiguous within a row in both layouts.
  const auto* src = static_cast<const uint8_t*>(data);
  const size_t row_bytes = size_t(shape.width) * source.group_bytes();
  for (int32_t z = 0; z < shape.depth; ++z) {
    for (int32_t y = 0; y < shape.height; ++y) {
      std::memcpy(copy.bytes.data() + stored.group_offset(0, y, z),
                  src + source.group_offset(0, y, z), row_bytes);
    }
  }
  // The copy is in the client's byte order; the default modes do not swap, so swap now.
  const int element = type_bytes(shape.type);
  if (source.swap_bytes() && element > 1) {
    for (size_t i = 0; i + size_t(element) <= copy.bytes.size(); i += size_t(element)) {
      std::reverse(copy.bytes.begin() + std::ptrdiff_t(i),
                   copy.bytes.begin() + std::ptrdiff_t(i) + element);
    }
  }
  return copy;
}

}  // namespace

ClientImageCopy copy_client_image(const PixelStoreModes& modes, const ImageShape& shape,
                                  bool three_d, const void* data) {
  try {
    return copy_image(modes, shape, three_d, data);
  } catch (const std::bad_alloc&) {
    return ClientImageCopy{};  // not recorded: replayed with no data
  }
}

DefaultUnpackModes::DefaultUnpackModes(Context& ctx) : ctx_(ctx), saved_(ctx.framebuffer.unpack) {
  ctx.framebuffer.unpack = default_unpack_modes();
}

DefaultUnpackModes::~DefaultUnpackModes() { ctx_.framebuffer.unpack = saved_; }

uint32_t pixel_map_values_to_record(GLsizei mapsize) {
  return mapsize >= 1 && mapsize <= kMaxPixelMapTable ? uint32_t(mapsize) : 0u;
}

bool is_proxy_texture_target(GLenum target) {
  return target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D ||
         target == GL_PROXY_TEXTURE_3D || target == GL_PROXY_TEXTURE_CUBE_MAP ||
         target == GL_PROXY_TEXTURE_RECTANGLE_ARB;
}

}  // namespace glpt
