#version 460
// GL 1.5 fixed-function fragment processing: polygon stipple, texturing with per-unit texture
// environments (GL 1.5 3.8.13, including GL_COMBINE and crossbar sources), colour sum, fog
// (3.10) and the alpha test (4.1.4). Blending, logic op, stencil, depth and masks are fixed
// function in the pipeline (or here: GLPT_FRAMEBUFFER_OPS). Specialization constants (raster_types.h) select each unit's target,
// environment and texture base format, so a pipeline contains only what its state uses.
//
// Built twice: GLPT_FLAT 1 takes the colours of the provoking vertex (GL_FLAT); both also in
// variants declaring fewer varyings (GLPT_VARYINGS, raster_varyings.h). Built twice more
// for pixel rectangles: GLPT_PIXELS 1 takes the fragment colour (or, for bitmaps and stencil
// images, whether there is a fragment) from the image in the pixels buffer; GLPT_PIXELS 2 also
// its depth (depth images), which needs gl_FragDepth and so a shader of its own.
// GLPT_GBUFFER 1: path-traced mode's G-buffer pass (after raster_gbuffer.geom): the same coverage,
// stipple, texturing and alpha test, but the outputs are the G-buffer (gbuffer_layout.h).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_quad : require

#include "raster_types.h"
#ifndef GLPT_GBUFFER
#define GLPT_GBUFFER 0
#endif
#if GLPT_GBUFFER
#include "gbuffer_layout.h"
#endif

#ifndef GLPT_PIXELS
#define GLPT_PIXELS 0
#endif
// GLPT_FRAMEBUFFER_OPS 1: blending or the logic op done here (raster_framebuffer_ops.h), for a
// single colour target read as an input attachment.
#ifndef GLPT_FRAMEBUFFER_OPS
#define GLPT_FRAMEBUFFER_OPS 0
#endif

layout(constant_id = GLPT_SC_UNIT0 + 0) const uint kUnit0 = 0u;
layout(constant_id = GLPT_SC_UNIT0 + 1) const uint kUnit1 = 0u;
layout(constant_id = GLPT_SC_UNIT0 + 2) const uint kUnit2 = 0u;
layout(constant_id = GLPT_SC_UNIT0 + 3) const uint kUnit3 = 0u;
layout(constant_id = GLPT_SC_COMBINE0 + 0) const uint kCombine0 = 0u;
layout(constant_id = GLPT_SC_COMBINE0 + 1) const uint kCombine1 = 0u;
layout(constant_id = GLPT_SC_COMBINE0 + 2) const uint kCombine2 = 0u;
layout(constant_id = GLPT_SC_COMBINE0 + 3) const uint kCombine3 = 0u;
layout(constant_id = GLPT_SC_COMBINE_ALPHA_OPERANDS0 + 0) const uint kAlphaOperands0 = 0u;
layout(constant_id = GLPT_SC_COMBINE_ALPHA_OPERANDS0 + 1) const uint kAlphaOperands1 = 0u;
layout(constant_id = GLPT_SC_COMBINE_ALPHA_OPERANDS0 + 2) const uint kAlphaOperands2 = 0u;
layout(constant_id = GLPT_SC_COMBINE_ALPHA_OPERANDS0 + 3) const uint kAlphaOperands3 = 0u;
layout(constant_id = GLPT_SC_FS_FLAGS) const uint kFlags = 0u;
layout(constant_id = GLPT_SC_FS_ALPHA_FOG) const uint kAlphaFog = 0u;

layout(std430, set = 0, binding = GLPT_RASTER_BINDING_STATES) readonly buffer States {
  RasterState states[];
};
layout(push_constant) uniform Push { RasterPushConstants push; };
// The draw's state, read field by field where used (never copied whole).
#define S states[v_state]

layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 0) uniform sampler1D u_tex1d_0;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 1) uniform sampler2D u_tex2d_0;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 2) uniform sampler3D u_tex3d_0;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 3) uniform samplerCube u_texcube_0;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 4) uniform sampler1D u_tex1d_1;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 5) uniform sampler2D u_tex2d_1;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 6) uniform sampler3D u_tex3d_1;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 7) uniform samplerCube u_texcube_1;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 8) uniform sampler1D u_tex1d_2;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 9) uniform sampler2D u_tex2d_2;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 10) uniform sampler3D u_tex3d_2;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 11) uniform samplerCube u_texcube_2;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 12) uniform sampler1D u_tex1d_3;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 13) uniform sampler2D u_tex2d_3;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 14) uniform sampler3D u_tex3d_3;
layout(set = 0, binding = GLPT_RASTER_BINDING_TEXTURES + 15) uniform samplerCube u_texcube_3;

#if GLPT_FRAMEBUFFER_OPS
#include "raster_framebuffer_ops.h"
layout(input_attachment_index = 0, set = 0,
       binding = GLPT_RASTER_BINDING_FRAMEBUFFER) uniform subpassInput u_framebuffer;
#endif

#if GLPT_PIXELS
layout(std430, set = 0, binding = GLPT_RASTER_BINDING_PIXELS) readonly buffer Pixels {
  uint pixel_words[];
};
#endif

#if GLPT_FLAT
#define INTERPOLATION flat
#else
#define INTERPOLATION
#endif
#define GLPT_VARYING_OUT in
#define GLPT_COLOR_VARYING_OUT INTERPOLATION in
#define GLPT_VARYINGS_INTO_FRAGMENT 1
#include "raster_varyings.h"

#if GLPT_GBUFFER
layout(constant_id = GLPT_SC_VS_FLAGS) const uint kVsFlags = 0u;
layout(constant_id = GLPT_SC_COLOR_MATERIAL) const uint kColorMaterial = 0u;
layout(location = GLPT_GBUFFER_VARYING_EYE) in vec4 v_eye;
layout(location = GLPT_GBUFFER_VARYING_NORMAL) INTERPOLATION in vec3 v_normal;
layout(location = GLPT_GBUFFER_VARYING_VERTEX_COLOR) INTERPOLATION in vec4 v_vertex_color;
layout(location = GLPT_GBUFFER_VARYING_CORNERS) flat in vec3 v_corner[3];
layout(location = GLPT_GBUFFER_VARYING_CORNER_NORMALS) flat in vec3 v_corner_normal[3];
layout(location = GLPT_GBUFFER_VARYING_BARYCENTRIC) in vec2 v_barycentric;
layout(location = GLPT_GBUFFER_VARYING_TERM_MAGNITUDE) flat in float v_term_magnitude;
layout(location = GLPT_GBUFFER_VARYING_CORNER_VERTICES) flat in uvec3 v_corner_vertex;
layout(location = GLPT_GBUFFER_POSITION) out vec4 o_position;
layout(location = GLPT_GBUFFER_SURFACE) out uvec4 o_surface;
layout(location = GLPT_GBUFFER_MATERIAL0) out uvec4 o_material0;
layout(location = GLPT_GBUFFER_MATERIAL1) out uvec4 o_material1;
#else
layout(location = 0) out vec4 o_color;
#if !GLPT_FRAMEBUFFER_OPS  // (blending in the shader: one colour target)
layout(location = 1) out vec4 o_color_second;  // GL_FRONT_AND_BACK: the same colour twice
#endif
#endif

