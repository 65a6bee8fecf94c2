// glpt's path tracer against the CPU reference tracer, in distribution (label `reference`,
// docs/light-transport.md "Tests"). Each scene is described once (reference_scene.hpp), drawn by
// glpt through its GL front end on a headless drawable (gl_issue.hpp) and traced by the
// reference in double precision; per 8 x 8 block and channel:
//   * the mean of a GLPT_REFERENCE=N image within 4.5 standard errors of the reference's mean
//     plus half an 8-bit step (compare_means),
//   * the variance over K 1-sample frames within 4.5 standard errors and 10 % of the
//     reference's variance of the same 8-bit value (compare_variances).
// The analytic scenes of tests/light_transport, then scenes that stress precision (scale 1e-6 and
// 1e6, 1e5 from the origin, grazing light, near/far 1e-4/1e7), then the self-check: a reference
// with a deliberate error must fail the same comparisons.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "../common/headless_gl_render.hpp"
#include "reference_tracer/distribution_compare.hpp"
#include "reference_tracer/gl_issue.hpp"
#include "reference_tracer/reference_scene.hpp"
#include "reference_tracer/reference_tracer.hpp"

namespace {

using glpt::reference::Camera;
using glpt::reference::Comparison;
using glpt::reference::Estimate;
using glpt::reference::Fault;
using glpt::reference::Light;
using glpt::reference::Material;
using glpt::reference::Object;
using glpt::reference::Scene;

constexpr int kSize = 32;
constexpr int kBlock = 8;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What glpt renders of a scene: a GLPT_REFERENCE image and independent 1-sample frames.
struct GlptRender {
  int samples = 0;
  std::vector<uint8_t> reference;
  std::vector<std::vector<uint8_t>> frames;
};

GlptRender render_glpt(const Scene& scene, int samples, int frames) {
  GlptRender out;
  out.samples = samples;
  auto draw = [&] { glpt::reference::issue_gl(scene); };
  out.reference = glpt::test::render_headless(
      scene.size, scene.glpt_settings({{"GLPT_REFERENCE", std::to_string(samples)}}), draw, 1,
      "reference");
  out.frames = glpt::test::render_headless_frames(
      scene.size, scene.glpt_settings({{"GLPT_SPP", "1"}, {"GLPT_ACCUMULATE", "0"}}),
      [&](int) { draw(); }, frames);
  return out;
}

// Samples per pixel on each side. The standard errors the tolerances are made of follow from
// them, so they trade the test's time against the smallest error it can see (a block mean's
// standard error is about 0.05 to 0.3 steps at these counts).
struct Budget {
  int glpt_samples = 512;  // GLPT_REFERENCE
  int frames = 32;         // 1-sample frames
  int reference_samples = 1536;
  int center_samples = 384;
};

Estimate reference_of(const Scene& scene, const Budget& budget, Fault fault = Fault::kNone) {
  glpt::reference::Options options;
  options.samples = budget.reference_samples;
  options.center_samples = budget.center_samples;
  options.fault = fault;
  return glpt::reference::render(scene, options);
}

// Both comparisons; EXPECTs them to pass and prints what they measured.
void expect_same_distribution(const Scene& scene, const Budget& budget = {}) {
  const auto start = std::chrono::steady_clock::now();
  const Estimate ref = reference_of(scene, budget);
  const double ref_seconds = seconds_since(start);
  const auto glpt_start = std::chrono::steady_clock::now();
  const GlptRender glpt = render_glpt(scene, budget.glpt_samples, budget.frames);
  const double glpt_seconds = seconds_since(glpt_start);
  const Comparison means =
      glpt::reference::compare_means(glpt.reference, glpt.samples, ref, kBlock);
  const Comparison variances = glpt::reference::compare_variances(glpt.frames, ref, kBlock);
  std::printf("reference %.1f s, glpt %.1f s\n  %s\n  %s\n", ref_seconds, glpt_seconds,
              means.summary().c_str(), variances.summary().c_str());
  EXPECT_EQ(means.failures(), 0) << means.failed_blocks();
  EXPECT_EQ(variances.failures(), 0) << variances.failed_blocks();
}

Material diffuse(glm::vec3 kd) {
  Material m;
  m.diffuse = kd;
  return m;
}

// The plane z = `z` facing +z over [-extent, extent]^2 as n x n quads.
void facing_plane(Scene& scene, float z, float extent, const Material& m, int n = 4,
                  glm::vec3 translation = glm::vec3(0.0f)) {
  Object& o = scene.objects.emplace_back();
  o.material = m;
  o.translation = translation;
  const float step = 2 * extent / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const float x = -extent + i * step, y = -extent + j * step;
      Scene::append_quad(o, {x, y, z}, {x + step, y, z}, {x + step, y + step, z}, {x, y + step, z});
    }
}

