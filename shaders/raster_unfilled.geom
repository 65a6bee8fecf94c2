#version 460
// GL polygon modes GL_LINE and GL_POINT (GL 1.5 3.5.4) as Mesa's draw module does them: each
// triangle is culled by its facing, takes its colours from the provoking vertex when flat and
// from its facing side when two-sided, gets GL's polygon offset, and becomes the lines (or
// points) of its boundary edges: the edges the decomposition marked (quad and polygon
// diagonals are not boundary edges) whose starting vertex has its edge flag set.
//
// Built twice: GLPT_POINTS 0 emits lines, 1 emits points.
#extension GL_GOOGLE_include_directive : require

#include "raster_types.h"

layout(triangles) in;
#if GLPT_POINTS
layout(points, max_vertices = 3) out;
#else
layout(line_strip, max_vertices = 6) out;
#endif

layout(constant_id = GLPT_SC_VS_FLAGS) const uint kVsFlags = 0u;
layout(constant_id = GLPT_SC_CLIP_PLANES) const uint kClipPlanes = 0u;
layout(constant_id = GLPT_SC_UNFILLED) const uint kUnfilled = 0u;

layout(std430, set = 0, binding = GLPT_RASTER_BINDING_STATES) readonly buffer States {
  RasterState states[];
};
layout(std430, set = 0, binding = GLPT_RASTER_BINDING_EDGES) readonly buffer Edges {
  uint edge_masks[];
};
layout(push_constant) uniform Push { RasterPushConstants push; };
// The draw's state, read field by field where used (never copied whole).
#define S states[g_state[0]]

layout(location = 0) in vec4 g_front_color[];
layout(location = 1) in vec4 g_back_color[];
layout(location = 2) in vec4 g_front_secondary[];
layout(location = 3) in vec4 g_back_secondary[];
layout(location = 4) in vec4 g_texcoord[][GLPT_RASTER_MAX_UNITS];
layout(location = GLPT_RASTER_VARYING_STATE) flat in uint g_state[];
layout(location = 8) in float g_fog[];
in gl_PerVertex {
  vec4 gl_Position;
  float gl_PointSize;
  float gl_ClipDistance[8];
} gl_in[];

layout(location = 0) out vec4 v_front_color;
layout(location = 1) out vec4 v_back_color;
layout(location = 2) out vec4 v_front_secondary;
layout(location = 3) out vec4 v_back_secondary;
layout(location = 4) out vec4 v_texcoord[GLPT_RASTER_MAX_UNITS];
layout(location = GLPT_RASTER_VARYING_STATE) flat out uint v_state;
layout(location = 8) out float v_fog;
out gl_PerVertex {
  vec4 gl_Position;
  float gl_PointSize;
  float gl_ClipDistance[8];
};

vec3 window_of(vec4 clip) {
  vec3 ndc = clip.xyz / clip.w;
  return vec3((ndc.xy * 0.5 + 0.5) * S.viewport.zw + S.viewport.xy,
              (ndc.z * 0.5 + 0.5) * (S.depth_range.y - S.depth_range.x) + S.depth_range.x);
}

