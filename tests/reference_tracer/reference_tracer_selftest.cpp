// The CPU reference tracer against closed-form answers, without glpt (label `reference`, CPU
// only): what the glpt comparisons (reference_test.cpp) rest on. Samples at the pixel centres
// (one jitter position), so each pixel's expected value is the analytic one at its centre ray.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "reference_tracer/reference_scene.hpp"
#include "reference_tracer/reference_tracer.hpp"

namespace {

using glpt::reference::Camera;
using glpt::reference::Estimate;
using glpt::reference::Light;
using glpt::reference::Material;
using glpt::reference::Object;
using glpt::reference::Options;
using glpt::reference::Scene;

constexpr int kSize = 16;
constexpr float kHalf = 0.57735f;

// The eye-space point of the plane z = `z` the centre ray of pixel (px, py) meets.
glm::dvec3 on_plane(int px, int py, double z) {
  const double nx = (px + 0.5) / kSize * 2 - 1, ny = (py + 0.5) / kSize * 2 - 1;
  return {nx * double(kHalf) * -z, ny * double(kHalf) * -z, z};
}

Options centres(int samples) {
  Options o;
  o.samples = samples;
  o.center_samples = 0;
  o.jitter_positions = 1;
  return o;
}

// The plane z = -5 as n x n quads (n = 64: 8,192 triangles, which the BVH must get right).
Scene plane_scene(int n, const Material& m) {
  Scene scene;
  scene.size = kSize;
  scene.camera = Camera::frustum(kHalf, 1.0f, 50.0f);
  Object& o = scene.objects.emplace_back();
  o.material = m;
  const float extent = 3.0f, step = 2 * extent / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const float x = -extent + i * step, y = -extent + j * step;
      Scene::append_quad(o, {x, y, -5}, {x + step, y, -5}, {x + step, y + step, -5},
                         {x, y + step, -5});
    }
  return scene;
}

// Lambert's polygon formula: the form factor from a point with normal n to a polygon above it.
double polygon_form_factor(glm::dvec3 p, glm::dvec3 n, const std::vector<glm::dvec3>& polygon) {
  double sum = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec3 a = glm::normalize(polygon[i] - p);
    const glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - p);
    const glm::dvec3 c = glm::cross(a, b);
    const double length = glm::length(c);
    if (length < 1e-15) continue;
    sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, c / length);
  }
  return std::abs(sum) / (2 * M_PI);
}

TEST(ReferenceTracer, TessellatedPlaneUnderAPointLightIsGlsDiffuseTerm) {
  // GL's colour is irradiance / pi: L = kd * 3 cos / d^2 exactly (one deterministic sample).
  Material m;
  m.diffuse = glm::vec3(0.75f);
  Scene scene = plane_scene(64, m);
  scene.trace.bounces = 0;
  scene.trace.light_radius = 0.0f;
  scene.lights.push_back(Light::point({0, 0, -3}, glm::vec3(3.0f)));
  const Estimate e = glpt::reference::render(scene, centres(2));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::dvec3 p = on_plane(x, y, -5);
      const glm::dvec3 to = glm::dvec3(0, 0, -3) - p;
      const double d2 = glm::dot(to, to);
      const double expected = 0.75 * 3.0 * (2.0 / std::sqrt(d2)) / d2;
      EXPECT_NEAR(e.at(x, y).mean.x, expected, 1e-9 * expected) << x << "," << y;
    }
}

TEST(ReferenceTracer, SphereLightGivesThePointLightsIrradiance) {
  Material m;
  m.diffuse = glm::vec3(1.0f);
  Scene scene = plane_scene(4, m);
  scene.trace.bounces = 0;
  scene.trace.light_radius = 0.6f;
  scene.lights.push_back(Light::point({0, 0, -3}, glm::vec3(3.0f)));
  const Estimate e = glpt::reference::render(scene, centres(4096));
  for (int y = 0; y < kSize; y += 3)
    for (int x = 0; x < kSize; x += 3) {
      const glm::dvec3 p = on_plane(x, y, -5);
      const glm::dvec3 to = glm::dvec3(0, 0, -3) - p;
      const double d2 = glm::dot(to, to);
      const double expected = 3.0 * (2.0 / std::sqrt(d2)) / d2;
      const double se = std::sqrt(e.at(x, y).variance.x / 4096);
      EXPECT_NEAR(e.at(x, y).mean.x, expected, 4.5 * se + 1e-9) << x << "," << y;
    }
}