// A box standing on the plane z = lo.z: its top at z = hi.z and four sides (no bottom).
void add_box(Scene& scene, glm::vec3 lo, glm::vec3 hi, const Material& m) {
  const float x0 = lo.x, x1 = hi.x, y0 = lo.y, y1 = hi.y, z0 = lo.z, z1 = hi.z;
  Object& box = scene.add_quad({x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}, m);
  Scene::append_quad(box, {x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}, {x0, y0, z1});
  Scene::append_quad(box, {x1, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x1, y1, z0});
  Scene::append_quad(box, {x0, y0, z0}, {x0, y0, z1}, {x1, y0, z1}, {x1, y0, z0});
  Scene::append_quad(box, {x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1});
}

Scene base_scene() {
  Scene scene;
  scene.size = kSize;
  scene.camera = Camera::frustum(0.57735f, 1.0f, 50.0f);
  return scene;
}

// ---- analytic scenes ---------------------------------------------------------------------------

// tests/light_transport's plane under a light: albedo 0.75, light of colour 3 at height 2.
Scene plane_under_light(float radius) {
  Scene scene = base_scene();
  scene.trace.bounces = 0;
  scene.trace.light_radius = radius;
  scene.lights.push_back(Light::point({0.0f, 0.0f, -3.0f}, glm::vec3(3.0f)));
  facing_plane(scene, -5.0f, 3.0f, diffuse(glm::vec3(0.75f)));
  return scene;
}

TEST(Reference, LambertianPlaneUnderAPointLight) {
  expect_same_distribution(plane_under_light(0.0f));
}

TEST(Reference, LambertianPlaneUnderASphereLight) {
  expect_same_distribution(plane_under_light(0.6f));
}

// A plane under an emissive square of half size `h` and GL emission `emission`, one bounce.
Scene plane_under_emitter(float h, float emission) {
  Scene scene = base_scene();
  scene.trace.bounces = 1;
  facing_plane(scene, -5.0f, 3.0f, diffuse(glm::vec3(0.75f)));
  Material emitter;
  emitter.emission = glm::vec3(emission);
  scene.add_quad({-h, -h, -3.5f}, {-h, h, -3.5f}, {h, h, -3.5f}, {h, -h, -3.5f}, emitter);
  return scene;
}

// A plane under an emissive square (GL emission 3), bounces on: next-event estimation of the
// emitter and bounce rays that hit it, weighed by MIS.
TEST(Reference, EmissiveSquareLightsAPlane) {
  expect_same_distribution(plane_under_emitter(1.0f, 3.0f));
}

// The extremes suite's emissions against the reference: a square 1/1000 the size with 1e6 times
// the radiance (about a third of the power above, from a sub-pixel emitter: next-event
// estimation must find it, bounce rays that hit it must not turn into fireflies MIS does not
// weigh down, and the camera pixels over it saturate as the composite clamps), and one a
// million times dimmer than GL's unit emission beside a unit light (what it adds must not be lost
// or amplified by the tone mapping: the images stay the light's alone to within rounding).
TEST(Reference, TinyEmitterOfEmission1e6LightsAPlane) {
  expect_same_distribution(plane_under_emitter(1.0e-3f, 1.0e6f));
}

TEST(Reference, EmitterOfEmission1eMinus6BesideALight) {
  Scene scene = plane_under_light(0.3f);
  scene.trace.bounces = 1;
  Material emitter;
  emitter.emission = glm::vec3(1.0e-6f);
  scene.add_quad({-1, -1, -4.5f}, {-1, 1, -4.5f}, {1, 1, -4.5f}, {1, -1, -4.5f}, emitter);
  expect_same_distribution(scene);
}