uint unit_config(uint u) {
  return u == 0u ? kUnit0 : u == 1u ? kUnit1 : u == 2u ? kUnit2 : kUnit3;
}
uint unit_combine(uint u) {
  return u == 0u ? kCombine0 : u == 1u ? kCombine1 : u == 2u ? kCombine2 : kCombine3;
}
uint unit_alpha_operands(uint u) {
  return u == 0u ? kAlphaOperands0 : u == 1u ? kAlphaOperands1 : u == 2u ? kAlphaOperands2
                                                               : kAlphaOperands3;
}

// ---- texture lookups as llvmpipe's sampler (gallivm) does them --------------------------------
// The sampler objects reproduce most of GL (rt_core/raster/sampler_setup.hpp); what has no Vulkan
// equivalent is done here with gallivm's arithmetic (lp_bld_sample.c, lp_bld_sample_soa.c):
// GL_CLAMP with different minification and magnification filters, and depth comparison.

// The derivatives gallivm takes from a 2x2 quad: ddx = v[1] - v[0], ddy = v[2] - v[0], pixels
// numbered from the top left of Mesa's memory. Mesa renders window-system buffers upside down,
// so with an even drawable height its quad holds the same four pixels as Vulkan's, numbered
// from GL's upper row: its v[0], v[1], v[2] are Vulkan's quad pixels 2, 3 and 0. (With an odd
// height Mesa's quads straddle two of Vulkan's; the nearest match is Vulkan's own numbering.)
// A draw rasterized in Mesa's orientation (GLPT_FS_MESA_ORIENTED) has Mesa's quads as they are.
void quad_derivatives(vec3 c, out vec3 ddx, out vec3 ddy) {
  vec3 q0 = subgroupQuadBroadcast(c, 0u), q1 = subgroupQuadBroadcast(c, 1u);
  vec3 q2 = subgroupQuadBroadcast(c, 2u), q3 = subgroupQuadBroadcast(c, 3u);
  if ((kFlags & GLPT_FS_MESA_ORIENTED) == 0u && (S.drawable.y & 1u) == 0u) {
    ddx = q3 - q2;
    ddy = q0 - q2;
  } else {
    ddx = q1 - q0;
    ddy = q2 - q0;
  }
}

// lp_build_extract_exponent / lp_build_extract_mantissa / lp_build_fast_log2.
int exponent_of(float x, int bias) { return int((floatBitsToUint(x) >> 23u) & 0xFFu) - 127 + bias; }
float mantissa_of(float x) {
  return uintBitsToFloat((floatBitsToUint(x) & 0x7FFFFFu) | 0x3F800000u);
}
float fast_log2(float x) {
  precise float l = float(exponent_of(x, -1)) + mantissa_of(x);
  return l;
}

struct Lod {
  bool minified;  // lod > 0: the minification filter applies
  int level0, level1;
  float fpart;    // weight of level1 (GL_*_MIPMAP_LINEAR)
};

// gallivm's rho from the quad derivatives (lp_build_rho with llvmpipe's defaults: exact, not
// approximated): squared for 2 and 3 coordinates. `dims`: 1, 2 or 3 coordinates.
float quad_rho(uint u, uint dims, vec3 ddx, vec3 ddy) {
  vec3 size = S.tex_size[u].xyz;
  precise float rho;
  if (dims > 1u) {
    precise vec3 sx = ddx * size, sy = ddy * size;
    precise float rx = sx.x * sx.x + sx.y * sx.y;
    precise float ry = sy.x * sy.x + sy.y * sy.y;
    if (dims > 2u) {
      rx = rx + sx.z * sx.z;
      ry = ry + sy.z * sy.z;
    }
    rho = max(rx, ry);  // rho squared
  } else {
    rho = max(abs(ddx.x), abs(ddy.x)) * size.x;
  }
  return rho;
}

// Whether gallivm takes the shortcut without post-log2 adjustments (no bias, no lod clamps, no
// linear mip filter): then lod > 0 is rho > 1 and the nearest level comes from the exponent bits.
bool lod_shortcut(uint flags) {
  return (flags & (GLPT_TEX_LOD_BIAS | GLPT_TEX_APPLY_MIN_LOD | GLPT_TEX_APPLY_MAX_LOD |
                   GLPT_TEX_MIP_LINEAR)) == 0u;
}
// The shortcut's integer lod: iround(log2(rho)) from the exponent of rho (squared) or rho * sqrt 2.
int shortcut_level(uint dims, float rho) {
  precise float scaled = rho * 1.41421356;
  return dims > 1u ? exponent_of(rho, 1) >> 1 : exponent_of(scaled, 0);
}
// The lod before bias and clamps: lp_build_fast_log2 of rho squared, halved.
float unadjusted_lod(uint dims, float rho) {
  precise float squared = dims > 1u ? rho : rho * rho;
  precise float l = fast_log2(squared) * 0.5;
  return l;
}

// lp_build_lod_selector with llvmpipe's defaults (exact rho, no brilinear), then
// lp_build_nearest_mip_level / lp_build_linear_mip_levels.
Lod select_lod(uint u, uint dims, vec3 ddx, vec3 ddy) {
  uint flags = S.tex_mode[u].y;
  int last = max(int(S.tex_size[u].w) - 1, 0);
  Lod r = Lod(false, 0, 0, 0.0);
  float lod;
  if ((flags & GLPT_TEX_MIN_MAX_LOD_EQUAL) != 0u) {
    lod = S.tex_lod[u].y;
  } else {
    float rho = quad_rho(u, dims, ddx, ddy);
    if (lod_shortcut(flags)) {
      r.minified = rho > 1.0;
      int ipart = shortcut_level(dims, rho);
      r.level0 = r.level1 = (flags & GLPT_TEX_MIP_NEAREST) != 0u ? clamp(ipart, 0, last) : 0;
      return r;
    }
    precise float l = unadjusted_lod(dims, rho);
    if ((flags & GLPT_TEX_LOD_BIAS) != 0u) l = l + S.tex_lod[u].x;
    if ((flags & GLPT_TEX_APPLY_MAX_LOD) != 0u) l = min(l, S.tex_lod[u].z);
    if ((flags & GLPT_TEX_APPLY_MIN_LOD) != 0u) l = max(l, S.tex_lod[u].y);
    lod = l;
  }
  r.minified = lod > 0.0;
  if ((flags & GLPT_TEX_MIP_LINEAR) != 0u) {
    float whole = floor(lod);
    precise float fpart = lod - whole;
    int level0 = int(whole);
    r.level0 = level0 < 0 ? 0 : min(level0, last);
    r.level1 = level0 < 0 ? 0 : min(level0 + 1, last);
    r.fpart = level0 < 0 || level0 >= last ? 0.0 : fpart;
  } else if ((flags & GLPT_TEX_MIP_NEAREST) != 0u) {
    r.level0 = r.level1 = clamp(int(roundEven(lod)), 0, last);
  }
  return r;
}

// Whether the lod decides anything for unit u (a mip filter, or different minification and
// magnification filters).
bool lod_matters(uint u) {
  uint flags = S.tex_mode[u].y;
  bool min_linear = (flags & GLPT_TEX_MIN_LINEAR) != 0u;
  bool mag_linear = (flags & GLPT_TEX_MAG_LINEAR) != 0u;
  return (flags & (GLPT_TEX_MIP_NEAREST | GLPT_TEX_MIP_LINEAR)) != 0u || min_linear != mag_linear;
}

