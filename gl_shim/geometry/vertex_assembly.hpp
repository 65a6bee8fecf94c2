// glBegin/glEnd: collects the vertices of the primitive being specified, with the attributes
// that were current at each glVertex.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "gl_shim/geometry/triangulate.hpp"
#include "gl_shim/gl_types.h"
#include "rt_core/frame.hpp"

namespace glpt {

struct CapturedVertex {
  glm::vec3 position;  // object space (x/w, y/w, z/w)
  glm::vec3 normal;    // object space
  glm::vec4 color;
  uint32_t material;  // index into VertexAssembly::materials
};

struct VertexAssembly {
  bool inside = false;
  GLenum mode = 0;
  std::vector<CapturedVertex> vertices;
  // Materials in effect during this primitive (glMaterial may change between vertices).
  std::vector<rt::Material> materials;
  uint64_t material_version_seen = ~uint64_t{0};
  uint64_t dropped_vertices = 0;           // beyond the per-primitive limit
  std::vector<TriangleIndices> triangles;  // scratch for glEnd, kept to avoid reallocating

  void begin(GLenum primitive_mode) {
    inside = true;
    mode = primitive_mode;
    vertices.clear();
    materials.clear();
    material_version_seen = ~uint64_t{0};
  }
};

}  // namespace glpt
