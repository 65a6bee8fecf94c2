#include "rt_core/accel/morton_sort.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <limits>
#include <numeric>

namespace glpt::rt {
namespace {

// Spreads the low 21 bits of v so that bit i moves to bit 3i.
uint64_t spread_bits(uint32_t v) {
  uint64_t x = v & 0x1fffffu;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

bool is_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

uint64_t morton_code(uint32_t x, uint32_t y, uint32_t z) {
  return spread_bits(x) | spread_bits(y) << 1 | spread_bits(z) << 2;
}

MortonOrder morton_order_points(std::span<const glm::vec3> points) {
  glm::vec3 low(std::numeric_limits<float>::max());
  glm::vec3 high(std::numeric_limits<float>::lowest());
  for (const glm::vec3& point : points) {
    if (is_finite(point)) {
      low = glm::min(low, point);
      high = glm::max(high, point);
    }
  }
  constexpr float kCells = float((1u << 21) - 1);
  const glm::vec3 extent = high - low;
  // Flat axes (a planar mesh) get scale 0: every point lands in cell 0 on that axis.
  const glm::vec3 scale(extent.x > 0 ? kCells / extent.x : 0.0f,
                        extent.y > 0 ? kCells / extent.y : 0.0f,
                        extent.z > 0 ? kCells / extent.z : 0.0f);

  std::vector<uint64_t> codes(points.size(), 0);
  for (size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) continue;
    glm::vec3 cell = glm::clamp((points[i] - low) * scale, glm::vec3(0.0f), glm::vec3(kCells));
    codes[i] = morton_code(uint32_t(cell.x), uint32_t(cell.y), uint32_t(cell.z));
  }

  MortonOrder order;
  order.permutation.resize(points.size());
  std::iota(order.permutation.begin(), order.permutation.end(), 0u);
  std::sort(order.permutation.begin(), order.permutation.end(), [&](uint32_t a, uint32_t b) {
    return codes[a] != codes[b] ? codes[a] < codes[b] : a < b;
  });
  order.sorted_codes.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) order.sorted_codes[i] = codes[order.permutation[i]];
  return order;
}

MortonOrder morton_order_triangles(std::span<const glm::vec3> positions) {
  const size_t triangle_count = positions.size() / 3;
  std::vector<glm::vec3> centroids(triangle_count);
  for (size_t t = 0; t < triangle_count; ++t) {
    centroids[t] = (positions[3 * t] + positions[3 * t + 1] + positions[3 * t + 2]) / 3.0f;
  }
  return morton_order_points(centroids);
}

}  // namespace glpt::rt