void emit(uint i, bool back, uint colour_from, float window_offset) {
  vec4 p = gl_in[i].gl_Position;
  if (window_offset != 0.0) {
    // As Mesa: the offset moves the vertex's window z, which is then clamped to [0, 1].
    float n = S.depth_range.x, f = S.depth_range.y;
    float window_z = clamp((p.z / p.w * 0.5 + 0.5) * (f - n) + n + window_offset, 0.0, 1.0);
    p.z = f != n ? ((window_z - n) / (f - n) * 2.0 - 1.0) * p.w : p.z;
  }
  gl_Position = p;
  // Colours: two-sided lighting picks the side the triangle shows (lines and points themselves
  // are always front-facing); flat shading uses the triangle's provoking vertex.
  v_front_color = back ? g_back_color[colour_from] : g_front_color[colour_from];
  v_back_color = v_front_color;
  v_front_secondary = back ? g_back_secondary[colour_from] : g_front_secondary[colour_from];
  v_back_secondary = v_front_secondary;
  for (int u = 0; u < GLPT_RASTER_MAX_UNITS; ++u) v_texcoord[u] = g_texcoord[i][u];
  v_fog = g_fog[i];
  v_state = g_state[i];
  // User clip planes pass through; the emitted lines are also clipped exactly to the view's
  // sides, as GL clips the polygon (see raster_ff.vert).
  int slot = 0;
  for (int c = 0; c < GLPT_RASTER_MAX_CLIP_PLANES; ++c)
    if ((kClipPlanes & (1u << c)) != 0u) {
      gl_ClipDistance[slot] = gl_in[i].gl_ClipDistance[slot];
      ++slot;
    }
  if (slot + 4 <= 8) {
    gl_ClipDistance[slot++] = p.w + p.x;
    gl_ClipDistance[slot++] = p.w - p.x;
    gl_ClipDistance[slot++] = p.w + p.y;
    gl_ClipDistance[slot++] = p.w - p.y;
  }
  for (; slot < 8; ++slot) gl_ClipDistance[slot] = 1.0;
  float size = clamp(S.point_size.x, S.point_size.y, S.point_size.z);
  // Sprites are squares of the exact size (as llvmpipe draws points it does not round); aliased
  // points round the size to an integer, halves down.
  gl_PointSize = (kUnfilled & GLPT_UNFILLED_SPRITE) != 0u ? size : max(1.0, ceil(size - 0.5));
  EmitVertex();
}

void main() {
  uint mask = (edge_masks[push.indices.y + uint(gl_PrimitiveIDIn) / 4u] >>
               (8u * (uint(gl_PrimitiveIDIn) % 4u))) & 7u;
  // Facing from the window-space area (GL 1.5 2.14.1), with glFrontFace.
  vec3 w0 = window_of(gl_in[0].gl_Position);
  vec3 w1 = window_of(gl_in[1].gl_Position);
  vec3 w2 = window_of(gl_in[2].gl_Position);
  vec3 e = w0 - w2, f = w1 - w2;
  float det = e.x * f.y - e.y * f.x;
  bool ccw = det > 0.0;
  bool front = (kUnfilled & GLPT_UNFILLED_FRONT_CW) != 0u ? !ccw : ccw;
  if ((kUnfilled & (front ? GLPT_UNFILLED_CULL_FRONT : GLPT_UNFILLED_CULL_BACK)) != 0u) return;
  if (det == 0.0) return;

  // Polygon offset as Mesa's draw module applies it to unfilled polygons: the largest window z
  // slope times the factor, plus the units times twice the depth buffer's resolution, added to
  // every vertex's window z.
  float offset = 0.0;
  if ((kUnfilled & GLPT_UNFILLED_OFFSET) != 0u) {
    float a = e.y * f.z - e.z * f.y;
    float b = e.z * f.x - e.x * f.z;
    float slope = max(abs(a / det), abs(b / det));
    offset = slope * S.polygon_offset.x + S.polygon_offset.y;
  }
  bool back = (kVsFlags & GLPT_VS_TWO_SIDE) != 0u && !front;
  // The colour each emitted vertex takes: its own, or the provoking vertex's (v2) when flat.
  bool flat_shade = (kUnfilled & GLPT_UNFILLED_FLAT) != 0u;
#if GLPT_POINTS
  for (uint i = 0u; i < 3u; ++i) {
    if ((mask & (1u << i)) == 0u) continue;
    emit(i, back, flat_shade ? 2u : i, offset);
    EndPrimitive();
  }
#else
  // Mesa's order: edge 2 (v2 -> v0), edge 0 (v0 -> v1), edge 1 (v1 -> v2).
  const uint order[3] = uint[3](2u, 0u, 1u);
  for (uint k = 0u; k < 3u; ++k) {
    uint edge = order[k];
    if ((mask & (1u << edge)) == 0u) continue;
    uint a = edge, b = (edge + 1u) % 3u;
    emit(a, back, flat_shade ? 2u : a, offset);
    emit(b, back, flat_shade ? 2u : b, offset);
    EndPrimitive();
  }
#endif
}