// A floor and a red wall standing on it at x = -1 under a sphere light, with `scale` applied to
// every length (the light's quadratic attenuation scaled to match, so the image is the same) and
// the geometry placed at `offset` in object space under a modelview translating it back.
Scene corner(float scale = 1.0f, glm::vec3 offset = glm::vec3(0.0f)) {
  Scene scene = base_scene();
  scene.camera = Camera::frustum(0.57735f, 1.0f * scale, 50.0f * scale);
  scene.trace.bounces = 3;
  scene.trace.light_radius = 0.3f * scale;
  scene.lights.push_back(
      Light::point(glm::vec3(0.5f, 0.5f, -3.5f) * scale, glm::vec3(2.0f), 1.0f / (scale * scale)));
  auto at = [&](float x, float y, float z) { return glm::vec3(x, y, z) * scale + offset; };
  scene.add_quad(at(-3, -3, -5), at(3, -3, -5), at(3, 3, -5), at(-3, 3, -5),
                 diffuse(glm::vec3(0.75f)), -offset);
  scene.add_quad(at(-1, -3, -5), at(-1, 3, -5), at(-1, 3, -3), at(-1, -3, -3),
                 diffuse(glm::vec3(0.75f, 0.25f, 0.25f)), -offset);
  return scene;
}

// Three bounces, Russian roulette after the first, a coloured wall: per channel.
TEST(Reference, CornerWithBounces) { expect_same_distribution(corner()); }

// GL's ambient light under ambient occlusion, with a small box standing on a floor as an
// instance of its own (its own modelview): the occlusion radius is the box's own size, so floor
// points see the box occlude only within about a box's width.
TEST(Reference, AmbientOcclusionByABoxOfItsOwnSize) {
  Scene scene = base_scene();
  scene.global_ambient = glm::vec3(1.0f);
  Material ambient;
  ambient.ambient = glm::vec3(0.75f);
  facing_plane(scene, -5.0f, 3.0f, ambient);
  // The box, 1 x 1 x 0.5, drawn 1 unit lower under a modelview lifting it back.
  Object& box = scene.objects.emplace_back();
  box.material = ambient;
  box.material.diffuse = glm::vec3(0.5f);
  box.translation = glm::vec3(0.0f, 0.0f, 1.0f);
  const float x0 = -0.5f, x1 = 0.5f, y0 = -0.5f, y1 = 0.5f, z0 = -6.0f, z1 = -5.5f;
  Scene::append_quad(box, {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1});  // top
  Scene::append_quad(box, {x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}, {x0, y0, z1});  // -x
  Scene::append_quad(box, {x1, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x1, y1, z0});  // +x
  Scene::append_quad(box, {x0, y0, z0}, {x0, y0, z1}, {x1, y0, z1}, {x1, y0, z0});  // -y
  Scene::append_quad(box, {x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1});  // +y
  expect_same_distribution(scene);
}

// A closed cube of albedo 0.5 and emission 0.25 seen from inside: 0.5 everywhere (less the
// 0.5^7 that paths cut after 6 bounces miss), every path collecting emission at each vertex
// Russian roulette lets it reach.
TEST(Reference, WhiteFurnace) {
  Scene scene = base_scene();
  scene.camera = Camera::frustum(0.57735f, 0.1f, 50.0f);
  scene.trace.bounces = 6;
  Material m;
  m.diffuse = glm::vec3(0.5f);
  m.emission = glm::vec3(0.25f);
  const float s = 1.0f;
  scene.add_quad({-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s}, m);
  scene.add_quad({-s, -s, s}, {-s, s, s}, {s, s, s}, {s, -s, s}, m);
  scene.add_quad({-s, -s, -s}, {-s, s, -s}, {-s, s, s}, {-s, -s, s}, m);
  scene.add_quad({s, -s, -s}, {s, -s, s}, {s, s, s}, {s, s, -s}, m);
  scene.add_quad({-s, -s, -s}, {-s, -s, s}, {s, -s, s}, {s, -s, -s}, m);
  scene.add_quad({-s, s, -s}, {s, s, -s}, {s, s, s}, {-s, s, s}, m);
  expect_same_distribution(scene);
}

