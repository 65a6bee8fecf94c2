// glBegin/glEnd in progress: the vertices of the primitive being specified, each with the
// attributes that were current at its glVertex (GL 1.5 2.6, 2.7).
#pragma once

#include <array>
#include <cstdint>

#include "gl_shim/gl_types.h"
#include "rt_core/record/frame_record.hpp"

namespace glpt {

struct VertexAssembly {
  bool inside = false;
  rec::StateId state = 0;     // the snapshot the primitive is drawn with (taken at glBegin)
  uint8_t texture_units = 0;  // bit u: unit u samples a texture, so its coordinates are recorded
  // glMaterial was called inside this primitive: every vertex records its material. The
  // vertices before the first call get the material at glBegin.
  bool per_vertex_material = false;
  std::array<rec::Material, 2> material_at_begin{};
  bool edge_flag_given = false;  // glEdgeFlag was called inside this primitive
  rec::VertexData vertices;       // one value per vertex for every recorded attribute
  uint64_t dropped_vertices = 0;  // beyond the per-primitive limit
};

}  // namespace glpt