// The explicit lod for textureLod that makes lavapipe's sampler choose what llvmpipe's implicit
// lod does from Mesa's quad derivatives (quad_derivatives): lavapipe's own implicit lod would
// take ddx from the other row of the quad. Both are gallivm, which adds the sampler's bias to an
// explicit lod and clamps it to the sampler's lods exactly as it does an implicit one, so the
// value passed is the lod before those adjustments. In gallivm's shortcut (no adjustments) the
// level is an integer and lod > 0 is rho > 1: an integer lod, or a tiny positive one for a
// minified level 0, gives the same level and filter choice.
float mesa_explicit_lod(uint u, uint dims, vec3 c) {
  uint flags = S.tex_mode[u].y;
  if ((flags & GLPT_TEX_MIN_MAX_LOD_EQUAL) != 0u) return 0.0;  // gallivm takes the sampler's
  vec3 ddx, ddy;
  quad_derivatives(c, ddx, ddy);
  float rho = quad_rho(u, dims, ddx, ddy);
  if (lod_shortcut(flags)) {
    int ipart = shortcut_level(dims, rho);
    return ipart != 0 ? float(ipart) : rho > 1.0 ? 1.0 / 1024.0 : 0.0;
  }
  return unadjusted_lod(dims, rho);
}

// Whether a quad's lookup filters linearly (the minification filter when minified).
bool lookup_is_linear(uint u, uint dims, vec3 c) {
  vec3 ddx, ddy;
  quad_derivatives(c, ddx, ddy);
  uint flags = S.tex_mode[u].y;
  return select_lod(u, dims, ddx, ddy).minified ? (flags & GLPT_TEX_MIN_LINEAR) != 0u
                                                 : (flags & GLPT_TEX_MAG_LINEAR) != 0u;
}

// GL_CLAMP (GL 1.5 3.8.7) has no Vulkan address mode. gallivm filters it linearly as
// CLAMP_TO_BORDER of the coordinate clamped to [0, 1] (the sampler is CLAMP_TO_BORDER) and picks
// nearest texels as CLAMP_TO_EDGE: a coordinate clamped just below 1 stays on the last texel.
vec3 clamp_coords(uint u, uint config, vec3 c) {
  float upper = 1.0;
  if ((config & GLPT_UNIT_CLAMP_PER_FILTER) != 0u) {
    uint dims = (config & 7u) == 1u ? 1u : (config & 7u) == 3u ? 3u : 2u;
    if (!lookup_is_linear(u, dims, c)) upper = uintBitsToFloat(0x3F7FFFFFu);
  }
  if ((config & GLPT_UNIT_CLAMP_S) != 0u) c.x = clamp(c.x, 0.0, upper);
  if ((config & (GLPT_UNIT_CLAMP_S << 1u)) != 0u) c.y = clamp(c.y, 0.0, upper);
  if ((config & (GLPT_UNIT_CLAMP_S << 2u)) != 0u) c.z = clamp(c.z, 0.0, upper);
  return c;
}

// ---- depth comparison (GL_ARB_shadow) as gallivm's SoA sampler does it

vec4 texel_2d(uint u, ivec2 p, int level) {
  if (u == 0u) return texelFetch(u_tex2d_0, p, level);
  if (u == 1u) return texelFetch(u_tex2d_1, p, level);
  if (u == 2u) return texelFetch(u_tex2d_2, p, level);
  return texelFetch(u_tex2d_3, p, level);
}

float depth_texel(uint u, uint target, ivec2 p, int level) {
  if (target == 1u) {
    if (u == 0u) return texelFetch(u_tex1d_0, p.x, level).r;
    if (u == 1u) return texelFetch(u_tex1d_1, p.x, level).r;
    if (u == 2u) return texelFetch(u_tex1d_2, p.x, level).r;
    return texelFetch(u_tex1d_3, p.x, level).r;
  }
  return texel_2d(u, p, level).r;
}

// Whether texel p of a level of `size` texels reads as the border colour: it lies outside on an
// axis (of `axes`) whose wrap mode takes the border there, GL_CLAMP only when filtering linearly
// (lp_build_sample_texel_soa).
bool reads_border(uint u, uint axes, ivec2 p, ivec2 size, bool linear) {
  uint wraps = S.tex_mode[u].x;
  for (uint i = 0u; i < axes; ++i) {
    uint wrap = (wraps >> (4u * i)) & 15u;
    bool uses_border = wrap == GLPT_WRAP_CLAMP_TO_BORDER || (wrap == GLPT_WRAP_CLAMP && linear);
    if (uses_border && (p[i] < 0 || p[i] >= size[i])) return true;
  }
  return false;
}

// lp_build_coord_mirror(coord, posOnly = true).
float mirror_coord(float c) {
  precise float half_c = c * 0.5;
  precise float f = half_c - roundEven(half_c);
  precise float m = f + f;
  return max(abs(m), 0.0);
}

// lp_build_sample_wrap_nearest: the texel index of `c` on an axis of `n` texels.
int wrap_nearest(uint wrap, float c, int n) {
  float size = float(n);
  if (wrap == GLPT_WRAP_REPEAT) {
    if ((n & (n - 1)) == 0) {
      precise float scaled = c * size;
      return int(floor(scaled)) & (n - 1);
    }
    precise float f = min(c - floor(c), uintBitsToFloat(0x3F7FFFFFu));  // lp_build_fract_safe
    precise float scaled = f * size;
    return int(scaled);
  }
  if (wrap == GLPT_WRAP_CLAMP_TO_BORDER) {
    precise float scaled = c * size;
    return int(floor(scaled));
  }
  if (wrap == GLPT_WRAP_MIRRORED_REPEAT) {
    precise float scaled = mirror_coord(c) * size;
    return min(int(scaled), n - 1);
  }
  precise float scaled = c * size;  // GL_CLAMP, GL_CLAMP_TO_EDGE
  return clamp(int(scaled), 0, n - 1);
}

// lp_build_sample_wrap_linear: the two texel indices of `c` on an axis of `n` texels and the
// weight of the second.
void wrap_linear(uint wrap, float c, int n, out int x0, out int x1, out float weight) {
  float size = float(n);
  precise float v;
  if (wrap == GLPT_WRAP_REPEAT && (n & (n - 1)) != 0) {
    // lp_build_coord_repeat_npot_linear
    precise float f = c - floor(c);
    precise float scaled = f * size;
    v = scaled - 0.5;
    float whole = floor(v);
    weight = v - whole;
    x0 = v < 0.0 ? n - 1 : int(whole);
    x1 = x0 != n - 1 ? x0 + 1 : 0;
    return;
  }
  if (wrap == GLPT_WRAP_MIRRORED_REPEAT) {
    precise float scaled = mirror_coord(c) * size;
    v = scaled - 0.5;
  } else {
    precise float scaled = c * size;
    if (wrap == GLPT_WRAP_CLAMP) scaled = clamp(scaled, 0.0, size);
    if (wrap == GLPT_WRAP_CLAMP_TO_EDGE) scaled = min(scaled, size);
    v = scaled - 0.5;
    if (wrap == GLPT_WRAP_CLAMP_TO_EDGE) v = max(v, 0.0);
  }
  float whole = floor(v);
  weight = v - whole;
  x0 = int(whole);
  x1 = x0 + 1;
  if (wrap == GLPT_WRAP_REPEAT) {
    x0 &= n - 1;
    x1 &= n - 1;
  } else if (wrap == GLPT_WRAP_CLAMP_TO_EDGE) {
    x1 = min(x1, n - 1);
  } else if (wrap == GLPT_WRAP_MIRRORED_REPEAT) {
    x0 = max(x0, 0);
    x1 = min(x1, n - 1);
  }
}

