#include "rt_core/scene/shading_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace glpt::rt {

// The shader switches on these numbers (GpuMaterial::params.z).
static_assert(static_cast<uint32_t>(ColorSource::kNone) == GLPT_COLOR_SOURCE_NONE);
static_assert(static_cast<uint32_t>(ColorSource::kAmbientAndDiffuse) ==
              GLPT_COLOR_SOURCE_AMBIENT_AND_DIFFUSE);
static_assert(static_cast<uint32_t>(ColorSource::kDiffuse) == GLPT_COLOR_SOURCE_DIFFUSE);
static_assert(static_cast<uint32_t>(ColorSource::kAmbient) == GLPT_COLOR_SOURCE_AMBIENT);
static_assert(static_cast<uint32_t>(ColorSource::kEmission) == GLPT_COLOR_SOURCE_EMISSION);
static_assert(static_cast<uint32_t>(ColorSource::kSpecular) == GLPT_COLOR_SOURCE_SPECULAR);

gpu::GpuMaterial pack_material(const Material& material, uint32_t index) {
  gpu::GpuMaterial packed{};
  packed.ambient = material.ambient;
  packed.diffuse = material.diffuse;
  packed.specular = material.specular;
  packed.emission = material.emission;
  uint32_t shininess_bits;
  std::memcpy(&shininess_bits, &material.shininess, sizeof shininess_bits);
  packed.params = glm::uvec4(shininess_bits, material.lit ? 1u : 0u,
                             static_cast<uint32_t>(material.color_source),
                             material.back == Material::kSameForBack ? index : material.back);
  return packed;
}

size_t packed_material_count(const Geometry& geometry) {
  return geometry.materials.empty() ? 1 : geometry.materials.size();
}

void pack_positions(const Geometry& geometry, std::span<const uint32_t> triangle_order,
                    std::span<gpu::GpuPosition> positions) {
  for (size_t sorted = 0; sorted < triangle_order.size(); ++sorted) {
    const size_t triangle = triangle_order[sorted];
    for (size_t corner = 0; corner < 3; ++corner)
      positions[3 * sorted + corner].position =
          glm::vec4(geometry.positions[3 * triangle + corner], 0.0f);
  }
}

void pack_shading(const Geometry& geometry, std::span<const uint32_t> triangle_order,
                  std::span<gpu::ShadingVertex> vertices, std::span<gpu::GpuMaterial> materials) {
  const size_t material_count = packed_material_count(geometry);
  for (size_t i = 0; i < material_count; ++i) {
    materials[i] = pack_material(geometry.materials.empty() ? Material{} : geometry.materials[i],
                                 static_cast<uint32_t>(i));
  }

  const glm::vec4 kDefaultColor(1.0f);  // GL's initial current colour
  for (size_t sorted = 0; sorted < triangle_order.size(); ++sorted) {
    const size_t triangle = triangle_order[sorted];
    uint32_t material_id =
        triangle < geometry.material_ids.size() ? geometry.material_ids[triangle] : 0;
    if (material_id >= material_count) material_id = 0;
    for (size_t corner = 0; corner < 3; ++corner) {
      const size_t source = 3 * triangle + corner;
      const glm::vec3 normal =
          source < geometry.normals.size() ? geometry.normals[source] : glm::vec3(0, 0, 1);
      const glm::vec4 color =
          source < geometry.colors.size() ? geometry.colors[source] : kDefaultColor;
      gpu::ShadingVertex& out = vertices[3 * sorted + corner];
      out.normal = glm::vec4(normal, static_cast<float>(material_id));
      out.color = color;
      for (size_t unit = 0; unit < GLPT_TRACE_UNITS; ++unit)
        out.texcoords[unit] = source < geometry.texcoords[unit].size()
                                  ? geometry.texcoords[unit][source]
                                  : glm::vec4(0, 0, 0, 1);
    }
  }
}

namespace {

glm::vec3 valid_emission(glm::vec3 e) {
  for (int c = 0; c < 3; ++c) e[c] = std::isfinite(e[c]) ? std::max(e[c], 0.0f) : 0.0f;
  return e;
}

}  // namespace

std::vector<EmitterTriangle> emitter_triangles(const Geometry& geometry,
                                               std::span<const uint32_t> triangle_order) {
  // Lit materials only: with lighting off GL has no emission (the unlit colour is what
  // GLPT_UNLIT=emit turns into light, found by bounces).
  auto emission_of = [&](size_t triangle, size_t corner) {
    const uint32_t id =
        triangle < geometry.material_ids.size() ? geometry.material_ids[triangle] : 0;
    if (id >= geometry.materials.size()) return glm::vec3(0.0f);
    const Material& material = geometry.materials[id];
    if (!material.lit) return glm::vec3(0.0f);
    if (material.color_source == ColorSource::kEmission) {
      const size_t source = 3 * triangle + corner;
      return valid_emission(source < geometry.colors.size() ? glm::vec3(geometry.colors[source])
                                                            : glm::vec3(1.0f));
    }
    return valid_emission(glm::vec3(material.emission));
  };
  const bool any_material_emits = std::any_of(
      geometry.materials.begin(), geometry.materials.end(), [](const Material& material) {
        return material.lit && (material.color_source == ColorSource::kEmission ||
                                glm::vec3(material.emission) != glm::vec3(0.0f));
      });
  std::vector<EmitterTriangle> triangles;
  if (!any_material_emits) return triangles;
  triangles.resize(triangle_order.size());
  bool emits = false;
  for (size_t sorted = 0; sorted < triangle_order.size(); ++sorted) {
    const size_t triangle = triangle_order[sorted];
    EmitterTriangle& out = triangles[sorted];
    for (size_t corner = 0; corner < 3; ++corner) {
      out.positions[corner] = geometry.positions[3 * triangle + corner];
      out.emission[corner] = emission_of(triangle, corner);
      emits = emits || out.emission[corner] != glm::vec3(0.0f);
    }
  }
  if (!emits) triangles.clear();
  return triangles;
}

}  // namespace glpt::rt
