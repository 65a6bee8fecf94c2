// The trace pass's sampling routines and BSDF (shaders/trace/sampling.h, bsdf.h), compiled as C++
// from the same headers the shader includes: every density integrates to one, each sampler
// produces its own density, the material never reflects more than it receives, and GL's
// shininess maps to the reflectance its Blinn-Phong lobe has.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "trace/bsdf.h"

namespace {

using namespace glpt::rt::gpu;

// Midpoint quadrature of f(direction) over the sphere (or the upper hemisphere).
template <typename F>
double integrate_sphere(F f, bool upper_only, int n_theta = 600, int n_phi = 1200) {
  const double theta_max = upper_only ? M_PI / 2 : M_PI;
  const double d_theta = theta_max / n_theta, d_phi = 2 * M_PI / n_phi;
  double sum = 0;
  for (int i = 0; i < n_theta; ++i) {
    const double theta = (i + 0.5) * d_theta;
    for (int j = 0; j < n_phi; ++j) {
      const double phi = (j + 0.5) * d_phi;
      const vec3 w(static_cast<float>(std::sin(theta) * std::cos(phi)),
                   static_cast<float>(std::sin(theta) * std::sin(phi)),
                   static_cast<float>(std::cos(theta)));
      sum += f(w) * std::sin(theta) * d_theta * d_phi;
    }
  }
  return sum;
}

struct Random {
  std::mt19937 engine{12345};
  std::uniform_real_distribution<float> uniform{0.0f, 1.0f};
  vec2 next2() { return vec2(uniform(engine), uniform(engine)); }
};

vec3 view_at(float theta) { return vec3(std::sin(theta), 0.0f, std::cos(theta)); }

TEST(Sampling, CosineHemispherePdfIntegratesToOneAndMatchesItsSampler) {
  const vec3 n = normalize(vec3(0.3f, -0.4f, 0.8f));
  EXPECT_NEAR(integrate_sphere([&](vec3 w) { return cosine_hemisphere_pdf(n, w); }, false), 1.0,
              1e-3);
  // E[g / pdf] = integral of g, for g = 1 over the hemisphere around n: 2 pi.
  Random random;
  double sum = 0;
  const int kSamples = 200000;
  for (int i = 0; i < kSamples; ++i) {
    const vec3 w = sample_cosine_hemisphere(n, random.next2());
    ASSERT_GE(dot(w, n), -1e-5f);
    sum += 1.0 / cosine_hemisphere_pdf(n, w);
  }
  EXPECT_NEAR(sum / kSamples, 2 * M_PI, 2 * M_PI * 0.01);
}

TEST(Sampling, ConePdfIntegratesToOneAndSamplesStayInTheCone) {
  for (float half_angle : {1e-3f, 0.02f, 0.3f, 1.2f}) {
    const vec3 axis = normalize(vec3(-0.2f, 0.9f, 0.1f));
    const float cos_max = std::cos(half_angle);
    const float one_minus = 2.0f * std::sin(0.5f * half_angle) * std::sin(0.5f * half_angle);
    Random random;
    for (int i = 0; i < 20000; ++i) {
      const vec3 w = sample_cone(axis, one_minus, random.next2());
      ASSERT_NEAR(length(w), 1.0f, 1e-5f);
      ASSERT_GE(dot(w, axis), cos_max - 1e-5f) << half_angle;
    }
    // The density is uniform over the cone: pdf times the cone's solid angle is one.
    const double solid_angle = 2 * M_PI * (1 - std::cos(double(half_angle)));
    EXPECT_NEAR(cone_pdf(one_minus) * solid_angle, 1.0, 1e-3) << half_angle;
  }
}

// Where the ray from `origin` along unit `w` meets the triangle (Moller-Trumbore), or -1.
double ray_triangle(vec3 origin, vec3 w, vec3 a, vec3 b, vec3 c) {
  const glm::dvec3 e1 = glm::dvec3(b - a), e2 = glm::dvec3(c - a), d = glm::dvec3(w);
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return -1;
  const glm::dvec3 s = glm::dvec3(origin - a);
  const double u = glm::dot(s, p) / det;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) / det;
  if (u < 0 || v < 0 || u + v > 1) return -1;
  return glm::dot(e2, q) / det;
}

