// Implementation-dependent values of glpt's fixed-function pipeline, chosen to be Mesa
// llvmpipe's (Mesa 25.0.7, measured through OSMesa) so that programs that size points and lines
// by these limits behave as they do on Mesa.
#pragma once

#include "rt_core/record/gl_state.hpp"

namespace glpt {

inline constexpr float kAliasedPointSizeRange[2] = {1.0f, 256.0f};  // GL_ALIASED_POINT_SIZE_RANGE
inline constexpr float kSmoothPointSizeRange[2] = {1.0f, 256.0f};   // GL_SMOOTH_POINT_SIZE_RANGE
inline constexpr float kPointSizeGranularity = 0.1f;  // GL_SMOOTH_POINT_SIZE_GRANULARITY
inline constexpr float kAliasedLineWidthRange[2] = {1.0f, 255.0f};  // GL_ALIASED_LINE_WIDTH_RANGE
inline constexpr float kSmoothLineWidthRange[2] = {1.0f, 255.0f};   // GL_SMOOTH_LINE_WIDTH_RANGE
inline constexpr float kLineWidthGranularity = 0.1f;  // GL_SMOOTH_LINE_WIDTH_GRANULARITY
inline constexpr int kStencilBits = 8;                // GL_STENCIL_BITS

// GL's initial rasterization and fragment state (rec::RasterState's defaults) with the
// implementation-dependent initial values Mesa uses: GL_POINT_SIZE_MAX is the largest point size,
// and the stencil masks are all ones of the stencil buffer's bits.
inline rec::RasterState initial_raster_state() {
  rec::RasterState s;
  s.primitive.point_size_max = kAliasedPointSizeRange[1];
  s.ops.stencil_value_mask = (1u << kStencilBits) - 1;
  s.ops.stencil_write_mask = (1u << kStencilBits) - 1;
  return s;
}

}  // namespace glpt
