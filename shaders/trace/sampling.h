// Sampling routines of the trace pass and their densities: pure functions of uniform random
// numbers, shared by GLSL and C++ (glsl_cpp.h) so tests/light_transport integrates each pdf.
// Directions are unit vectors in eye space; every pdf is per unit solid angle.
#ifndef GLPT_SHADERS_TRACE_SAMPLING_H
#define GLPT_SHADERS_TRACE_SAMPLING_H

#include "glsl_cpp.h"

#ifdef __cplusplus
namespace glpt::rt::gpu {
using namespace glm;
#endif

GLPT_CONST float kPi = 3.14159265358979f;

// An orthonormal basis (t, b, n) around a unit vector (Duff et al. 2017, branchless).
struct Basis {
  vec3 t;
  vec3 b;
  vec3 n;
};

GLPT_FN Basis make_basis(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  float c = n.x * n.y * a;
  Basis basis;
  basis.t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
  basis.b = vec3(c, s + n.y * n.y * a, -n.y);
  basis.n = n;
  return basis;
}

GLPT_FN vec3 to_world(Basis basis, vec3 local) {
  return local.x * basis.t + local.y * basis.b + local.z * basis.n;
}

GLPT_FN vec3 to_local(Basis basis, vec3 world) {
  return vec3(dot(world, basis.t), dot(world, basis.b), dot(world, basis.n));
}

// ---- cosine-weighted hemisphere (diffuse bounces, ambient occlusion) --------------------------

GLPT_FN vec3 sample_cosine_hemisphere(vec3 n, vec2 u) {
  float r = sqrt(u.x);
  float phi = 2.0f * kPi * u.y;
  return normalize(to_world(make_basis(n), vec3(r * cos(phi), r * sin(phi),
                                                sqrt(max(0.0f, 1.0f - u.x)))));
}

GLPT_FN float cosine_hemisphere_pdf(vec3 n, vec3 direction) {
  return max(dot(n, direction), 0.0f) / kPi;
}

// ---- cones (sphere lights, distant lights with an angular radius) -----------------------------
// A cone of half-angle a around `axis` is given by 1 - cos(a): for the tiny cones of far lights
// it would cancel in float if computed as such, sin^2(a) / (1 + cos(a)) does not.

GLPT_FN vec3 sample_cone(vec3 axis, float one_minus_cos_max, vec2 u) {
  float one_minus_cos = u.x * one_minus_cos_max;
  float cos_theta = 1.0f - one_minus_cos;
  float sin_theta = sqrt(max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
  float phi = 2.0f * kPi * u.y;
  return normalize(to_world(make_basis(axis), vec3(sin_theta * cos(phi), sin_theta * sin(phi),
                                                   cos_theta)));
}

// The density of sample_cone: uniform over the cone's solid angle 2 pi (1 - cos a).
GLPT_FN float cone_pdf(float one_minus_cos_max) {
  return 1.0f / (2.0f * kPi * max(one_minus_cos_max, 1.0e-30f));
}

// ---- triangles (emissive surfaces) ------------------------------------------------------------

// Barycentric weights (w0, w1, w2) of a point uniformly distributed over a triangle's area
// (Shirley & Chiu's square-to-triangle map).
GLPT_FN vec3 sample_triangle_uniform(vec2 u) {
  float r = sqrt(u.x);
  return vec3(1.0f - r, r * (1.0f - u.y), r * u.y);
}

// The solid-angle density of a direction towards a point sampled uniformly over a triangle of
// area `area`, seen at `distance` with cosine `cos_at_light` between the triangle's normal and
// the direction (either side: GL's emission leaves both faces): d^2 / (area |cos|).
GLPT_FN float triangle_solid_angle_pdf(float area, float distance, float cos_at_light) {
  float c = abs(cos_at_light);
  return area > 0.0f && c > 0.0f ? distance * distance / (area * c) : 0.0f;
}

// ---- GGX (Trowbridge-Reitz) microfacets, Smith height-correlated masking ----------------------
// Local frame: the shading normal is +z.

GLPT_FN float ggx_d(float n_dot_h, float alpha) {
  float a2 = alpha * alpha;
  float d = n_dot_h * n_dot_h * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
}

// Smith's Lambda for GGX (Heitz 2014, eq. 72).
GLPT_FN float ggx_lambda(float cos_theta, float alpha) {
  float c2 = max(cos_theta * cos_theta, 1.0e-12f);
  float tan2 = max(1.0f - c2, 0.0f) / c2;
  return 0.5f * (sqrt(1.0f + alpha * alpha * tan2) - 1.0f);
}

GLPT_FN float ggx_g1(float cos_theta, float alpha) {
  return 1.0f / (1.0f + ggx_lambda(cos_theta, alpha));
}

GLPT_FN float ggx_g2(float n_dot_v, float n_dot_l, float alpha) {
  return 1.0f / (1.0f + ggx_lambda(n_dot_v, alpha) + ggx_lambda(n_dot_l, alpha));
}

// Visible-normal sampling (Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 2018):
// returns the microfacet normal h for the local view direction v (v.z > 0).
GLPT_FN vec3 sample_ggx_vndf(vec3 v, float alpha, vec2 u) {
  vec3 vh = normalize(vec3(alpha * v.x, alpha * v.y, v.z));
  float len2 = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = len2 > 0.0f ? vec3(-vh.y, vh.x, 0.0f) * inversesqrt(len2) : vec3(1.0f, 0.0f, 0.0f);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0f * kPi * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0f, nh.z)));
}

// The density of the reflected direction l = reflect(-v, h) when h comes from sample_ggx_vndf:
// D_v(h) / (4 v.h) = G1(v) D(h) / (4 n.v).
GLPT_FN float ggx_vndf_reflection_pdf(vec3 v, vec3 l, float alpha) {
  if (v.z <= 0.0f || l.z <= 0.0f) return 0.0f;
  vec3 h = normalize(v + l);
  return ggx_g1(v.z, alpha) * ggx_d(h.z, alpha) / (4.0f * v.z);
}

// ---- multiple importance sampling -------------------------------------------------------------

// Veach's power heuristic (beta = 2): the weight of a sample of density `pdf_a` that technique b
// (density `pdf_b`) could also have produced.
GLPT_FN float power_heuristic(float pdf_a, float pdf_b) {
  float a2 = pdf_a * pdf_a;
  float b2 = pdf_b * pdf_b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

#ifdef __cplusplus
}  // namespace glpt::rt::gpu
#endif

#endif  // GLPT_SHADERS_TRACE_SAMPLING_H
