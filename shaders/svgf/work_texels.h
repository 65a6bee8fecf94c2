// The denoiser's texels of half floats (shared_types.h, GLPT_DN_BINDING_WORK): a channel's rgb
// radiance and variance (or the fast average's rgb) as four halves in two words, two channels
// to an rgba32ui texel. Written by the SVGF passes, read by them and by the composite.
#ifndef GLPT_SHADERS_SVGF_WORK_TEXELS_H
#define GLPT_SHADERS_SVGF_WORK_TEXELS_H

uvec2 pack_work(vec4 value) {
  value = clamp(value, vec4(-65504.0), vec4(65504.0));  // beyond the largest half: infinite
  return uvec2(packHalf2x16(value.rg), packHalf2x16(value.ba));
}
vec4 unpack_work(uvec2 packed) { return vec4(unpackHalf2x16(packed.x), unpackHalf2x16(packed.y)); }

#endif  // GLPT_SHADERS_SVGF_WORK_TEXELS_H
