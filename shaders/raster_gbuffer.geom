#version 460
// Path-traced mode's G-buffer pass: passes each triangle through unchanged (same positions, same
// vertex order, so coverage, facing and the provoking vertex are the raster pipeline's) and gives
// every fragment the whole triangle: its three eye-space corners and vertex normals (flat) and
// the fragment's barycentric coordinates. The fragment shader derives the exact geometric normal
// from the corners and moves secondary-ray origins onto the smooth surface the vertex normals
// describe (Hanika's shadow-terminator fix), neither of which one vertex's data allows; and the
// triangle's largest term magnitude (how coarse its positions are: offset_ray.h).
//
// Built twice: GLPT_CLIP 1 passes the user clip distances through.
#extension GL_GOOGLE_include_directive : require

#include "gbuffer_layout.h"
#include "raster_types.h"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(location = 0) in vec4 g_front_color[];
layout(location = 1) in vec4 g_back_color[];
layout(location = 2) in vec4 g_front_secondary[];
layout(location = 3) in vec4 g_back_secondary[];
layout(location = 4) in vec4 g_texcoord[][GLPT_RASTER_MAX_UNITS];
layout(location = GLPT_RASTER_VARYING_STATE) flat in uint g_state[];
layout(location = 8) in float g_fog[];
layout(location = GLPT_GBUFFER_VARYING_EYE) in vec4 g_eye[];
layout(location = GLPT_GBUFFER_VARYING_NORMAL) in vec3 g_normal[];
layout(location = GLPT_GBUFFER_VARYING_VERTEX_COLOR) in vec4 g_vertex_color[];
layout(location = GLPT_GBUFFER_VARYING_NORMAL, component = 3) in float g_term_magnitude[];
layout(location = GLPT_GBUFFER_VARYING_VERTEX_INDEX) flat in uint g_vertex_index[];
// The vertex shader's per-vertex block, member for member (Vulkan compares the blocks).
in gl_PerVertex {
  vec4 gl_Position;
  float gl_PointSize;
#if GLPT_CLIP
  float gl_ClipDistance[8];
#endif
} gl_in[];

layout(location = 0) out vec4 v_front_color;
layout(location = 1) out vec4 v_back_color;
layout(location = 2) out vec4 v_front_secondary;
layout(location = 3) out vec4 v_back_secondary;
layout(location = 4) out vec4 v_texcoord[GLPT_RASTER_MAX_UNITS];
layout(location = GLPT_GBUFFER_VARYING_STATE) flat out uint v_state;
layout(location = 8) out float v_fog;
layout(location = GLPT_GBUFFER_VARYING_EYE) out vec4 v_eye;
layout(location = GLPT_GBUFFER_VARYING_NORMAL) out vec3 v_normal;
layout(location = GLPT_GBUFFER_VARYING_VERTEX_COLOR) out vec4 v_vertex_color;
layout(location = GLPT_GBUFFER_VARYING_CORNERS) flat out vec3 v_corner[3];
layout(location = GLPT_GBUFFER_VARYING_CORNER_NORMALS) flat out vec3 v_corner_normal[3];
layout(location = GLPT_GBUFFER_VARYING_BARYCENTRIC) out vec2 v_barycentric;
layout(location = GLPT_GBUFFER_VARYING_TERM_MAGNITUDE) flat out float v_term_magnitude;
layout(location = GLPT_GBUFFER_VARYING_CORNER_VERTICES) flat out uvec3 v_corner_vertex;
out gl_PerVertex {
  vec4 gl_Position;
#if GLPT_CLIP
  float gl_ClipDistance[8];
#endif
};

void main() {
  vec3 corners[3], normals[3];
  for (int i = 0; i < 3; ++i) {
    corners[i] = g_eye[i].xyz / g_eye[i].w;
    normals[i] = g_normal[i];
  }
  float term_magnitude = max(max(g_term_magnitude[0], g_term_magnitude[1]), g_term_magnitude[2]);
  const vec2 barycentric[3] = vec2[3](vec2(0.0), vec2(1.0, 0.0), vec2(0.0, 1.0));
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
#if GLPT_CLIP
    for (int c = 0; c < 8; ++c) gl_ClipDistance[c] = gl_in[i].gl_ClipDistance[c];
#endif
    v_front_color = g_front_color[i];
    v_back_color = g_back_color[i];
    v_front_secondary = g_front_secondary[i];
    v_back_secondary = g_back_secondary[i];
    for (int u = 0; u < GLPT_RASTER_MAX_UNITS; ++u) v_texcoord[u] = g_texcoord[i][u];
    v_fog = g_fog[i];
    v_state = g_state[i];
    v_eye = g_eye[i];
    v_normal = g_normal[i];
    v_vertex_color = g_vertex_color[i];
    v_corner = corners;
    v_corner_normal = normals;
    v_barycentric = barycentric[i];
    v_term_magnitude = term_magnitude;
    v_corner_vertex = uvec3(g_vertex_index[0], g_vertex_index[1], g_vertex_index[2]);
    EmitVertex();
  }
  EndPrimitive();
}
