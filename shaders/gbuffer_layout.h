// The G-buffer of path-traced mode: what the raster pipelines write per pixel for the traced
// draws (raster_ff.frag built with GLPT_GBUFFER=1) and the trace pass reads (path_trace.comp).
// Compiled as C++ (constants only) and as GLSL (constants and the packing helpers).
//
// Attachment (location)  format          contents
//   0 POSITION           R32G32B32A32F   xyz: eye-space position (after the modelview's w
//                                        division), w: fog coordinate
//   1 SURFACE            R32G32B32A32UI  x: record state index + 1 (0: no traced surface here),
//                                        y: shading normal, z: geometric normal (octahedral,
//                                        2 x snorm16), w: flags (bits 0-7) | precision exponent
//                                        (bits 8-15) | half(shininess) << 16
//   2 MATERIAL0          R32G32B32A32UI  lit: half2 diffuse.rg, diffuse.ba, ambient.rg,
//                                        (ambient.b, specular.r); unlit: x = the fragment's colour
//                                        as unorm8 RGBA (exactly what raster mode would write)
//   3 MATERIAL1          R32G32B32A32UI  half2 specular.gb, emission.rg, (emission.b, lift.x),
//                                        (lift.y, lift.z); lift: eye-space displacement of
//                                        secondary-ray origins onto the smooth surface the vertex
//                                        normals describe (the shadow-terminator fix)
#ifndef GLPT_SHADERS_GBUFFER_LAYOUT_H
#define GLPT_SHADERS_GBUFFER_LAYOUT_H

#define GLPT_GBUFFER_POSITION 0
#define GLPT_GBUFFER_SURFACE 1
#define GLPT_GBUFFER_MATERIAL0 2
#define GLPT_GBUFFER_MATERIAL1 3
#define GLPT_GBUFFER_ATTACHMENTS 4

// SURFACE.w flags
#define GLPT_GBUFFER_LIT 1u        // GL lighting was on: trace it; off: MATERIAL0.x is the colour
#define GLPT_GBUFFER_BACK_FACE 2u  // two-sided lighting lit the back face (normal already flipped)
// SURFACE.w bits 8-15: e, with 2^(e - 128) at least the eye-space magnitude of the terms the
// position was computed from (object coordinates times the modelview, see offset_ray.h); 0: none.
#define GLPT_GBUFFER_PRECISION_SHIFT 8u

// Per-vertex outputs the G-buffer variants add after raster_ff.vert's own (locations 0-8).
#define GLPT_GBUFFER_VARYING_EYE 9            // vec4: homogeneous eye-space position
#define GLPT_GBUFFER_VARYING_NORMAL 10        // vec3: eye-space normal as GL lights with it
#define GLPT_GBUFFER_VARYING_VERTEX_COLOR 11  // vec4: the current colour (colour material)
// Added by raster_gbuffer.geom: the triangle's three eye-space vertices and normals (flat) and
// the barycentric coordinates of the fragment.
#define GLPT_GBUFFER_VARYING_CORNERS 12      // vec3[3]
#define GLPT_GBUFFER_VARYING_CORNER_NORMALS 15  // vec3[3]
#define GLPT_GBUFFER_VARYING_BARYCENTRIC 18  // vec2: weights of corners 1 and 2
// float: the eye-space magnitude of the terms of the position: per vertex into the geometry
// shader as GLPT_GBUFFER_VARYING_NORMAL's fourth component (the geometry shader's inputs are
// limited to 64 components, 16 locations, on lavapipe), the triangle's largest out of it (flat).
#define GLPT_GBUFFER_VARYING_TERM_MAGNITUDE 19
// uint: the draw's state index (raster_types.h GLPT_RASTER_VARYING_STATE)
#define GLPT_GBUFFER_VARYING_STATE 20
// Per-vertex materials (glMaterial between glBegin and glEnd, RasterPushConstants::materials):
// the vertex shader hands its gl_VertexIndex to the geometry shader (flat uint), which gives the
// fragment shader the triangle's three (flat uvec3), so the G-buffer's material is the vertices'
// as GL lights them, not the draw state's. 13 is a location of the vertex-to-geometry interface
// (free there: raster_ff.vert's own end at GLPT_RASTER_VARYING_STATE, 12), 21 of the
// geometry-to-fragment one.
#define GLPT_GBUFFER_VARYING_VERTEX_INDEX 13
#define GLPT_GBUFFER_VARYING_CORNER_VERTICES 21

#ifndef __cplusplus
// Octahedral unit-vector encoding (Cigolle et al. 2014) in two snorm16 values: about 1e-4
// radians of error, in one 32-bit word.
vec2 gbuffer_sign_not_zero(vec2 v) {
  return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}
uint gbuffer_pack_normal(vec3 n) {
  vec2 p = n.xy * (1.0 / (abs(n.x) + abs(n.y) + abs(n.z)));
  if (n.z < 0.0) p = (1.0 - abs(p.yx)) * gbuffer_sign_not_zero(p);
  return packSnorm2x16(p);
}
// The precision exponent of SURFACE.w: rounded up, so the magnitude it gives back is never less.
uint gbuffer_pack_precision(float magnitude) {
  if (!(magnitude > 0.0)) return 0u;  // also NaN
  int e = clamp(int(ceil(log2(min(magnitude, 3.0e38)))) + 128, 1, 255);
  return uint(e) << GLPT_GBUFFER_PRECISION_SHIFT;
}
float gbuffer_unpack_precision(uint surface_w) {
  uint e = (surface_w >> GLPT_GBUFFER_PRECISION_SHIFT) & 0xFFu;
  return e == 0u ? 0.0 : exp2(float(int(e) - 128));
}
vec3 gbuffer_unpack_normal(uint bits) {
  vec2 p = unpackSnorm2x16(bits);
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * gbuffer_sign_not_zero(n.xy);
  return normalize(n);
}
#endif

#endif  // GLPT_SHADERS_GBUFFER_LAYOUT_H