// GL's lights and materials together: a glossy floor (GGX from shininess 32) with a box on it,
// a coloured spot light with exponent, cutoff and all three attenuations at its default angular
// size, a directional light of 2 degrees, GL's global and per-light ambient under AO, one bounce.
Scene lights_and_materials() {
  Scene scene = base_scene();
  scene.trace.bounces = 1;
  scene.trace.light_size_deg = 2.0f;
  scene.global_ambient = glm::vec3(0.125f);
  Light spot = Light::point({0.5f, 1.5f, -3.0f}, {2.0f, 1.5f, 1.0f});
  spot.specular = glm::vec3(2.0f);
  spot.ambient = glm::vec3(0.25f, 0.0f, 0.0f);
  spot.spot_direction = glm::normalize(glm::vec3(-0.25f, -0.75f, -1.0f));
  spot.spot_exponent = 8.0f;
  spot.spot_cutoff = 40.0f;
  spot.constant_attenuation = 0.5f;
  spot.linear_attenuation = 0.25f;
  spot.quadratic_attenuation = 0.25f;
  scene.lights.push_back(spot);
  Light sun = Light::directional({-0.5f, 0.5f, 1.0f}, {0.25f, 0.25f, 0.5f});
  sun.specular = glm::vec3(0.5f);
  scene.lights.push_back(sun);
  Material floor;
  floor.diffuse = glm::vec3(0.5f);
  floor.ambient = glm::vec3(0.5f);
  floor.specular = glm::vec3(0.5f);
  floor.shininess = 32.0f;
  facing_plane(scene, -5.0f, 3.0f, floor);
  Material green = diffuse({0.25f, 0.75f, 0.25f});
  green.ambient = glm::vec3(0.5f);
  add_box(scene, {-1.0f, -1.0f, -5.0f}, {0.0f, 0.0f, -4.25f}, green);
  return scene;
}

TEST(Reference, SpotAndDirectionalLightsOnAGlossyFloor) {
  expect_same_distribution(lights_and_materials());
}

// Materials of ~0 albedo, which path_trace.comp traces with unit reflectances at the primary
// vertex (unit_reflectance_bsdf; the composite multiplies them back): three squares side by side
// under a point light, GL's ambient under AO and one bounce off a white box - black and shiny
// (the diffuse lobe still picked 5 % of the time, the specular 95 %), GL's ambient colour alone
// (the diffuse channels hold that radiance as it is) and shiny white.
TEST(Reference, MaterialsWithoutAlbedo) {
  Scene scene = base_scene();
  scene.trace.bounces = 1;
  scene.global_ambient = glm::vec3(0.25f);
  Light light = Light::point({0.0f, 1.5f, -3.5f}, glm::vec3(2.0f));
  light.specular = glm::vec3(2.0f);
  scene.lights.push_back(light);
  Material black_shiny;
  black_shiny.specular = glm::vec3(0.75f);
  black_shiny.shininess = 16.0f;
  Material ambient_only;
  ambient_only.ambient = glm::vec3(0.5f, 0.25f, 0.75f);
  Material white_shiny = diffuse(glm::vec3(0.75f));
  white_shiny.specular = glm::vec3(0.5f);
  white_shiny.shininess = 8.0f;
  facing_plane(scene, -5.0f, 1.0f, black_shiny, 2, glm::vec3(-2.0f, 0.0f, 0.0f));
  facing_plane(scene, -5.0f, 1.0f, ambient_only, 2);
  facing_plane(scene, -5.0f, 1.0f, white_shiny, 2, glm::vec3(2.0f, 0.0f, 0.0f));
  Material white = diffuse(glm::vec3(0.75f));
  add_box(scene, {-0.5f, 0.25f, -5.0f}, {0.5f, 1.0f, -4.0f}, white);
  expect_same_distribution(scene);
}

// ---- precision ---------------------------------------------------------------------------------

// glpt failed it until offset_ray_origin's near-origin step scaled with the point: a fixed
// 1/65536 wherever a coordinate is below 1/32 is 15 times this scene, and shadows, occlusion
// and bounce light were lost (block (0,8) green 18.0 against the reference's 5.7). Now: worst
// block -2.1 SE in the means, -1.5 SE in the variances.
TEST(Reference, CornerAtMicroScale) { expect_same_distribution(corner(1e-6f)); }

TEST(Reference, CornerAtMegaScale) { expect_same_distribution(corner(1e6f)); }

// The corner drawn 1e5 from the object-space origin (x + 1e5 is exact in float for these
// coordinates), under a modelview that brings it back in front of the camera. Rays meet the BLAS
// in object space, where coordinates near 1e5 have float steps of 1/128: secondary-ray origins
// must move off the surface by a step of that size, not by a few ulps of their eye-space
// position (about 1e-4 here). Before they did (shaders/trace/offset_ray.h), the lit floor was
// darker with 20 times the reference's 1-sample variance with bounces off (shadow rays blocked at
// random), and with bounces the floor behind the wall was lit through it (block (0,16) red 40.9
// against 26.2); a step too large leaks light the same way (16 steps: 11 of 48 blocks out).
TEST(Reference, CornerFarFromTheOrigin) {
  expect_same_distribution(corner(1.0f, glm::vec3(1.0e5f, 0.0f, 0.0f)));
}

