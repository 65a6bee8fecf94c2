// The canonical vertex-attribute setters behind every glVertex*/glNormal*/glColor*/glTexCoord*/
// glSecondaryColor*/glFogCoord*/glEdgeFlag*/glIndex* variant (generated in
// gl_attribute_families.cpp, which converts the arguments: normalized_component for colours and
// normals, float_component for the rest).
#pragma once

#include <glm/glm.hpp>

#include "gl_shim/context.hpp"
#include "gl_shim/gl_types.h"
#include "gl_shim/state/normalized_values.hpp"

namespace glpt {

void attribute_vertex(Context& ctx, glm::vec4 position);
void attribute_color(Context& ctx, glm::vec4 color);
// Inline: called once per vertex by immediate-mode programs, and a call that takes the vector by
// value packs it through the stack (two 4-byte stores read back as one 8-byte load, which the
// store buffer cannot forward: bench/vertex_stream spent 15% of its time in glNormal3f).
inline void attribute_normal(Context& ctx, glm::vec3 normal) { ctx.current.normal = normal; }
inline void attribute_tex_coord(Context& ctx, glm::vec4 coord) { ctx.current.tex_coord[0] = coord; }
void attribute_multi_tex_coord(Context& ctx, GLenum texture_unit, glm::vec4 coord);

// glMaterial between glBegin and glEnd (allowed by GL 1.5 2.6.3), called once it set the fields
// `fields` (material_field_bit) of ctx.lighting.material: from then on every vertex of the
// primitive records its own material. Does nothing outside glBegin/glEnd.
void material_set_inside_begin_end(Context& ctx, uint32_t fields);
// The bit of one material field: `side` 0 front, 1 back; `field` 0 ambient, 1 diffuse,
// 2 specular, 3 emission, 4 shininess.
constexpr uint32_t material_field_bit(int side, int field) { return 1u << (side * 5 + field); }

// Makes the GL_COLOR_MATERIAL update a glColor inside glBegin/glEnd deferred (see
// VertexAssembly::color_material_pending); called before anything reads or writes the material.
void flush_color_material(Context& ctx);

// extra_attributes.cpp
void attribute_secondary_color(Context& ctx, glm::vec3 color);  // alpha stays 1 (as in Mesa)
void attribute_fog_coord(Context& ctx, float coord);
void attribute_edge_flag(Context& ctx, bool flag);
void attribute_index(Context& ctx, float index);  // colour-index mode: stored for queries only

template <typename T>
float float_component(T v) {
  return static_cast<float>(v);
}

}  // namespace glpt
