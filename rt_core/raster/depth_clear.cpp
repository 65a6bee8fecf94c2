#include "rt_core/raster/depth_clear.hpp"

#include <algorithm>
#include <cmath>

namespace glpt::rt {
namespace {

constexpr uint32_t kMaxZ24 = 0xFFFFFF;

uint32_t as_attachment_clear(float depth) {  // util_pack_z (lrint rounds half to even)
  if (depth <= 0.0f) return 0;
  if (depth >= 1.0f) return kMaxZ24;
  return static_cast<uint32_t>(std::lrint(static_cast<double>(depth) * kMaxZ24));
}

uint32_t as_fragment_depth(float depth) {  // llvmpipe: float product, rounded half to even
  const float product = std::clamp(depth, 0.0f, 1.0f) * 16777215.0f;
  return static_cast<uint32_t>(std::nearbyint(product));
}

// The float nearest z24 / 0xFFFFFF, or a neighbour, that `convert` maps to z24 exactly.
template <typename Convert>
float depth_converting_to(uint32_t z24, Convert convert) {
  z24 = std::min(z24, kMaxZ24);
  const float nearest = static_cast<float>(static_cast<double>(z24) / kMaxZ24);
  float below = nearest, above = nearest;
  for (int step = 0; step < 4; ++step) {
    if (convert(below) == z24) return below;
    if (convert(above) == z24) return above;
    below = std::nextafter(below, 0.0f);
    above = std::nextafter(above, 1.0f);
  }
  return nearest;  // (not reached for 24-bit values: a float has 24 bits of mantissa)
}

}  // namespace

uint32_t mesa_clear_z24(double depth, bool whole_buffer) {
  depth = std::clamp(depth, 0.0, 1.0);
  if (whole_buffer) return static_cast<uint32_t>(std::lrint(depth * kMaxZ24));
  const auto ndc = static_cast<float>(depth * 2.0 - 1.0);
  const float half = ndc * 0.5f;  // two float roundings, as llvmpipe's viewport transform
  const float window = half + 0.5f;
  return as_fragment_depth(window);
}

float attachment_clear_depth(uint32_t z24) { return depth_converting_to(z24, as_attachment_clear); }

float fragment_depth(uint32_t z24) { return depth_converting_to(z24, as_fragment_depth); }

}  // namespace glpt::rt
