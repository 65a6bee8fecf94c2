#include "rt_core/accel/morton_sort.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>
#include <random>
#include <vector>

#include "rt_core/scene/shading_data.hpp"

namespace glpt::rt {
namespace {

uint64_t naive_morton(uint32_t x, uint32_t y, uint32_t z) {
  uint64_t code = 0;
  for (int bit = 0; bit < 21; ++bit) {
    code |= uint64_t((x >> bit) & 1) << (3 * bit);
    code |= uint64_t((y >> bit) & 1) << (3 * bit + 1);
    code |= uint64_t((z >> bit) & 1) << (3 * bit + 2);
  }
  return code;
}

// A grid of small triangles in random order: what an unsorted triangle soup looks like.
std::vector<glm::vec3> shuffled_grid_triangles(int n, uint32_t seed) {
  std::vector<glm::vec3> positions;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      glm::vec3 base(float(i), float(j), float((i * 7 + j * 3) % 5));
      positions.push_back(base);
      positions.push_back(base + glm::vec3(0.5f, 0.0f, 0.0f));
      positions.push_back(base + glm::vec3(0.0f, 0.5f, 0.0f));
    }
  }
  std::vector<int> order(positions.size() / 3);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  std::vector<glm::vec3> shuffled;
  for (int t : order) shuffled.insert(shuffled.end(), &positions[3 * t], &positions[3 * t] + 3);
  return shuffled;
}

glm::vec3 centroid(const std::vector<glm::vec3>& positions, size_t triangle) {
  return (positions[3 * triangle] + positions[3 * triangle + 1] + positions[3 * triangle + 2]) /
         3.0f;
}

TEST(MortonSort, CodeInterleavesBits) {
  std::mt19937 random(1);
  for (int i = 0; i < 1000; ++i) {
    uint32_t x = random() & 0x1fffff, y = random() & 0x1fffff, z = random() & 0x1fffff;
    ASSERT_EQ(morton_code(x, y, z), naive_morton(x, y, z)) << x << " " << y << " " << z;
  }
  EXPECT_EQ(morton_code(1, 0, 0), 1u);
  EXPECT_EQ(morton_code(0, 1, 0), 2u);
  EXPECT_EQ(morton_code(0, 0, 1), 4u);
}

TEST(MortonSort, OrderIsAPermutationWithAscendingCodes) {
  const std::vector<glm::vec3> positions = shuffled_grid_triangles(40, 7);
  const size_t triangle_count = positions.size() / 3;
  const MortonOrder order = morton_order_triangles(positions);

  ASSERT_EQ(order.permutation.size(), triangle_count);
  ASSERT_EQ(order.sorted_codes.size(), triangle_count);
  std::vector<uint32_t> sorted_indices = order.permutation;
  std::sort(sorted_indices.begin(), sorted_indices.end());
  for (size_t i = 0; i < triangle_count; ++i) ASSERT_EQ(sorted_indices[i], i);
  EXPECT_TRUE(std::is_sorted(order.sorted_codes.begin(), order.sorted_codes.end()));
}

TEST(MortonSort, SortedOrderIsSpatiallyCoherent) {
  const std::vector<glm::vec3> positions = shuffled_grid_triangles(40, 11);
  const MortonOrder order = morton_order_triangles(positions);
  auto mean_step = [&](auto triangle_at) {
    double total = 0;
    for (size_t i = 1; i < order.permutation.size(); ++i) {
      total += glm::distance(centroid(positions, triangle_at(i)),
                             centroid(positions, triangle_at(i - 1)));
    }
    return total / double(order.permutation.size() - 1);
  };
  const double unsorted = mean_step([](size_t i) { return i; });
  const double sorted = mean_step([&](size_t i) { return order.permutation[i]; });
  EXPECT_LT(sorted * 5, unsorted) << "sorted " << sorted << " unsorted " << unsorted;
}

