// The surface model GL materials map to (docs/light-transport.md, "Materials"): a Lambertian
// diffuse lobe under a GGX specular lobe, energy-conserving, with GL's colours. Pure functions
// shared by GLSL and C++ (glsl_cpp.h): tests/light_transport checks that the lobes never reflect
// more than they receive and that each sampling density integrates to one.
//
// Local frame throughout: the shading normal is +z, v points to the viewer, l to the light.
#ifndef GLPT_SHADERS_TRACE_BSDF_H
#define GLPT_SHADERS_TRACE_BSDF_H

#include "sampling.h"

#ifdef __cplusplus
namespace glpt::rt::gpu {
using namespace glm;
#endif

#define GLPT_LOBE_DIFFUSE 0u
#define GLPT_LOBE_SPECULAR 1u

struct Bsdf {
  vec3 diffuse;   // Lambertian reflectance (the albedo the channels divide out)
  vec3 specular;  // GGX lobe reflectance at normal incidence (no Fresnel: GL has none)
  float alpha;    // GGX roughness
};

// GL's shininess s is the exponent of an unnormalised Blinn-Phong lobe (n.h)^s. Walter et al.
// 2007 match Blinn-Phong to a microfacet distribution of the same width by alpha = sqrt(2/(s+2)).
GLPT_FN float shininess_to_alpha(float shininess) {
  return clamp(sqrt(2.0f / (clamp(shininess, 0.0f, 128.0f) + 2.0f)), 0.02f, 1.0f);
}

// GL's lobe is not normalised: at normal incidence it reflects 8 ks (1 - 2^-(s/2+1)) / (s + 2) of
// the light (docs/light-transport.md derives it), which is also the reflectance a normalised lobe
// needs to show GL's peak brightness. The GGX lobe takes that reflectance, at most 1.
GLPT_FN float specular_reflectance_scale(float shininess) {
  float s = clamp(shininess, 0.0f, 128.0f);
  return min(1.0f, 8.0f * (1.0f - exp2(-0.5f * s - 1.0f)) / (s + 2.0f));
}

GLPT_FN float max3(vec3 v) { return max(v.x, max(v.y, v.z)); }

GLPT_FN float luminance(vec3 c) { return dot(c, vec3(0.2126f, 0.7152f, 0.0722f)); }

// The material of a GL surface: diffuse (after colour material and the texture environment),
// specular and shininess. The diffuse lobe receives what the specular lobe does not reflect, so
// the two together never reflect more than 1 (the GGX lobe's own albedo is at most its
// reflectance).
GLPT_FN Bsdf material_bsdf(vec3 diffuse_gl, vec3 specular_gl, float shininess) {
  Bsdf bsdf;
  bsdf.specular = clamp(specular_gl, vec3(0.0f), vec3(1.0f)) *
                  specular_reflectance_scale(shininess);
  bsdf.diffuse = clamp(diffuse_gl, vec3(0.0f), vec3(1.0f)) * (1.0f - max3(bsdf.specular));
  bsdf.alpha = shininess_to_alpha(shininess);
  return bsdf;
}

// f * cos(theta_l) of one lobe, for directions v and l (local frame).
// The diffuse lobe does not depend on v; the specular one needs v above the surface.
GLPT_FN vec3 bsdf_lobe_cos(Bsdf bsdf, uint lobe, vec3 v, vec3 l) {
  if (l.z <= 0.0f) return vec3(0.0f);
  if (lobe == GLPT_LOBE_DIFFUSE) return bsdf.diffuse * (l.z / kPi);
  if (v.z <= 0.0f) return vec3(0.0f);
  vec3 h = normalize(v + l);
  float d = ggx_d(h.z, bsdf.alpha);
  float g = ggx_g2(v.z, l.z, bsdf.alpha);
  return bsdf.specular * (d * g / (4.0f * v.z));
}

// The probability of choosing each lobe for a bounce: in proportion to its reflectance.
GLPT_FN float specular_lobe_probability(Bsdf bsdf) {
  float d = luminance(bsdf.diffuse);
  float s = luminance(bsdf.specular);
  return d + s > 0.0f ? s / (d + s) : 0.0f;
}

GLPT_FN float lobe_probability(Bsdf bsdf, uint lobe) {
  float p = specular_lobe_probability(bsdf);
  return lobe == GLPT_LOBE_SPECULAR ? p : 1.0f - p;
}

// The density of `lobe`'s own sampling routine (local frame).
GLPT_FN float lobe_pdf(Bsdf bsdf, uint lobe, vec3 v, vec3 l) {
  if (lobe == GLPT_LOBE_DIFFUSE) return max(l.z, 0.0f) / kPi;
  return ggx_vndf_reflection_pdf(v, l, bsdf.alpha);
}

// Samples a direction of `lobe` (local frame); z <= 0 means the sample is lost (below the
// surface).
GLPT_FN vec3 sample_lobe(Bsdf bsdf, uint lobe, vec3 v, vec2 u) {
  if (lobe == GLPT_LOBE_DIFFUSE) return sample_cosine_hemisphere(vec3(0.0f, 0.0f, 1.0f), u);
  vec3 h = sample_ggx_vndf(v, bsdf.alpha, u);
  return reflect(-v, h);
}

#ifdef __cplusplus
}  // namespace glpt::rt::gpu
#endif

#endif  // GLPT_SHADERS_TRACE_BSDF_H