// ---- anisotropic filtering (EXT_texture_filter_anisotropic) as gallivm does it

// Texel p of a level of `size` texels as a linear filter reads it: the border colour where the
// wrap mode takes it.
vec4 texel_or_border_2d(uint u, ivec2 p, ivec2 size, int level) {
  if (reads_border(u, 2u, p, size, true)) return S.tex_border[u];
  return texel_2d(u, clamp(p, ivec2(0), size - 1), level);
}

// lp_build_sample_image_linear on one level: bilinear whatever the texture's filters.
vec4 linear_texel_2d(uint u, vec2 c, ivec2 size, int level) {
  uint wraps = S.tex_mode[u].x;
  int x0, x1, y0, y1;
  float ws, wt;
  wrap_linear(wraps & 15u, c.x, size.x, x0, x1, ws);
  wrap_linear((wraps >> 4u) & 15u, c.y, size.y, y0, y1, wt);
  vec4 t00 = texel_or_border_2d(u, ivec2(x0, y0), size, level);
  vec4 t01 = texel_or_border_2d(u, ivec2(x1, y0), size, level);
  vec4 t10 = texel_or_border_2d(u, ivec2(x0, y1), size, level);
  vec4 t11 = texel_or_border_2d(u, ivec2(x1, y1), size, level);
  // lp_build_lerp_2d: lp_build_mad (llvm.fmuladd) per lerp.
  vec4 v0 = fma(vec4(ws), t01 - t00, t00), v1 = fma(vec4(ws), t11 - t10, t10);
  return fma(vec4(wt), v1 - v0, v0);
}

// A 2-D texture with an anisotropy of 2 or more (st/mesa hands gallivm its whole part, N), as
// llvmpipe samples it (lp_build_sample_aniso). lavapipe runs the same filter, but only from its
// own implicit derivatives, whose quad rows are not Mesa's (quad_derivatives); so it is done here.
// The level: the nearest (truncated) to the lod of the footprint's minor axis, lengthened to
// 1/N of the major one where the footprint is longer than N (lp_build_pmin), whatever the mip
// filter. Then up to N bilinear lookups of that level, whatever the texture's filters, spread
// evenly along the longer of the pixel's two screen-space derivatives, averaged. The lod takes
// the quad's derivatives, the lookups each pixel's own (lp_build_ddx/ddy: per row, per column).
// Each operation in gallivm's order, unfused.
vec4 anisotropic_2d(uint u, vec2 c) {
  uint flags = S.tex_mode[u].y;
  vec2 base = S.tex_size[u].xy;
  float anisotropy = S.tex_lod[u].w;
  int level = 0;
  if (lod_matters(u)) {
    float lod;
    if ((flags & GLPT_TEX_MIN_MAX_LOD_EQUAL) != 0u) {
      lod = S.tex_lod[u].y;
    } else {
      vec3 ddx3, ddy3;
      quad_derivatives(vec3(c, 0.0), ddx3, ddy3);
      precise float sx = ddx3.x * base.x, sy = ddy3.x * base.x;
      precise float tx = ddx3.y * base.y, ty = ddy3.y * base.y;
      precise float px2 = sx * sx + tx * tx, py2 = sy * sy + ty * ty;
      float pmax2 = max(px2, py2), pmin2 = min(px2, py2);
      precise float limit = pmin2 * (anisotropy * anisotropy);
      precise float lengthened = pmax2 / anisotropy;  // as gallivm has it: not squared
      if (pmax2 > limit) pmin2 = lengthened;
      precise float l = fast_log2(pmin2) * 0.5;
      if ((flags & GLPT_TEX_LOD_BIAS) != 0u) l = l + S.tex_lod[u].x;
      if ((flags & GLPT_TEX_APPLY_MAX_LOD) != 0u) l = min(l, S.tex_lod[u].z);
      if ((flags & GLPT_TEX_APPLY_MIN_LOD) != 0u) l = max(l, S.tex_lod[u].y);
      lod = l;
    }
    int last = max(int(S.tex_size[u].w) - 1, 0);
    level = clamp(int(lod), 0, last);  // lp_build_itrunc, then the nearest level's clamp
  }
  ivec2 size = max(ivec2(base) >> level, ivec2(1));
  // Mesa's derivatives: ddx along its quad's rows (Vulkan's, dFdxFine), ddy its lower row minus
  // its upper one. With an even drawable height Mesa's upper row is Vulkan's lower one.
  float ddy_sign =
      (kFlags & GLPT_FS_MESA_ORIENTED) == 0u && (S.drawable.y & 1u) == 0u ? -1.0 : 1.0;
  vec2 ddx = dFdxFine(c), ddy = dFdyFine(c) * ddy_sign;
  precise float rho_x = max(abs(ddx.x), abs(ddx.y)) * float(size.x);
  precise float rho_y = max(abs(ddy.x), abs(ddy.y)) * float(size.y);
  // lp_build_iceil, then an unsigned min: NaN and overflow give N.
  int count = int(ceil(max(rho_x, rho_y)));
  uint samples = min(uint(count), uint(anisotropy));
  vec2 step = rho_x > rho_y ? ddx : ddy;
  precise float float_n = float(samples);
  precise float rcp_n = 1.0 / float_n;
  precise float base_k = float_n * -0.5 + 0.5;
  precise vec4 sum = vec4(0.0);
  for (uint k = 0u; k < samples; ++k) {
    precise float float_k = (float(k) + base_k) * rcp_n;
    precise vec2 offset = vec2(float_k * step.x, float_k * step.y);
    precise vec2 at = c + offset;
    sum = sum + linear_texel_2d(u, at, size, level);
  }
  // No samples (a footprint of 0 texels: the same coordinates across the pixel's row and
  // column) is 0 * (1 / 0) in gallivm: NaN, which the colour conversion turns into 0.
  return sum * rcp_n;
}

// lp_build_sample_comparefunc: ref FUNC texel, ordered except GL_NOTEQUAL.
bool depth_test_passes(uint func, float ref, float texel) {
  if (func == 1u) return ref < texel;
  if (func == 2u) return ref == texel;
  if (func == 3u) return ref <= texel;
  if (func == 4u) return ref > texel;
  if (func == 5u) return !(ref == texel);
  if (func == 6u) return ref >= texel;
  return func == 7u;  // GL_NEVER + 7 = GL_ALWAYS
}

// One comparison against texel (x, y) of `level`, or against the border outside the level
// where the wrap mode uses the border (lp_build_sample_texel_soa).
float compare_texel(uint u, uint target, ivec2 p, ivec2 size, int level, float ref) {
  uint flags = S.tex_mode[u].y;
  bool filters_linear = (flags & (GLPT_TEX_MIN_LINEAR | GLPT_TEX_MAG_LINEAR)) != 0u;
  bool border = reads_border(u, target == 1u ? 1u : 2u, p, size, filters_linear);
  float texel = border ? S.tex_border[u].r
                       : depth_texel(u, target, clamp(p, ivec2(0), size - 1), level);
  return depth_test_passes(S.tex_mode[u].z, ref, texel) ? 1.0 : 0.0;
}