TEST(MortonSort, HandlesEmptyFlatAndNonFiniteInput) {
  EXPECT_TRUE(morton_order_triangles({}).permutation.empty());

  // All centroids equal: ties keep the original order.
  std::vector<glm::vec3> same(12, glm::vec3(1.0f));
  EXPECT_EQ(morton_order_triangles(same).permutation, (std::vector<uint32_t>{0, 1, 2, 3}));

  std::vector<glm::vec3> with_nan = shuffled_grid_triangles(3, 1);
  with_nan[4].x = std::numeric_limits<float>::quiet_NaN();
  const MortonOrder order = morton_order_triangles(with_nan);
  EXPECT_EQ(order.permutation.size(), 9u);
  EXPECT_TRUE(std::is_sorted(order.sorted_codes.begin(), order.sorted_codes.end()));
}

TEST(MortonSort, PackedGeometryKeepsEachTrianglesData) {
  Geometry geometry;
  geometry.positions = shuffled_grid_triangles(10, 3);
  const size_t triangle_count = geometry.triangle_count();
  geometry.materials.resize(3);
  geometry.materials[1].diffuse = glm::vec4(0.1f, 0.2f, 0.3f, 1.0f);
  geometry.materials[2].lit = false;
  for (size_t v = 0; v < geometry.positions.size(); ++v) {
    geometry.normals.push_back(glm::vec3(0.0f, float(v), 1.0f));
    geometry.colors.push_back(glm::vec4(float(v) / 1000.0f, 0.5f, 0.25f, 1.0f));
  }
  for (size_t t = 0; t < triangle_count; ++t) geometry.material_ids.push_back(uint32_t(t % 3));

  const MortonOrder order = morton_order_triangles(geometry.positions);
  std::vector<gpu::GpuPosition> positions(3 * triangle_count);
  std::vector<gpu::ShadingVertex> vertices(3 * triangle_count);
  std::vector<gpu::GpuMaterial> materials(packed_material_count(geometry));
  pack_positions(geometry, order.permutation, positions);
  pack_shading(geometry, order.permutation, vertices, materials);

  for (size_t sorted = 0; sorted < triangle_count; ++sorted) {
    const size_t original = order.permutation[sorted];
    for (size_t corner = 0; corner < 3; ++corner) {
      const gpu::ShadingVertex& vertex = vertices[3 * sorted + corner];
      const size_t source = 3 * original + corner;
      ASSERT_EQ(glm::vec3(positions[3 * sorted + corner].position), geometry.positions[source]);
      ASSERT_EQ(vertex.normal.w, float(geometry.material_ids[original]));
      ASSERT_EQ(glm::vec3(vertex.normal), geometry.normals[source]);
      ASSERT_EQ(vertex.color, geometry.colors[source]);
    }
  }
  ASSERT_EQ(materials.size(), 3u);
  EXPECT_EQ(materials[1].diffuse, geometry.materials[1].diffuse);
  EXPECT_EQ(materials[2].params.y, 0u);  // unlit
  EXPECT_EQ(materials[0].params.y, 1u);
}

TEST(MortonSort, PackingFillsMissingAttributesWithGlDefaults) {
  Geometry geometry;
  geometry.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  geometry.material_ids = {5};  // out of range: falls back to material 0
  const std::vector<uint32_t> order = {0};
  std::vector<gpu::ShadingVertex> vertices(3);
  std::vector<gpu::GpuMaterial> materials(packed_material_count(geometry));
  ASSERT_EQ(materials.size(), 1u);  // a default material even when none is given
  pack_shading(geometry, order, vertices, materials);
  for (const auto& vertex : vertices) {
    EXPECT_EQ(vertex.normal.w, 0.0f);
    EXPECT_EQ(glm::vec3(vertex.normal), glm::vec3(0, 0, 1));
    EXPECT_EQ(vertex.color, glm::vec4(1.0f));
  }
  EXPECT_EQ(materials[0].diffuse, Material{}.diffuse);
}

