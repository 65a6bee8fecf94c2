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

// The diffuse channels hold radiance / albedo (so a denoiser blurs lighting, not texture); where
// a component of the albedo is ~0 its radiance is kept as it is (divided by 1), which the
// composite pass undoes the same way.
vec3 demodulation_albedo(vec3 albedo) {
  return mix(vec3(1.0), albedo, greaterThan(albedo, vec3(1.0e-3)));
}

// The albedo of a lit G-buffer pixel: its BSDF's diffuse reflectance.
vec3 gbuffer_albedo(GBufferMaterial m) {
  return demodulation_albedo(material_bsdf(m.diffuse.rgb, m.specular, m.shininess).diffuse);
}

#endif  // GLPT_SHADERS_TRACE_GBUFFER_MATERIAL_H