// A sun 3 degrees above the horizon of a floor (its 1-degree cone partly grazing) and the long
// shadow of a box.
TEST(Reference, GrazingSunlight) {
  Scene scene = base_scene();
  const float elevation = glm::radians(3.0f);
  scene.lights.push_back(
      Light::directional({std::cos(elevation), 0.0f, std::sin(elevation)}, glm::vec3(4.0f)));
  facing_plane(scene, -5.0f, 3.0f, diffuse(glm::vec3(0.75f)));
  Material white = diffuse(glm::vec3(0.75f));
  add_box(scene, {0.5f, -1.0f, -5.0f}, {1.0f, 1.0f, -4.75f}, white);
  expect_same_distribution(scene);
}

// Near and far planes 1e-4 and 1e7: a small floor at 5 units in front of a wall 1e6 away and
// 2e6 wide, both lit by a sun from behind the camera. The wall's depth rounds to 1 in float:
// GL_LEQUAL keeps it (reference_scene.hpp).
TEST(Reference, NearAndFarPlanesEightOrdersApart) {
  Scene scene = base_scene();
  scene.camera = Camera::frustum(0.57735f, 1.0e-4f, 1.0e7f);
  scene.depth_less_equal = true;
  scene.lights.push_back(Light::directional({0.25f, 0.5f, 1.0f}, glm::vec3(1.0f)));
  facing_plane(scene, -5.0f, 1.5f, diffuse(glm::vec3(0.75f)));
  facing_plane(scene, -1.0e6f, 1.0e6f, diffuse(glm::vec3(0.25f, 0.5f, 0.75f)), 2);
  expect_same_distribution(scene);
}

// ---- the comparisons can fail ------------------------------------------------------------------

// glpt's images against references with deliberate errors: a wrong attenuation moves the means
// (and variances), one bounce fewer moves the means of the corner (its floor and wall light
// each other; in the glossy-floor scene one bounce adds less than the tolerance), and choosing
// lights uniformly keeps the means and changes the variances. The correct reference passes both
// comparisons on the same images.
TEST(Reference, TheComparisonsRejectAWrongReference) {
  const Budget budget;
  struct Outcome {
    int means = 0, variances = 0;
  };
  auto compare = [&](const Scene& scene, const GlptRender& glpt, Fault fault, const char* name) {
    const Estimate ref = reference_of(scene, budget, fault);
    const Comparison means =
        glpt::reference::compare_means(glpt.reference, glpt.samples, ref, kBlock);
    const Comparison variances = glpt::reference::compare_variances(glpt.frames, ref, kBlock);
    std::printf("%s:\n  %s\n  %s\n", name, means.summary().c_str(), variances.summary().c_str());
    return Outcome{means.failures(), variances.failures()};
  };
  const Scene lit = lights_and_materials();
  const GlptRender lit_glpt = render_glpt(lit, budget.glpt_samples, budget.frames);
  const Outcome correct = compare(lit, lit_glpt, Fault::kNone, "correct");
  EXPECT_EQ(correct.means, 0);
  EXPECT_EQ(correct.variances, 0);
  EXPECT_GT(compare(lit, lit_glpt, Fault::kWrongAttenuation, "wrong attenuation").means, 0);
  const Outcome uniform = compare(lit, lit_glpt, Fault::kUniformLightChoice, "uniform choice");
  EXPECT_EQ(uniform.means, 0);
  EXPECT_GT(uniform.variances, 0);

  Scene room = corner();
  room.trace.bounces = 1;
  const GlptRender room_glpt = render_glpt(room, budget.glpt_samples, budget.frames);
  const Outcome room_correct = compare(room, room_glpt, Fault::kNone, "corner, correct");
  EXPECT_EQ(room_correct.means, 0);
  EXPECT_EQ(room_correct.variances, 0);
  EXPECT_GT(compare(room, room_glpt, Fault::kDroppedBounce, "corner, dropped bounce").means, 0);
}

}  // namespace
