#include "heatmap.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace glpt::diff {
namespace {

// Control points of the colour map, evenly spaced over [0, 1], interpolated linearly. Chosen by
// hand for rising luminance (like the magma map the FLIP tool uses), not copied from it.
constexpr std::array<std::array<float, 3>, 6> kStops = {{
    {0.00f, 0.00f, 0.02f},
    {0.23f, 0.06f, 0.43f},
    {0.55f, 0.13f, 0.50f},
    {0.87f, 0.29f, 0.36f},
    {0.99f, 0.62f, 0.27f},
    {0.99f, 0.96f, 0.72f},
}};

}  // namespace

void heatmap_color(float error, uint8_t rgb[3]) {
  const float e = std::isnan(error) ? 1.0f : std::clamp(error, 0.0f, 1.0f);
  const float position = e * static_cast<float>(kStops.size() - 1);
  const size_t i = std::min(static_cast<size_t>(position), kStops.size() - 2);
  const float t = position - static_cast<float>(i);
  for (int c = 0; c < 3; ++c) {
    const float v = kStops[i][c] + t * (kStops[i + 1][c] - kStops[i][c]);
    rgb[c] = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  }
}

std::vector<uint8_t> heatmap_rgba8(const FlipResult& result) {
  std::vector<uint8_t> rgba(result.error.size() * 4);
  for (size_t i = 0; i < result.error.size(); ++i) {
    heatmap_color(result.error[i], &rgba[i * 4]);
    rgba[i * 4 + 3] = 255;
  }
  return rgba;
}

}  // namespace glpt::diff