// One level's filtered comparison (lp_build_sample_image_nearest / _linear with compare).
float compare_level(uint u, uint target, vec2 c, int level, bool linear, float ref) {
  uint wraps = S.tex_mode[u].x;
  ivec2 size = max(ivec2(S.tex_size[u].xy) >> level, ivec2(1));
  if (target == 1u) size.y = 1;
  if (!linear) {
    ivec2 p = ivec2(wrap_nearest(wraps & 15u, c.x, size.x), 0);
    if (target != 1u) p.y = wrap_nearest((wraps >> 4u) & 15u, c.y, size.y);
    return compare_texel(u, target, p, size, level, ref);
  }
  int x0, x1, y0 = 0, y1 = 0;
  float ws, wt = 0.0;
  wrap_linear(wraps & 15u, c.x, size.x, x0, x1, ws);
  if (target != 1u) wrap_linear((wraps >> 4u) & 15u, c.y, size.y, y0, y1, wt);
  float m00 = compare_texel(u, target, ivec2(x0, y0), size, level, ref);
  float m01 = compare_texel(u, target, ivec2(x1, y0), size, level, ref);
  // lp_build_masklerp: the weights of the texels that pass, summed.
  precise float inv_ws = 1.0 - ws;
  precise float v0 = (m01 != 0.0 ? ws : 0.0) + (m00 != 0.0 ? inv_ws : 0.0);
  if (target == 1u) return v0;
  float m10 = compare_texel(u, target, ivec2(x0, y1), size, level, ref);
  float m11 = compare_texel(u, target, ivec2(x1, y1), size, level, ref);
  precise float v1 = (m11 != 0.0 ? ws : 0.0) + (m10 != 0.0 ? inv_ws : 0.0);
  return fma(wt, v1 - v0, v0);  // lp_build_lerp: lp_build_mad (llvm.fmuladd)
}

// The comparison result of unit u at the projected coordinates c. Mesa's fixed-function
// program takes the reference from the coordinate after the texture's own (ff_fragment_shader.c
// load_texture): t / q for a 1D texture, r / q for a 2D one.
float compare_unit(uint u, uint target, vec3 c) {
  uint flags = S.tex_mode[u].y;
  // gallivm clamps the reference to [0, 1] for normalized depth formats (all of Mesa's
  // GL_DEPTH_COMPONENT* formats).
  float ref = clamp(target == 1u ? c.y : c.z, 0.0, 1.0);
  vec3 ddx, ddy;
  quad_derivatives(c, ddx, ddy);
  uint dims = target == 1u ? 1u : 2u;
  Lod lod = select_lod(u, dims, ddx, ddy);
  bool min_linear = (flags & GLPT_TEX_MIN_LINEAR) != 0u;
  bool mag_linear = (flags & GLPT_TEX_MAG_LINEAR) != 0u;
  bool mipmapped = (flags & (GLPT_TEX_MIP_NEAREST | GLPT_TEX_MIP_LINEAR)) != 0u;
  if (min_linear != mag_linear && !lod.minified)
    return compare_level(u, target, c.xy, 0, mag_linear, ref);
  float result = compare_level(u, target, c.xy, lod.level0, min_linear, ref);
  if (mipmapped && (flags & GLPT_TEX_MIP_LINEAR) != 0u && lod.fpart > 0.0) {
    float second = compare_level(u, target, c.xy, lod.level1, min_linear, ref);
    result = fma(lod.fpart, second - result, result);
  }
  return result;
}

// ---- rectangle textures (ARB_texture_rectangle)

// The next float above x.
float next_float_up(float x) {
  uint bits = floatBitsToUint(x);
  return x > 0.0 ? uintBitsToFloat(bits + 1u) : x < 0.0 ? uintBitsToFloat(bits - 1u)
                                                     : uintBitsToFloat(1u);
}

// A texel coordinate s on an axis of `size` texels as a normalized one. llvmpipe samples
// rectangle textures with unnormalized coordinates, and gallivm's first step with normalized
// ones is c * size: where that product is exactly s, every later step (wrap, filter weights) is
// the same. s / size is such a c, or one float next to one.
float normalized_rect_coord(float s, float size) {
  precise float c = s / size;
  precise float back = c * size;
  if (back == s || isnan(back) || isinf(back)) return c;
  precise float other = back < s ? next_float_up(c) : -next_float_up(-c);
  precise float other_back = other * size;
  return other_back == s ? other : c;
}

// The texture colour of unit u: a projective lookup of (s, t, r) / q, as Mesa's fixed-function
// fragment program does.
vec4 sample_unit(uint u) {
  uint config = unit_config(u);
  uint target = config & 7u;
  vec4 tc = v_texcoord[u];
  if ((config & GLPT_UNIT_COORD_REPLACE) != 0u) {
    // Vulkan's point coordinate has t = 0 on the framebuffer's row 0, which is GL's bottom row
    // here: GL's default origin, GL_UPPER_LEFT, is its mirror.
    float t = (kFlags & GLPT_FS_SPRITE_LOWER_LEFT) != 0u ? gl_PointCoord.y : 1.0 - gl_PointCoord.y;
    tc = vec4(gl_PointCoord.x, t, 0.0, 1.0);
  }
  vec3 projected = tc.xyz / tc.w;
  if ((config & GLPT_UNIT_RECT) != 0u) {
    projected.x = normalized_rect_coord(projected.x, S.tex_size[u].x);
    projected.y = normalized_rect_coord(projected.y, S.tex_size[u].y);
  }
  if ((config & GLPT_UNIT_COMPARE) != 0u && (target == 1u || target == 2u))
    return vec4(compare_unit(u, target, projected));
  // gallivm wraps the anisotropic filter's texels itself: the coordinates stay unclamped.
  if (target == 2u && (config & GLPT_UNIT_ANISOTROPIC) != 0u)
    return anisotropic_2d(u, projected.xy);
  vec3 c = clamp_coords(u, config, projected);
  if (target != 4u && lod_matters(u)) {
    // The lod from the unclamped coordinates, as gallivm computes it before wrapping.
    float lod = mesa_explicit_lod(u, target, projected);
    if (target == 1u) {
      if (u == 0u) return textureLod(u_tex1d_0, c.x, lod);
      if (u == 1u) return textureLod(u_tex1d_1, c.x, lod);
      if (u == 2u) return textureLod(u_tex1d_2, c.x, lod);
      return textureLod(u_tex1d_3, c.x, lod);
    }
    if (target == 2u) {
      if (u == 0u) return textureLod(u_tex2d_0, c.xy, lod);
      if (u == 1u) return textureLod(u_tex2d_1, c.xy, lod);
      if (u == 2u) return textureLod(u_tex2d_2, c.xy, lod);
      return textureLod(u_tex2d_3, c.xy, lod);
    }
    if (u == 0u) return textureLod(u_tex3d_0, c, lod);
    if (u == 1u) return textureLod(u_tex3d_1, c, lod);
    if (u == 2u) return textureLod(u_tex3d_2, c, lod);
    return textureLod(u_tex3d_3, c, lod);
  }
  if (target == 1u) {
    if (u == 0u) return texture(u_tex1d_0, c.x);
    if (u == 1u) return texture(u_tex1d_1, c.x);
    if (u == 2u) return texture(u_tex1d_2, c.x);
    return texture(u_tex1d_3, c.x);
  }
  if (target == 2u) {
    if (u == 0u) return texture(u_tex2d_0, c.xy);
    if (u == 1u) return texture(u_tex2d_1, c.xy);
    if (u == 2u) return texture(u_tex2d_2, c.xy);
    return texture(u_tex2d_3, c.xy);
  }
  if (target == 3u) {
    if (u == 0u) return texture(u_tex3d_0, c);
    if (u == 1u) return texture(u_tex3d_1, c);
    if (u == 2u) return texture(u_tex3d_2, c);
    return texture(u_tex3d_3, c);
  }
  // Cube maps select a face by the direction (t, r); q does not take part.
  if (u == 0u) return texture(u_texcube_0, tc.xyz);
  if (u == 1u) return texture(u_texcube_1, tc.xyz);
  if (u == 2u) return texture(u_texcube_2, tc.xyz);
  return texture(u_texcube_3, tc.xyz);
}

