// Conversion of a Geometry into the records the path tracer reads (shaders/shared_types.h), in the
// Morton-sorted triangle order its BLAS is built in: positions (per shape) and shading data
// (normals, colours, materials: per shading of that shape).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rt_core/scene/trace_scene.hpp"
#include "shared_types.h"

namespace glpt::rt {

// `index`: the material's own index in its geometry's table (the back material of faces seen from
// behind, unless Material::back names another).
gpu::GpuMaterial pack_material(const Material& material, uint32_t index);

// How many GpuMaterial records pack_shading writes: at least one, so out-of-range or missing
// material ids always have something to point at.
size_t packed_material_count(const Geometry& geometry);

// Writes 3 * triangle_order.size() positions.
void pack_positions(const Geometry& geometry, std::span<const uint32_t> triangle_order,
                    std::span<gpu::GpuPosition> positions);

// Writes 3 * triangle_order.size() vertices and packed_material_count() materials. Vertex
// attributes the geometry lacks get GL's defaults (normal +Z, colour white); material ids out of
// range become 0.
void pack_shading(const Geometry& geometry, std::span<const uint32_t> triangle_order,
                  std::span<gpu::ShadingVertex> vertices, std::span<gpu::GpuMaterial> materials);

// One triangle of a geometry that emits light (GL emission of a lit material), object space.
struct EmitterTriangle {
  glm::vec3 positions[3];
  glm::vec3 emission[3];  // per vertex: the material's, or the colour under GL_EMISSION tracking
};

// Every triangle of `geometry` in `triangle_order` (its BLAS primitive order) when at least one
// of them emits, so that BLAS primitive p is element p; empty when none does. Non-finite or
// negative emission counts as none.
std::vector<EmitterTriangle> emitter_triangles(const Geometry& geometry,
                                               std::span<const uint32_t> triangle_order);

}  // namespace glpt::rt
