// The current secondary colour, fog coordinate, edge flag and colour index (GL 1.5 spec 2.7):
// the setters behind the generated glSecondaryColor*/glFogCoord*/glEdgeFlag*/glIndex* variants.
#include "gl_shim/context.hpp"
#include "gl_shim/geometry/attributes.hpp"

namespace glpt {

void attribute_secondary_color(Context& ctx, glm::vec3 c) {
  ctx.current.secondary_color = glm::vec4(c, 1.0f);
  if (ctx.assembly.inside) ctx.assembly.vertices.per_vertex |= rec::kPerVertexSecondaryColor;
}

void attribute_fog_coord(Context& ctx, float coord) { ctx.current.fog_coord = coord; }

// GL booleans: any nonzero value is true (Mesa stores the raw value as a float and then reports
// GL_EDGE_FLAG false for anything but 1; glpt follows the spec).
void attribute_edge_flag(Context& ctx, bool flag) {
  VertexAssembly& a = ctx.assembly;
  if (a.inside && !a.first_edge_flag_vertex) {
    a.first_edge_flag_vertex = static_cast<uint32_t>(a.vertices.position.size());
    a.edge_flag_before_first = ctx.current.edge_flag;
  }
  ctx.current.edge_flag = flag;
  render_mode_edge_flag(ctx);
}

void attribute_index(Context& ctx, float index) { ctx.current.index = index; }

}  // namespace glpt