// A depth texture's value as GL_DEPTH_TEXTURE_MODE presents it (GL 1.4 3.8.4; the base format
// code of the unit is the mode's): (d, d, d, 1), (d, d, d, d) or (0, 0, 0, d).
vec4 depth_texture_color(uint config, float d) {
  uint format = (config >> 6u) & 7u;
  if (format == 2u) return vec4(0.0, 0.0, 0.0, d);
  if (format == 5u) return vec4(d);
  return vec4(d, d, d, 1.0);
}

vec4 texture_color(uint u) {
  uint config = unit_config(u);
  vec4 t = sample_unit(u);
  return (config & GLPT_UNIT_DEPTH) != 0u ? depth_texture_color(config, t.r) : t;
}

vec4 combine_source(uint source, vec4 texel, vec4 primary, vec4 previous, vec4 constant,
                    vec4 texels[GLPT_RASTER_MAX_UNITS]) {
  if (source == GLPT_SRC_TEXTURE) return texel;
  if (source == GLPT_SRC_CONSTANT) return constant;
  if (source == GLPT_SRC_PRIMARY) return primary;
  if (source == GLPT_SRC_PREVIOUS) return previous;
  return texels[source - GLPT_SRC_TEXTURE0];
}

vec3 rgb_operand(uint operand, vec4 v) {
  if (operand == 0u) return v.rgb;
  if (operand == 1u) return 1.0 - v.rgb;
  if (operand == 2u) return vec3(v.a);
  return vec3(1.0 - v.a);
}

float alpha_operand(uint operand, vec4 v) { return operand == 0u ? v.a : 1.0 - v.a; }

vec3 combine_rgb(uint function, vec3 a0, vec3 a1, vec3 a2) {
  if (function == GLPT_COMBINE_REPLACE) return a0;
  if (function == GLPT_COMBINE_MODULATE) return a0 * a1;
  if (function == GLPT_COMBINE_ADD) return a0 + a1;
  if (function == GLPT_COMBINE_ADD_SIGNED) return a0 + a1 - 0.5;
  if (function == GLPT_COMBINE_INTERPOLATE) return a0 * a2 + a1 * (1.0 - a2);
  if (function == GLPT_COMBINE_SUBTRACT) return a0 - a1;
  return vec3(4.0 * dot(a0 - 0.5, a1 - 0.5));  // DOT3_RGB(A)
}

float combine_alpha(uint function, float a0, float a1, float a2) {
  if (function == GLPT_COMBINE_REPLACE) return a0;
  if (function == GLPT_COMBINE_MODULATE) return a0 * a1;
  if (function == GLPT_COMBINE_ADD) return a0 + a1;
  if (function == GLPT_COMBINE_ADD_SIGNED) return a0 + a1 - 0.5;
  if (function == GLPT_COMBINE_INTERPOLATE) return a0 * a2 + a1 * (1.0 - a2);
  return a0 - a1;  // SUBTRACT
}

// GL 1.5 table 3.22/3.23: one unit's environment applied to the fragment colour `cf`.
vec4 texture_environment(uint u, vec4 texel, vec4 cf, vec4 primary, vec4 constant, vec4 scale,
                         vec4 texels[GLPT_RASTER_MAX_UNITS]) {
  uint config = unit_config(u);
  uint mode = (config >> 3u) & 7u;
  uint format = (config >> 6u) & 7u;
  const uint kRgba = 0u, kRgb = 1u, kAlpha = 2u, kLuminance = 3u, kLuminanceAlpha = 4u;
  // Components the texture has: L/I give their value as RGB (stored expanded); ALPHA has no
  // colour; RGB/L have no alpha. `texel` already holds GL's expansion (rgb of A is 0, a of RGB
  // is 1), so only the formulas that treat missing components as "keep the fragment's" differ.
  bool has_color = format != kAlpha;
  bool has_alpha = format == kRgba || format == kAlpha || format == kLuminanceAlpha || format == 5u;
  vec4 result = cf;
  if (mode == 0u) {  // MODULATE
    result.rgb = has_color ? cf.rgb * texel.rgb : cf.rgb;
    result.a = has_alpha ? cf.a * texel.a : cf.a;
  } else if (mode == 1u) {  // DECAL (defined for RGB and RGBA)
    if (format == kRgb) result.rgb = texel.rgb;
    if (format == kRgba) result.rgb = mix(cf.rgb, texel.rgb, texel.a);
  } else if (mode == 2u) {  // BLEND
    if (has_color) result.rgb = mix(cf.rgb, constant.rgb, texel.rgb);
    if (has_alpha) result.a = format == 5u ? mix(cf.a, constant.a, texel.a) : cf.a * texel.a;
  } else if (mode == 3u) {  // REPLACE
    if (has_color) result.rgb = texel.rgb;
    if (has_alpha) result.a = texel.a;
  } else if (mode == 4u) {  // ADD
    if (has_color) result.rgb = cf.rgb + texel.rgb;
    if (has_alpha) result.a = format == 5u ? cf.a + texel.a : cf.a * texel.a;
  } else {  // COMBINE
    uint c = unit_combine(u);
    uint alpha_operands = unit_alpha_operands(u);
    vec4 previous = cf;
    vec3 a_rgb[3];
    float a_alpha[3];
    for (uint i = 0u; i < 3u; ++i) {
      vec4 src_rgb =
          combine_source((c >> (8u + 3u * i)) & 7u, texel, primary, previous, constant, texels);
      vec4 src_alpha =
          combine_source((c >> (17u + 3u * i)) & 7u, texel, primary, previous, constant, texels);
      a_rgb[i] = rgb_operand((c >> (26u + 2u * i)) & 3u, src_rgb);
      a_alpha[i] = alpha_operand((alpha_operands >> i) & 1u, src_alpha);
    }
    uint rgb_function = c & 15u;
    result.rgb = clamp(combine_rgb(rgb_function, a_rgb[0], a_rgb[1], a_rgb[2]) * scale.x, 0.0, 1.0);
    if (rgb_function == GLPT_COMBINE_DOT3_RGBA) {
      result.a = result.r;
    } else {
      result.a = clamp(combine_alpha((c >> 4u) & 15u, a_alpha[0], a_alpha[1], a_alpha[2]) * scale.y,
                       0.0, 1.0);
    }
    return result;
  }
  return clamp(result, 0.0, 1.0);
}

bool alpha_test_passes(float alpha, float ref) {
  uint func = (kAlphaFog >> 8u) & 7u;  // GL_NEVER + func - 1
  if (func == 1u) return false;                 // NEVER
  if (func == 2u) return alpha < ref;           // LESS
  if (func == 3u) return alpha == ref;          // EQUAL
  if (func == 4u) return alpha <= ref;          // LEQUAL
  if (func == 5u) return alpha > ref;           // GREATER
  if (func == 6u) return alpha != ref;          // NOTEQUAL
  if (func == 7u) return alpha >= ref;          // GEQUAL
  return true;                                  // ALWAYS
}

