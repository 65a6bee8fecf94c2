// glBegin/glEnd in progress: the vertices of the primitive being specified, each with the
// attributes that were current at its glVertex (GL 1.5 2.6, 2.7).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

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
  // A glColor inside glBegin/glEnd whose GL_COLOR_MATERIAL update of ctx.lighting.material is
  // still to be made (flush_color_material): nothing reads the material before glEnd unless
  // glMaterial is called, and immediate mode calls glColor for every vertex.
  bool color_material_pending = false;
  std::array<rec::Material, 2> material_at_begin{};
  // The material fields glMaterial set inside this primitive (material_field_bit).
  uint16_t material_fields_set = 0;
  // The first glEdgeFlag inside this primitive: how many vertices preceded it, and the current
  // edge flag before it (selection and feedback draw the vertices before it on their own, as
  // Mesa's immediate mode does when a new attribute appears inside glBegin/glEnd).
  std::optional<uint32_t> first_edge_flag_vertex;
  bool edge_flag_before_first = true;
  rec::VertexData vertices;       // one value per vertex for every recorded attribute
  uint64_t dropped_vertices = 0;  // beyond the per-primitive limit
};

}  // namespace glpt