TEST(Sampling, TriangleSolidAnglePdfIntegratesToOneAndSamplesCoverTheArea) {
  const vec3 a(-1.0f, 0.2f, 2.0f), b(1.5f, -0.5f, 2.5f), c(0.3f, 1.4f, 1.2f);
  const float area = 0.5f * length(cross(b - a, c - a));
  const vec3 n = normalize(cross(b - a, c - a));
  for (vec3 origin : {vec3(0.0f), vec3(0.1f, 0.3f, 1.9f), vec3(4.0f, -3.0f, 1.0f)}) {
    // The density over every direction that meets the triangle, in solid angle, integrates to 1.
    const double integral = integrate_sphere(
        [&](vec3 w) {
          const double t = ray_triangle(origin, w, a, b, c);
          return t > 0 ? double(triangle_solid_angle_pdf(area, float(t), dot(n, w))) : 0.0;
        },
        false, 1200, 2400);
    EXPECT_NEAR(integral, 1.0, 0.01) << origin.x << " " << origin.y << " " << origin.z;
  }
  // Uniform over the area: the fraction of samples in the sub-triangle of the first vertex and
  // the edge midpoints is a quarter; barycentrics are non-negative and sum to one.
  Random random;
  int in_corner = 0;
  const int kSamples = 100000;
  for (int i = 0; i < kSamples; ++i) {
    const vec3 w = sample_triangle_uniform(random.next2());
    ASSERT_GE(std::min({w.x, w.y, w.z}), -1e-6f);
    ASSERT_NEAR(w.x + w.y + w.z, 1.0f, 1e-5f);
    if (w.x > 0.5f) ++in_corner;
  }
  EXPECT_NEAR(double(in_corner) / kSamples, 0.25, 0.01);
}

TEST(Sampling, GgxVisibleNormalPdfMatchesItsSamplerAndIntegratesToOne) {
  for (float alpha : {0.05f, 0.2f, 0.5f, 1.0f}) {
    for (float theta : {0.0f, 0.6f, 1.2f, 1.5f}) {
      const vec3 v = view_at(theta);
      // Reflections that land below the horizon are lost; together with the density above it
      // they account for every sample.
      Random random;
      const int kSamples = 400000;
      int lost = 0;
      double cos_over_pdf = 0;
      for (int i = 0; i < kSamples; ++i) {
        const vec3 l = reflect(-v, sample_ggx_vndf(v, alpha, random.next2()));
        if (l.z <= 0.0f) {
          ++lost;
          continue;
        }
        cos_over_pdf += l.z / ggx_vndf_reflection_pdf(v, l, alpha);
      }
      const double above = alpha >= 0.2f ? integrate_sphere(
                                               [&](vec3 l) { return ggx_vndf_reflection_pdf(v, l, alpha); }, true)
                                         : 1.0 - double(lost) / kSamples;
      EXPECT_NEAR(above + double(lost) / kSamples, 1.0, 0.01) << alpha << " " << theta;
      // E[cos / pdf] over the samples above = the integral of cos over the hemisphere = pi.
      EXPECT_NEAR(cos_over_pdf / kSamples, M_PI * (1.0 - 0.0), M_PI * 0.03)
          << alpha << " " << theta;
    }
  }
}