#if GLPT_PIXELS
// GL 1.5 3.6.4 "Zoom": the image group whose zoomed rectangle holds the fragment's centre, as
// Mesa picks it where a centre lies exactly on a group edge: tabulated per window column and row
// (and per triangle of Mesa's quad) by rt_core/raster/pixel_quad.cpp.
ivec2 pixel_group() {
  ivec2 window = ivec2(floor(gl_FragCoord.xy)) - ivec2(int(S.pixel_table.y), int(S.pixel_table.z));
  ivec2 size = ivec2(S.pixel_image.zw);
  if (S.pixel_table.x == 0xFFFFFFFFu) return clamp(window, ivec2(0), size - 1);
  bool first = dot(S.pixel_diagonal.xy, gl_FragCoord.xy) + S.pixel_diagonal.z >= 0.0;
  uint column = pixel_words[S.pixel_table.x + uint(max(window.x, 0))];
  uint row = pixel_words[S.pixel_table.x + S.pixel_table.w + uint(max(window.y, 0))];
  return ivec2(first ? column & 0xFFFFu : column >> 16u, first ? row & 0xFFFFu : row >> 16u);
}

// The fragment colour of a pixel rectangle: the image's colour for colour images, `color` (the
// raster colour) otherwise. Depth images give the fragment depth; bitmaps and stencil passes
// discard the fragments their value does not select (push.indices.z). Groups outside the
// stored rectangle of a copy read as zero.
vec4 pixel_fragment(vec4 color) {
  ivec2 g = pixel_group();
  // Copies count rows from the top (Mesa reads its y-inverted buffer into the texture).

  ivec2 p = g - ivec2(S.pixel_stored.xy);
  bool stored = all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, ivec2(S.pixel_stored.zw)));
  uint index = stored ? uint(p.y) * S.pixel_stored.z + uint(p.x) : 0u;
  uint word = S.pixel_image.y + index;
  uint format = S.pixel_image.x;
  float depth = gl_FragCoord.z;
  uint value = 0u;
  if (format == GLPT_PIXELS_RGBA32F) {
    word = S.pixel_image.y + 4u * index;
    vec4 c = vec4(uintBitsToFloat(pixel_words[word]), uintBitsToFloat(pixel_words[word + 1u]),
                  uintBitsToFloat(pixel_words[word + 2u]), uintBitsToFloat(pixel_words[word + 3u]));
    color = clamp((stored ? c : vec4(0.0)) * S.pixel_scale + S.pixel_bias, 0.0, 1.0);
  } else if (format == GLPT_PIXELS_RGBA8) {
    // A copy of the BGRA8 colour buffer; bytes times 1/255, as llvmpipe converts Mesa's copy.
    uint b = pixel_words[word];
    vec4 c = vec4(uvec4(b >> 16u, b >> 8u, b, b >> 24u) & 0xFFu) * (1.0 / 255.0);
    color = clamp((stored ? c : vec4(0.0)) * S.pixel_scale + S.pixel_bias, 0.0, 1.0);
  } else if (format == GLPT_PIXELS_DEPTH32F) {
    depth = stored ? uintBitsToFloat(pixel_words[word]) : 0.0;
  } else if (format == GLPT_PIXELS_DEPTH24) {
    depth = stored ? float(pixel_words[word] & 0xFFFFFFu) / 16777215.0 : 0.0;
  } else if (format == GLPT_PIXELS_VALUE32) {
    value = stored ? pixel_words[word] : 0u;
  } else {  // GLPT_PIXELS_VALUE8
    uint packed = pixel_words[S.pixel_image.y + index / 4u];
    value = stored ? (packed >> (8u * (index & 3u))) & 0xFFu : 0u;
  }
#if GLPT_PIXELS == 2
  gl_FragDepth = depth;
#endif
  uint keep = push.indices.z;
  if (keep == GLPT_PIXELS_KEEP_NONZERO && value == 0u) discard;
  if ((keep & GLPT_PIXELS_KEEP_BIT) != 0u && ((value >> (keep & 7u)) & 1u) == 0u) discard;
  return color;
}
#endif

#if GLPT_GBUFFER
vec3 normalize_or(vec3 v, vec3 fallback) {
  float len2 = dot(v, v);
  return len2 > 1.0e-30 && !isinf(len2) ? v * inversesqrt(len2) : fallback;
}

// The texture units applied to `base` (a material colour) instead of the lit colour: the
// surface's albedo under GL's texture environments.
vec4 textured(vec4 base, vec4 texels[GLPT_RASTER_MAX_UNITS]) {
  vec4 color = base;
  for (uint u = 0u; u < GLPT_RASTER_MAX_UNITS; ++u) {
    if ((unit_config(u) & 7u) == 0u) continue;
    color = texture_environment(u, texels[u], color, base, S.env_color[u], S.env_scale[u], texels);
  }
  return color;
}

#include "raster_vertex_words.h"

// The material GL lights this fragment's vertices with: the state's, or where glMaterial was
// called between glBegin and glEnd the vertices' own: the provoking (last) vertex's under
// GL_FLAT, else interpolated across the triangle as GL interpolates the colours lit with them.
RasterMaterial gbuffer_vertex_material(uint face) {
  if (push.materials.z == 0u) return S.material[face];
#if GLPT_FLAT
  return vertex_material(v_corner_vertex.z, face);
#else
  vec3 w = vec3(1.0 - v_barycentric.x - v_barycentric.y, v_barycentric);
  RasterMaterial m0 = vertex_material(v_corner_vertex.x, face);
  RasterMaterial m1 = vertex_material(v_corner_vertex.y, face);
  RasterMaterial m2 = vertex_material(v_corner_vertex.z, face);
  RasterMaterial m;
  m.ambient = w.x * m0.ambient + w.y * m1.ambient + w.z * m2.ambient;
  m.diffuse = w.x * m0.diffuse + w.y * m1.diffuse + w.z * m2.diffuse;
  m.specular = w.x * m0.specular + w.y * m1.specular + w.z * m2.specular;
  m.emission = w.x * m0.emission + w.y * m1.emission + w.z * m2.emission;
  m.shininess = w.x * m0.shininess + w.y * m1.shininess + w.z * m2.shininess;
  return m;
#endif
}

