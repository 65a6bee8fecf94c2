// Values -> client memory (GL 1.5 4.3.2 "Conversion of RGBA values", "Final conversion",
// "Placement in client memory"): what glReadPixels, glGetTexImage and glGetPolygonStipple write.
//
// Values are given in group order (x fastest, then y bottom to top, then z), already through pixel
// transfer. `written` (optional, one byte per group): groups whose byte is 0 are left untouched in
// client memory (pixels outside the drawable, which GL leaves undefined; Mesa does not write them).
// The format/type pair must have passed check_format_and_type and the layout must be valid.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl_shim/pixels/pixel_layout.hpp"
#include "gl_shim/state/framebuffer_state.hpp"

namespace glpt {

struct PackTarget {
  const PixelStoreModes& modes;
  ImageShape shape;
  bool three_d = false;  // IMAGE_HEIGHT / SKIP_IMAGES apply
  void* data = nullptr;
  const uint8_t* written = nullptr;
};

// How a LUMINANCE group is formed from RGBA.
enum class LuminanceFrom : uint8_t {
  kSumRgb,  // glReadPixels: L = R + G + B, clamped to [0, 1] (GL 1.5 4.3.2)
  kRed      // glGetTexImage: L = R (GL 1.5 6.1.4, table 6.1; Mesa)
};

// Colour formats: components in [0, 1] converted as Mesa does (unsigned: round(c * (2^b - 1)),
// signed: round(c * (2^(b-1) - 1)), packed fields likewise, nearest-even in float arithmetic).
void pack_color(const PackTarget& dst, const std::vector<glm::vec4>& rgba, LuminanceFrom luminance);

// DEPTH_COMPONENT: depth in [0, 1] as unsigned/signed normalized integers or floats.
void pack_depth(const PackTarget& dst, const std::vector<float>& depth);

// STENCIL_INDEX / COLOR_INDEX: integer values masked to the type's bits (signed types keep the
// bits below the sign, as Mesa does), floats as they are, GL_BITMAP as the low bit.
// DEPTH_STENCIL / GL_UNSIGNED_INT_24_8_EXT: the packed words as they are.
void pack_indices(const PackTarget& dst, const std::vector<uint32_t>& values);

// A bitmap of width * height bytes (non-zero = set) packed as GL_COLOR_INDEX / GL_BITMAP.
void pack_bitmap(const PixelStoreModes& modes, int32_t width, int32_t height,
                 const std::vector<uint8_t>& bits, void* data);

}  // namespace glpt