TEST(Bsdf, NeverReflectsMoreThanItReceives) {
  // Directional albedo: the integral of f cos over the light directions, for views from
  // normal incidence to grazing, for GL materials from matte to the shiniest.
  for (float shininess : {0.0f, 5.0f, 20.0f, 60.0f, 128.0f}) {
    for (vec3 ks : {vec3(0.0f), vec3(0.5f), vec3(1.0f)}) {
      const Bsdf bsdf = material_bsdf(vec3(1.0f), ks, shininess);
      for (float theta : {0.0f, 0.5f, 1.0f, 1.4f, 1.55f}) {
        const vec3 v = view_at(theta);
        double albedo = 0;
        if (bsdf.alpha >= 0.2f) {
          albedo = integrate_sphere(
              [&](vec3 l) {
                return double(max3(bsdf_lobe_cos(bsdf, GLPT_LOBE_DIFFUSE, v, l) +
                                   bsdf_lobe_cos(bsdf, GLPT_LOBE_SPECULAR, v, l)));
              },
              true);
        } else {  // a sharp lobe: the diffuse part by quadrature, the specular by its sampler
          albedo = integrate_sphere(
              [&](vec3 l) { return double(max3(bsdf_lobe_cos(bsdf, GLPT_LOBE_DIFFUSE, v, l))); },
              true, 200, 400);
          Random random;
          double specular = 0;
          const int kSamples = 100000;
          for (int i = 0; i < kSamples; ++i) {
            const vec3 l = sample_lobe(bsdf, GLPT_LOBE_SPECULAR, v, random.next2());
            const float pdf = lobe_pdf(bsdf, GLPT_LOBE_SPECULAR, v, l);
            if (l.z > 0.0f && pdf > 0.0f)
              specular += max3(bsdf_lobe_cos(bsdf, GLPT_LOBE_SPECULAR, v, l)) / pdf;
          }
          albedo += specular / kSamples;
        }
        EXPECT_LE(albedo, 1.0 + 5e-3) << "shininess " << shininess << " ks " << ks.x << " theta "
                                      << theta;
      }
    }
  }
}

TEST(Bsdf, DiffuseLobeIsLambertian) {
  const Bsdf bsdf = material_bsdf(vec3(0.6f, 0.3f, 0.9f), vec3(0.0f), 0.0f);
  const vec3 v = view_at(0.7f);
  const double albedo = integrate_sphere(
      [&](vec3 l) { return double(bsdf_lobe_cos(bsdf, GLPT_LOBE_DIFFUSE, v, l).x); }, true);
  EXPECT_NEAR(albedo, 0.6, 1e-3);
  EXPECT_EQ(specular_lobe_probability(bsdf), 0.0f);
}

TEST(Bsdf, ShininessMapsToTheReflectanceOfGlsLobe) {
  // GL's specular term ks (n.h)^s as a BRDF is ks (n.h)^s / (pi cos(theta_l)); its directional
  // albedo at normal incidence is (1 / pi) * integral of (n.h)^s over the light directions.
  const vec3 n(0.0f, 0.0f, 1.0f);
  for (float s : {0.0f, 1.0f, 6.0f, 10.0f, 50.0f, 128.0f}) {
    const double gl_albedo = integrate_sphere(
                                 [&](vec3 l) {
                                   const vec3 h = normalize(l + n);
                                   return std::pow(double(h.z), double(s));
                                 },
                                 true) /
                             M_PI;
    EXPECT_NEAR(specular_reflectance_scale(s), std::min(1.0, gl_albedo), 2e-3) << s;
  }
  // Walter et al.'s width match: alpha^2 = 2 / (s + 2).
  EXPECT_NEAR(shininess_to_alpha(50.0f), std::sqrt(2.0f / 52.0f), 1e-6);
}

TEST(Sampling, PowerHeuristicWeightsOfTwoTechniquesSumToOne) {
  for (float a : {0.0f, 0.1f, 1.0f, 30.0f})
    for (float b : {0.01f, 0.5f, 7.0f})
      EXPECT_NEAR(power_heuristic(a, b) + power_heuristic(b, a), 1.0f, 1e-6f);
  EXPECT_EQ(power_heuristic(0.0f, 0.0f), 0.0f);
}

}  // namespace
