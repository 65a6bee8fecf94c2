// Spatial ordering of triangle soups before BLAS builds.
//
// lavapipe's BLAS builder (Mesa 25.0) splits the primitive *index* range and does not sort
// primitives itself, so a triangle soup in arbitrary order gives nodes spanning the whole mesh
// and traversal 10-100x slower. Sorting triangles by the Morton code of their centroid first
// makes index ranges spatially compact. Primitive ids reported by ray queries then refer to the
// sorted order, so the order is kept and all per-triangle shading data is stored in it.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace glpt::rt {

// Interleaves the low 21 bits of x, y and z (x in bit 0) into a 63-bit Morton code.
uint64_t morton_code(uint32_t x, uint32_t y, uint32_t z);

struct MortonOrder {
  // Sorted position -> original index (of the triangle or point): a permutation of 0..count-1.
  std::vector<uint32_t> permutation;
  // Morton code of each element in sorted order (non-decreasing).
  std::vector<uint64_t> sorted_codes;
};

// Orders points (e.g. centroids) along the Morton curve of their bounding box; same conventions
// as below.
MortonOrder morton_order_points(std::span<const glm::vec3> points);

// `positions` holds 3 vertices per triangle (a trailing partial triangle is ignored). Centroids
// are quantized to 21 bits per axis inside their bounding box; ties keep the original order, so
// the result is deterministic. Non-finite centroids sort as code 0.
MortonOrder morton_order_triangles(std::span<const glm::vec3> positions);

}  // namespace glpt::rt