TEST(MortonSort, PackingKeepsEveryTextureUnitsCoordinates) {
  Geometry geometry;
  geometry.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  geometry.texcoords[0] = {{0.1f, 0.2f, 0, 1}, {0.3f, 0.4f, 0, 1}, {0.5f, 0.6f, 0, 1}};
  geometry.texcoords[1] = {{7, 8, 0, 1}, {9, 10, 0, 1}, {11, 12, 0, 1}};
  geometry.texcoords[3] = {{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}};  // unit 2 untextured
  const std::vector<uint32_t> order = {0};
  std::vector<gpu::ShadingVertex> vertices(3);
  std::vector<gpu::GpuMaterial> materials(packed_material_count(geometry));
  pack_shading(geometry, order, vertices, materials);
  for (size_t corner = 0; corner < 3; ++corner) {
    EXPECT_EQ(vertices[corner].texcoords[0], geometry.texcoords[0][corner]);
    EXPECT_EQ(vertices[corner].texcoords[1], geometry.texcoords[1][corner]);
    EXPECT_EQ(vertices[corner].texcoords[2], glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(vertices[corner].texcoords[3], geometry.texcoords[3][corner]);
  }
}

// Emitter triangles: a geometry of three triangles with materials 0 (not emitting), 1 (emission
// 0.5, lit) and 2 (emission through GL_COLOR_MATERIAL's GL_EMISSION: the vertex colours).
Geometry emitting_geometry() {
  Geometry geometry;
  for (int t = 0; t < 3; ++t)
    for (const glm::vec3 corner : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)})
      geometry.positions.push_back(corner + glm::vec3(float(t), 0, 0));
  for (size_t v = 0; v < geometry.positions.size(); ++v)
    geometry.colors.push_back(glm::vec4(float(v) / 10.0f, 0.0f, 1.0f, 1.0f));
  geometry.materials.resize(3);
  geometry.materials[1].emission = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  geometry.materials[2].color_source = ColorSource::kEmission;
  geometry.material_ids = {0, 1, 2};
  return geometry;
}

TEST(EmitterTriangles, EveryTriangleInBlasOrderWithItsEmission) {
  const Geometry geometry = emitting_geometry();
  const std::vector<uint32_t> order = {2, 0, 1};  // BLAS primitive p is triangle order[p]
  const std::vector<EmitterTriangle> emitters = emitter_triangles(geometry, order);
  ASSERT_EQ(emitters.size(), 3u);
  for (size_t p = 0; p < 3; ++p)
    for (size_t corner = 0; corner < 3; ++corner)
      EXPECT_EQ(emitters[p].positions[corner], geometry.positions[3 * order[p] + corner]);
  EXPECT_EQ(emitters[1].emission[0], glm::vec3(0.0f));  // triangle 0: material 0 emits nothing
  EXPECT_EQ(emitters[2].emission[1], glm::vec3(0.5f));  // triangle 1: the material's emission
  EXPECT_EQ(emitters[0].emission[2], glm::vec3(geometry.colors[8]));  // triangle 2: the colour
}

TEST(EmitterTriangles, NoneWhereNothingEmitsOrLightingIsOffOrEmissionIsNotFinite) {
  const std::vector<uint32_t> order = {0, 1, 2};
  Geometry dark = emitting_geometry();
  dark.materials[1].emission = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  dark.materials[2].color_source = ColorSource::kNone;
  EXPECT_TRUE(emitter_triangles(dark, order).empty());
  // GL has no emission with lighting off: an unlit draw's colour is not a light source.
  Geometry unlit = emitting_geometry();
  for (Material& m : unlit.materials) m.lit = false;
  EXPECT_TRUE(emitter_triangles(unlit, order).empty());
  // NaN, infinite and negative emission count as none.
  Geometry bad = dark;
  bad.materials[1].emission = glm::vec4(std::nanf(""), INFINITY, -1.0f, 1.0f);
  EXPECT_TRUE(emitter_triangles(bad, order).empty());
}

}  // namespace
}  // namespace glpt::rt