TEST(ReferenceTracer, EmissiveSquareLightsAPlaneByItsFormFactor) {
  // Bounces on: emitter sampling and bounce rays that hit it, weighed by MIS, count it once.
  Material m;
  m.diffuse = glm::vec3(1.0f);
  Scene scene = plane_scene(4, m);
  scene.trace.bounces = 1;
  Material emitter;
  emitter.emission = glm::vec3(3.0f);
  scene.add_quad({-1, -1, -3.5f}, {-1, 1, -3.5f}, {1, 1, -3.5f}, {1, -1, -3.5f}, emitter);
  const Estimate e = glpt::reference::render(scene, centres(4096));
  const std::vector<glm::dvec3> square = {
      {-1, -1, -3.5}, {-1, 1, -3.5}, {1, 1, -3.5}, {1, -1, -3.5}};
  int checked = 0;
  for (int y = 0; y < kSize; y += 3)
    for (int x = 0; x < kSize; x += 3) {
      const glm::dvec3 p = on_plane(x, y, -5);
      const glm::dvec3 through = p * (3.5 / 5.0);
      if (std::abs(through.x) < 1.0 && std::abs(through.y) < 1.0) continue;  // the square
      const double expected = 3.0 * polygon_form_factor(p, {0, 0, 1}, square);
      const double se = std::sqrt(e.at(x, y).variance.x / 4096);
      EXPECT_NEAR(e.at(x, y).mean.x, expected, 4.5 * se + 1e-9) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 10);
}

TEST(ReferenceTracer, AmbientOcclusionOfACornerIsOneMinusTheWallsFormFactor) {
  // GL_AO_RADIUS fixed far beyond the wall: every wall hit occludes.
  Material m;
  m.ambient = glm::vec3(0.75f);
  Scene scene = plane_scene(4, m);
  scene.global_ambient = glm::vec3(1.0f);
  scene.trace.ao_radius = 100.0f;
  scene.add_quad({-1, -3, -5}, {-1, 3, -5}, {-1, 3, -3}, {-1, -3, -3}, m);
  const Estimate e = glpt::reference::render(scene, centres(4096));
  const std::vector<glm::dvec3> wall = {{-1, -3, -5}, {-1, 3, -5}, {-1, 3, -3}, {-1, -3, -3}};
  for (int y = 2; y < kSize; y += 4)
    for (int x = 6; x < kSize; x += 2) {
      const glm::dvec3 p = on_plane(x, y, -5);
      const double expected = 0.75 * (1.0 - polygon_form_factor(p, {0, 0, 1}, wall));
      const double se = std::sqrt(e.at(x, y).variance.x / 4096);
      EXPECT_NEAR(e.at(x, y).mean.x, expected, 4.5 * se + 1e-9) << x << "," << y;
    }
}

TEST(ReferenceTracer, WhiteFurnaceSumsTheBouncesItTraces) {
  // A closed cube, albedo a = 0.5, emission 0.25 on every face: a path of up to B bounces
  // collects 0.25 (1 + a + ... + a^B); Russian roulette keeps it unbiased.
  Scene scene;
  scene.size = 8;
  scene.camera = Camera::frustum(kHalf, 0.1f, 50.0f);
  scene.trace.bounces = 6;
  Material m;
  m.diffuse = glm::vec3(0.5f);
  m.emission = glm::vec3(0.25f);
  scene.add_quad({-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, m);
  scene.add_quad({-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, m);
  scene.add_quad({-1, -1, -1}, {-1, 1, -1}, {-1, 1, 1}, {-1, -1, 1}, m);
  scene.add_quad({1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}, m);
  scene.add_quad({-1, -1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, m);
  scene.add_quad({-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, m);
  const Estimate e = glpt::reference::render(scene, centres(2048));
  const double expected = 0.25 * (1.0 - std::pow(0.5, 7)) / 0.5;
  double mean = 0, variance = 0;
  for (const auto& p : e.pixels) {
    mean += p.mean.x / double(e.pixels.size());
    variance += p.variance.x / 2048.0 / double(e.pixels.size() * e.pixels.size());
  }
  EXPECT_NEAR(mean, expected, 4.5 * std::sqrt(variance));
}

}  // namespace
