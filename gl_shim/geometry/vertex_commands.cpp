// glBegin/glEnd and the current vertex attributes (GL 1.5 spec 2.6, 2.7): each glVertex appends
// a vertex with the current attributes to the primitive being assembled; glEnd hands the
// primitive to the frame recorder with the state snapshot taken at glBegin.
#include <bit>
#include <cmath>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/framebuffers/framebuffer_rendering.hpp"
#include "gl_shim/geometry/attributes.hpp"
#include "gl_shim/geometry/vertex_assembly.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/state/lighting.hpp"

namespace glpt {
namespace {

// One glBegin/glEnd may not grow without bound: past this many vertices the rest are dropped
// and GL_OUT_OF_MEMORY is recorded (the spec's answer when an implementation runs out).
constexpr size_t kMaxVerticesPerPrimitive = size_t{1} << 24;

bool is_primitive_mode(GLenum mode) { return mode <= GL_POLYGON; }

void reset(rec::VertexData& d, GLenum mode) {
  d.mode = mode;
  clear_vertex_arrays(d);
  d.per_vertex = 0;
}

}  // namespace

void attribute_vertex(Context& ctx, glm::vec4 p) {
  VertexAssembly& a = ctx.assembly;
  if (!a.inside) return;  // a vertex outside glBegin/glEnd has no effect
  rec::VertexData& d = a.vertices;
  if (d.position.size() >= kMaxVerticesPerPrimitive) {
    if (a.dropped_vertices++ == 0) record_error(ctx, GL_OUT_OF_MEMORY);
    return;
  }
  const CurrentAttributes& c = ctx.current;
  const size_t vertex = d.position.size();
  d.position.push_back(p);
  rec::store_attribute(d.normal, c.normal, vertex);
  rec::store_attribute(d.color, c.color, vertex);
  rec::store_attribute(d.secondary_color, c.secondary_color, vertex);
  rec::store_attribute(d.fog_coord, c.fog_coord, vertex);
  for (uint32_t units = a.texture_units; units != 0; units &= units - 1) {
    const int u = std::countr_zero(units);
    rec::store_attribute(d.tex_coord[u], c.tex_coord[u], vertex);
  }
  rec::store_attribute(d.edge_flag, uint8_t{c.edge_flag ? uint8_t{1} : uint8_t{0}}, vertex);
  if (a.per_vertex_material) d.material.push_back(ctx.lighting.material);
}

void attribute_color(Context& ctx, glm::vec4 c) {
  ctx.current.color = c;
  VertexAssembly& a = ctx.assembly;
  if (a.inside) {
    a.vertices.per_vertex |= rec::kPerVertexColor;
    // The material is read again at glEnd (or by a glMaterial, or per vertex once one was
    // called): only the last colour's update matters.
    if (!a.per_vertex_material) {
      a.color_material_pending = true;
      return;
    }
  }
  apply_color_material(ctx);
}

void flush_color_material(Context& ctx) {
  if (!ctx.assembly.color_material_pending) return;
  ctx.assembly.color_material_pending = false;
  apply_color_material(ctx);
}

void attribute_multi_tex_coord(Context& ctx, GLenum unit, glm::vec4 t) {
  if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + rec::kMaxTextureUnits)
    return record_error(ctx, GL_INVALID_ENUM);
  ctx.current.tex_coord[unit - GL_TEXTURE0] = t;
}

void material_set_inside_begin_end(Context& ctx, uint32_t fields) {
  VertexAssembly& a = ctx.assembly;
  if (!a.inside) return;
  if (!a.per_vertex_material) {
    // From now on every vertex carries its material; the ones before get the material at
    // glBegin.
    a.per_vertex_material = true;
    a.vertices.material.assign(a.vertices.position.size(), a.material_at_begin);
  }
  // Mesa's display lists store a material field as a vertex attribute from its first glMaterial
  // in the list on, and copy that first value into the vertices compiled before it (vbo_save's
  // "dangling attribute" fix-up); immediate mode does not. glpt does the same within the
  // primitive being replayed.
  const uint32_t first_set = fields & ~a.material_fields_set;
  a.material_fields_set |= fields;
  if (a.vertices.source != rec::PrimitiveSource::kDisplayList || first_set == 0) return;
  for (auto& vertex : a.vertices.material) {
    for (int side = 0; side < 2; ++side) {
      const rec::Material& now = ctx.lighting.material[side];
      rec::Material& m = vertex[side];
      if (first_set & material_field_bit(side, 0)) m.ambient = now.ambient;
      if (first_set & material_field_bit(side, 1)) m.diffuse = now.diffuse;
      if (first_set & material_field_bit(side, 2)) m.specular = now.specular;
      if (first_set & material_field_bit(side, 3)) m.emission = now.emission;
      if (first_set & material_field_bit(side, 4)) m.shininess = now.shininess;
    }
  }
}

namespace impl {

void glBegin(Context& ctx, GLenum mode) {
  if (!is_primitive_mode(mode)) return record_error(ctx, GL_INVALID_ENUM);
  // A draw: Mesa validates its derived state here (matrix analysis decides later arithmetic).
  ctx.matrices.validate_for_draw(ctx.transform.clip_plane_mask);
  if (const GLenum e = framebuffer_error(ctx); e != GL_NO_ERROR) return record_error(ctx, e);
  VertexAssembly& a = ctx.assembly;
  a.inside = true;
  a.state = ctx.snapshots.capture(ctx, ctx.recorder.record());
  const rec::TexturingState& texturing = *ctx.recorder.record().states[a.state].texturing;
  a.texture_units = 0;
  for (int u = 0; u < rec::kMaxTextureUnits; ++u)
    if (texturing.units[u].target != 0) a.texture_units |= static_cast<uint8_t>(1u << u);
  if (ctx.render_mode.mode == GL_FEEDBACK) a.texture_units |= 1;  // feedback reports unit 0's
  a.material_at_begin = ctx.lighting.material;
  a.per_vertex_material = false;
  a.color_material_pending = false;
  a.material_fields_set = 0;
  a.first_edge_flag_vertex.reset();
  a.dropped_vertices = 0;
  reset(a.vertices, mode);
  // Replayed by glCallList: Mesa compiled it into an indexed draw. GL_COMPILE_AND_EXECUTE
  // executes while compiling (call_depth 0): Mesa draws that like immediate mode.
  a.vertices.source = ctx.lists.call_depth > 0 ? rec::PrimitiveSource::kDisplayList
                                               : rec::PrimitiveSource::kImmediate;
}

void glEnd(Context& ctx) {
  VertexAssembly& a = ctx.assembly;
  if (!a.inside) return record_error(ctx, GL_INVALID_OPERATION);
  a.inside = false;
  flush_color_material(ctx);
  rec::VertexData& d = a.vertices;
  if (d.position.empty()) return;
  d.primitives.push_back({0, static_cast<uint32_t>(d.position.size())});
  if (ctx.render_mode.mode != GL_RENDER) return render_mode_assembled_primitive(ctx, a);
  ctx.recorder.add_primitive(a.state, d);
  note_frame_content(ctx);
}

}  // namespace impl
}  // namespace glpt