// `color`: the fragment's colour as raster mode computes it (the lit colour after texturing,
// colour sum and fog); `back`: two-sided lighting lights the back face.
void write_gbuffer(vec4 color, bool back, vec4 texels[GLPT_RASTER_MAX_UNITS]) {
  vec3 p = v_eye.xyz / v_eye.w;
  vec3 edge1 = v_corner[1] - v_corner[0], edge2 = v_corner[2] - v_corner[0];
  vec3 shading = normalize_or(v_normal, vec3(0.0, 0.0, 1.0));
  vec3 geometric = normalize_or(cross(edge1, edge2), shading);
  o_position = vec4(p, v_fog);
  uint flags = gbuffer_pack_precision(v_term_magnitude);
  if ((kVsFlags & GLPT_VS_LIGHTING) == 0u) {
    // Unlit: the exact colour raster mode writes; nothing to trace at this pixel.
    o_surface = uvec4(v_state + 1u, gbuffer_pack_normal(shading),
                      gbuffer_pack_normal(geometric), flags);
    o_material0 = uvec4(packUnorm4x8(clamp(color, 0.0, 1.0)), 0u, 0u, 0u);
    o_material1 = uvec4(0u);
    return;
  }
  flags |= GLPT_GBUFFER_LIT;
  uint face = back ? 1u : 0u;
  if (back) {
    flags |= GLPT_GBUFFER_BACK_FACE;
    shading = -shading;
  }
  // GL_COLOR_MATERIAL: the current colour replaces the tracked material colours (as
  // raster_ff.vert's light_face).
  RasterMaterial m = gbuffer_vertex_material(face);
  vec4 ambient = m.ambient, diffuse = m.diffuse, specular = m.specular, emission = m.emission;
  const uint cm_mode = kColorMaterial & 7u;
  if ((kColorMaterial & (face == 0u ? 8u : 16u)) != 0u) {
    if (cm_mode == 1u || cm_mode == 3u) ambient = v_vertex_color;
    if (cm_mode == 2u || cm_mode == 3u) diffuse = v_vertex_color;
    if (cm_mode == 4u) specular = v_vertex_color;
    if (cm_mode == 5u) emission = v_vertex_color;
  }
  // GL's texture environment receives the lit colour (GL 1.5 3.9): emission, and specular under
  // GL_SINGLE_COLOR, are textured with it. Every environment is affine in the fragment colour,
  // f(c) = A c + B per component: those terms get A c = f(c) - f(0); B stays with the albedo.
  vec3 offset = textured(vec4(0.0, 0.0, 0.0, 1.0), texels).rgb;
  emission.rgb = textured(vec4(emission.rgb, 1.0), texels).rgb - offset;
  if ((kVsFlags & GLPT_VS_SEPARATE_SPECULAR) == 0u)
    specular.rgb = textured(vec4(specular.rgb, 1.0), texels).rgb - offset;
  diffuse = vec4(textured(diffuse, texels).rgb, color.a);  // alpha: GL's fragment alpha
  ambient = textured(ambient, texels);

  // Hanika's shadow-terminator fix ("Hacking the shadow terminator", Ray Tracing Gems II ch. 4):
  // secondary rays from the flat triangle of a coarse smooth mesh would hit its neighbours near
  // the terminator; their origin moves onto the curved surface the vertex normals describe.
  vec3 w = vec3(1.0 - v_barycentric.x - v_barycentric.y, v_barycentric);
  vec3 lift = vec3(0.0);
  for (int i = 0; i < 3; ++i) {
    vec3 u = normalize_or(v_corner_normal[i], geometric);
    lift -= w[i] * min(0.0, dot(p - v_corner[i], u)) * u;
  }
  if (any(isnan(lift)) || any(isinf(lift))) lift = vec3(0.0);

  o_surface = uvec4(v_state + 1u, gbuffer_pack_normal(shading),
                    gbuffer_pack_normal(geometric), flags | (packHalf2x16(vec2(m.shininess.x, 0.0)) << 16));
  o_material0 = uvec4(packHalf2x16(diffuse.rg), packHalf2x16(diffuse.ba), packHalf2x16(ambient.rg),
                      packHalf2x16(vec2(ambient.b, specular.r)));
  o_material1 = uvec4(packHalf2x16(specular.gb), packHalf2x16(emission.rg),
                      packHalf2x16(vec2(emission.b, lift.x)), packHalf2x16(lift.yz));
}
#endif

void main() {
#if !GLPT_GBUFFER
  if ((kFlags & GLPT_FS_CLEAR) != 0u) {
    o_color = S.clear_color;
#if !GLPT_FRAMEBUFFER_OPS
    o_color_second = o_color;
#endif
    return;
  }
#endif
  // gl_FragCoord and gl_FrontFacing only in the variants that read them (raster_types.h,
  // GLPT_VARYING_WINDOW_POSITION).
#if (GLPT_VARYINGS & GLPT_VARYING_WINDOW_POSITION) != 0
  if ((kFlags & GLPT_FS_POLYGON_STIPPLE) != 0u) {
    uint row = uint(gl_FragCoord.y) & 31u, column = uint(gl_FragCoord.x) & 31u;
    if (((S.stipple[row >> 2u][row & 3u] >> (31u - column)) & 1u) == 0u) discard;
  }
#endif
#if (GLPT_VARYINGS & GLPT_VARYING_BACK) != 0
  bool back = (kFlags & GLPT_FS_TWO_SIDE) != 0u && !gl_FrontFacing;
#else
  bool back = false;  // two-sided lighting selects a variant with the back colours
#endif
  vec4 primary = back ? v_back_color : v_front_color;
  vec4 secondary = back ? v_back_secondary : v_front_secondary;
#if GLPT_PIXELS
  primary = pixel_fragment(primary);
#endif

  // Texture units in order; every unit's texel first (crossbar sources may name any unit).
  vec4 texels[GLPT_RASTER_MAX_UNITS];
  for (uint u = 0u; u < GLPT_RASTER_MAX_UNITS; ++u)
    texels[u] = (unit_config(u) & 7u) != 0u ? texture_color(u) : vec4(1.0);
  vec4 color = primary;
  for (uint u = 0u; u < GLPT_RASTER_MAX_UNITS; ++u) {
    if ((unit_config(u) & 7u) == 0u) continue;
    color = texture_environment(u, texels[u], color, primary, S.env_color[u], S.env_scale[u],
                                texels);
  }

  // Colour sum (GL 1.5 3.9). The spec clamps the sum to [0, 1]; Mesa's fixed-function fragment
  // program adds the secondary colour unclamped and fogs that (ff_fragment_shader.c), which
  // shows where the sum exceeds 1 under fog. Raster mode matches Mesa; the G-buffer keeps the
  // clamped sum, as an albedo above 1 would create light.
  if ((kFlags & GLPT_FS_COLOR_SUM) != 0u) {
#if GLPT_GBUFFER
    color.rgb = min(color.rgb + secondary.rgb, 1.0);
#else
    color.rgb += secondary.rgb;
#endif
  }

  uint fog_mode = (kAlphaFog >> 12u) & 3u;
  if (fog_mode != 0u) {
    float z = v_fog;
    float f;
    if (fog_mode == 1u)
      f = (S.fog_params.z - z) * S.fog_params.w;
    else if (fog_mode == 2u)
      f = exp(-S.fog_params.x * z);
    else
      f = exp(-(S.fog_params.x * z) * (S.fog_params.x * z));
    f = clamp(f, 0.0, 1.0);
    color.rgb = mix(S.fog_color.rgb, color.rgb, f);
  }

  if (!alpha_test_passes(color.a, S.alpha_ref.x)) discard;
  // The part of a draw split by alpha this pass draws.
  if ((kFlags & GLPT_FS_OPAQUE_PART) != 0u && color.a < GLPT_OPAQUE_ALPHA) discard;
  if ((kFlags & GLPT_FS_TRANSLUCENT_PART) != 0u && color.a >= GLPT_OPAQUE_ALPHA) discard;
#if GLPT_GBUFFER
  write_gbuffer(color, back, texels);
#else
#if GLPT_FRAMEBUFFER_OPS
  o_color = framebuffer_ops(color, subpassLoad(u_framebuffer), push.framebuffer_ops);
#else
  o_color = color;
  o_color_second = color;
#endif
#endif
}
