// The material a G-buffer pixel holds (gbuffer_layout.h), decoded the same way by the trace pass
// and the composite pass, and the albedo the diffuse channels are divided by.
#ifndef GLPT_SHADERS_TRACE_GBUFFER_MATERIAL_H
#define GLPT_SHADERS_TRACE_GBUFFER_MATERIAL_H

#include "bsdf.h"

struct GBufferMaterial {
  vec4 diffuse;  // a: GL's fragment alpha
  vec3 ambient;
  vec3 specular;
  vec3 emission;
  float shininess;
  vec3 lift;  // the shadow-terminator displacement of secondary-ray origins
};

GBufferMaterial gbuffer_material(uvec4 surface, uvec4 m0, uvec4 m1) {
  GBufferMaterial m;
  m.diffuse = vec4(unpackHalf2x16(m0.x), unpackHalf2x16(m0.y));
  vec2 ambient_rg = unpackHalf2x16(m0.z), ambient_b_specular_r = unpackHalf2x16(m0.w);
  m.ambient = vec3(ambient_rg, ambient_b_specular_r.x);
  m.specular = vec3(ambient_b_specular_r.y, unpackHalf2x16(m1.x));
  vec2 emission_b_lift_x = unpackHalf2x16(m1.z);
  m.emission = vec3(unpackHalf2x16(m1.y), emission_b_lift_x.x);
  m.lift = vec3(emission_b_lift_x.y, unpackHalf2x16(m1.w));
  m.shininess = unpackHalf2x16(surface.w >> 16).x;
  return m;
}

// The diffuse channels hold light per unit of albedo (so a denoiser blurs lighting, not texture),
// which the composite pass multiplies by the albedo. The trace pass evaluates the primary
// vertex's lobes with unit reflectance (path_trace.comp), so a texel of ~0 albedo (black
// lettering) still estimates the light falling on it, as its neighbours' filtering needs: its
// value is light, not a 0 the denoiser would spread into them. One exception per component:
// where the albedo is ~0 but the surface still reflects something the diffuse channels carry
// (GL's ambient term, or GL's diffuse colour that the specular lobe's energy left no room for in
// the albedo), the channels hold that radiance as it is and the composite multiplies it by 1.
const float kAlbedoFloor = 1.0e-3;

// 1 per component where the diffuse channels hold radiance as it is, 0 where light per unit of
// albedo: `albedo` the BSDF's diffuse reflectance, `diffuse_gl` and `ambient` GL's colours.
vec3 raw_diffuse(vec3 albedo, vec3 diffuse_gl, vec3 ambient) {
  return vec3(lessThan(albedo, vec3(kAlbedoFloor))) *
         vec3(greaterThanEqual(max(ambient, diffuse_gl), vec3(kAlbedoFloor)));
}

// What the composite pass multiplies the diffuse channels by.
vec3 diffuse_channel_factor(vec3 albedo, vec3 diffuse_gl, vec3 ambient) {
  return mix(albedo, vec3(1.0), raw_diffuse(albedo, diffuse_gl, ambient));
}

// Radiance `value` of a lobe of reflectance `reflectance` per unit of reflectance; 0 where the
// reflectance is ~0 (the radiance is then at most kAlbedoFloor times the light: dropped, rather
// than divided into a value the denoiser would spread).
vec3 per_unit_reflectance(vec3 value, vec3 reflectance) {
  return mix(vec3(0.0), value / max(reflectance, vec3(kAlbedoFloor)),
             greaterThanEqual(reflectance, vec3(kAlbedoFloor)));
}

#endif  // GLPT_SHADERS_TRACE_GBUFFER_MATERIAL_H
