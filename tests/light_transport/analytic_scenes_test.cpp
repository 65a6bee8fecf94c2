// Path-traced GL scenes whose radiance is known in closed form (docs/light-transport.md, "Tests"):
// each is drawn with GL through glpt's front end on a headless drawable and read back with
// glReadPixels, and compared with the analytic answer (8-bit read-back: tolerances are stated as
// a relative error plus one or two steps of 1/255). Raster mode stands for Mesa where an image
// is compared with GL's (the conformance suite checks raster mode against Mesa pixel for pixel).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "../common/gl_scene.hpp"
#include "../common/headless_gl_render.hpp"
#include "gl/gl_enums.h"
#include "gl_shim/gl_entry_decls.h"

namespace {

using glpt::test::inverse_square_light;
using glpt::test::quad;

constexpr int kSize = 64;
// camera(): a 60-degree frustum, x and y in [-kHalf, kHalf] * distance.
constexpr float kHalf = 0.57735f;

using glpt::test::Settings;

struct Image {
  std::vector<uint8_t> rgba;
  // GL window coordinates: y = 0 is the bottom row; channel 0..3.
  int at(int x, int y, int channel = 0) const {
    return rgba[(size_t(y) * kSize + size_t(x)) * 4 + size_t(channel)];
  }
  double mean(int channel = 0) const {
    double sum = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) sum += at(x, y, channel);
    return sum / (kSize * kSize);
  }
};

// Draws `scene` `frames` times on a fresh context with the GLPT_* `settings` and reads the last
// frame back (tests/common/headless_gl_render.hpp).
Image render(const Settings& settings, const std::function<void()>& scene, int frames,
             const char* tag, glpt::rt::FrameStats* stats = nullptr) {
  return Image{glpt::test::render_headless(kSize, settings, scene, frames, tag, stats)};
}

Settings path(Settings extra) {
  extra.insert(extra.begin(), {"GLPT_MODE", "path"});
  return extra;
}

void camera(float near_plane = 1.0f) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-kHalf * near_plane, kHalf * near_plane, -kHalf * near_plane, kHalf * near_plane,
            near_plane, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
}

// GL lighting with no ambient anywhere and the given material (specular black unless set).
void material(glm::vec3 diffuse, glm::vec3 emission = glm::vec3(0.0f),
              glm::vec3 ambient = glm::vec3(0.0f), glm::vec3 specular = glm::vec3(0.0f),
              float shininess = 0.0f) {
  glEnable(GL_LIGHTING);
  const float black[] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
  const float d[] = {diffuse.r, diffuse.g, diffuse.b, 1};
  const float e[] = {emission.r, emission.g, emission.b, 1};
  const float a[] = {ambient.r, ambient.g, ambient.b, 1};
  const float s[] = {specular.r, specular.g, specular.b, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, d);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, e);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, a);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

// The plane z = `z` facing +z, split into n x n quads over [-extent, extent]^2.
void facing_plane(float z, float extent, int n = 4) {
  const float step = 2 * extent / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const float x = -extent + i * step, y = -extent + j * step;
      quad({x, y, z}, {x + step, y, z}, {x + step, y + step, z}, {x, y + step, z});
    }
}

// The eye-space point of the plane z = `z` seen through the centre of pixel (px, py).
glm::vec3 on_plane(int px, int py, float z) {
  const float nx = (px + 0.5f) / kSize * 2 - 1, ny = (py + 0.5f) / kSize * 2 - 1;
  return {nx * kHalf * -z, ny * kHalf * -z, z};
}

// |measured - expected| <= relative * expected + steps (8-bit values).
void expect_close(double measured, double expected, double relative, double steps,
                  const std::string& where) {
  EXPECT_LE(std::abs(measured - expected), relative * expected + steps)
      << where << ": measured " << measured << ", expected " << expected;
}

// ---- emission and bounces ----------------------------------------------------------------------

TEST(LightTransport, WhiteFurnace) {
  // A closed cube of diffuse albedo a and uniform emission Le seen from inside: every path
  // collects Le at each vertex, so the radiance is Le / (1 - a) everywhere (0.25 / 0.5 = 0.5).
  auto scene = [] {
    camera(0.1f);
    material(glm::vec3(0.5f), glm::vec3(0.25f));
    const float s = 1.0f;
    // Six faces, each wound to face the inside.
    quad({-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s});  // back (z = -s), facing +z
    quad({-s, -s, s}, {-s, s, s}, {s, s, s}, {s, -s, s});      // front (z = +s), facing -z
    quad({-s, -s, -s}, {-s, s, -s}, {-s, s, s}, {-s, -s, s});  // left, facing +x
    quad({s, -s, -s}, {s, -s, s}, {s, s, s}, {s, s, -s});      // right, facing -x
    quad({-s, -s, -s}, {-s, -s, s}, {s, -s, s}, {s, -s, -s});  // bottom, facing +y
    quad({-s, s, -s}, {s, s, -s}, {s, s, s}, {-s, s, s});      // top, facing -y
  };
  // 12 bounces: the paths cut after them miss 0.5^13 of the light (0.01 %).
  const Image image = render(path({{"GLPT_BOUNCES", "12"}, {"GLPT_SPP", "32"}}), scene, 8, "path");
  std::printf("white furnace: image mean %.2f (expected 127.5)\n", image.mean());
  expect_close(image.mean(), 0.5 * 255, 0.01, 0.0, "image mean");
  // Per pixel, 256 paths, each of which collects Le at every vertex Russian roulette lets it
  // reach (a geometric number of them): a standard deviation of about 4 %; within 15 %.
  for (int y = 0; y < kSize; y += 7)
    for (int x = 0; x < kSize; x += 7)
      expect_close(image.at(x, y), 0.5 * 255, 0.15, 1.0,
                   "pixel " + std::to_string(x) + "," + std::to_string(y));
}

TEST(LightTransport, EachBounceAddsLessThanTheOneBefore) {
  // The same cube, not emitting, lit by a point light in its middle: bounce k adds light
  // reflected k times, so the image grows with the bounce count by ever smaller steps (each
  // order carries a = 0.5 of the one before, spread over the walls).
  auto scene = [] {
    camera(0.1f);
    material(glm::vec3(0.5f));
    inverse_square_light(GL_LIGHT0, {0.0f, 0.3f, 0.0f}, glm::vec3(0.25f));
    const float s = 1.0f;
    quad({-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s});
    quad({-s, -s, s}, {-s, s, s}, {s, s, s}, {s, -s, s});
    quad({-s, -s, -s}, {-s, s, -s}, {-s, s, s}, {-s, -s, s});
    quad({s, -s, -s}, {s, -s, s}, {s, s, s}, {s, s, -s});
    quad({-s, -s, -s}, {-s, -s, s}, {s, -s, s}, {s, -s, -s});
    quad({-s, s, -s}, {s, s, -s}, {s, s, s}, {-s, s, s});
  };
  std::vector<double> means;
  for (int bounces = 0; bounces <= 3; ++bounces) {
    const Image image = render(path({{"GLPT_BOUNCES", std::to_string(bounces)},
                                     {"GLPT_SPP", "32"},
                                     {"GLPT_LIGHT_RADIUS", "0"}}),
                               scene, 4, ("bounces" + std::to_string(bounces)).c_str());
    means.push_back(image.mean());
  }
  for (size_t k = 1; k < means.size(); ++k) EXPECT_GT(means[k], means[k - 1]) << k;
  for (size_t k = 2; k < means.size(); ++k)
    EXPECT_LT(means[k] - means[k - 1], means[k - 1] - means[k - 2]) << k;
}

// ---- lights ------------------------------------------------------------------------------------

// Radiance of a Lambertian plane z = -5 (albedo 1) under a light of diffuse colour 3 at height 2
// above its centre with inverse-square attenuation: GL's colour is irradiance / pi, so
// L = E / pi = 3 cos(theta) / d^2. A sphere light fully above the horizon gives the same
// irradiance as a point at its centre.
double plane_radiance(int px, int py) {
  const glm::vec3 p = on_plane(px, py, -5.0f);
  const glm::vec3 light(0.0f, 0.0f, -3.0f);
  const double d2 = glm::dot(light - p, light - p);
  const double cosine = 2.0 / std::sqrt(d2);
  return 3.0 * cosine / d2;
}

void plane_under_light() {
  camera();
  material(glm::vec3(1.0f));
  inverse_square_light(GL_LIGHT0, {0.0f, 0.0f, -3.0f}, glm::vec3(3.0f));
  facing_plane(-5.0f, 3.0f);
}

TEST(LightTransport, LambertianPlaneUnderAPointLight) {
  const Image image = render(path({{"GLPT_LIGHT_RADIUS", "0"}, {"GLPT_BOUNCES", "0"}}),
                             plane_under_light, 1, "point");
  for (int y = 1; y < kSize; y += 6)
    for (int x = 1; x < kSize; x += 6)
      expect_close(image.at(x, y), 255 * plane_radiance(x, y), 0.01, 1.0,
                   "pixel " + std::to_string(x) + "," + std::to_string(y));
}

TEST(LightTransport, LambertianPlaneUnderASphereLight) {
  const Image image =
      render(path({{"GLPT_LIGHT_RADIUS", "0.6"}, {"GLPT_BOUNCES", "0"}, {"GLPT_SPP", "64"}}),
             plane_under_light, 4, "sphere");
  for (int y = 1; y < kSize; y += 6)
    for (int x = 1; x < kSize; x += 6)
      expect_close(image.at(x, y), 255 * plane_radiance(x, y), 0.01, 1.5,
                   "pixel " + std::to_string(x) + "," + std::to_string(y));
}

TEST(LightTransport, ALitSceneWithoutLightsHasOnlyGlsAmbientAndEmission) {
  auto scene = [] {
    camera();
    material(glm::vec3(1.0f), glm::vec3(0.1f, 0.2f, 0.3f));
    facing_plane(-5.0f, 3.0f);
  };
  const Image image = render(path({}), scene, 1, "path");
  EXPECT_NEAR(image.at(32, 32, 0), 26, 1);  // 0.1 * 255: no default light
  EXPECT_NEAR(image.at(32, 32, 2), 77, 1);
  const Image lit = render(path({{"GLPT_DEFAULT_LIGHT", "1"}}), scene, 1, "default_light");
  EXPECT_GT(lit.at(32, 32, 0), 100);  // asked for: a white directional light
}

// ---- ambient occlusion -------------------------------------------------------------------------

TEST(LightTransport, AmbientOcclusionOfAnOpenPlaneIsOne) {
  auto scene = [] {
    camera();
    material(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.8f));
    const float white[] = {1, 1, 1, 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, white);
    facing_plane(-5.0f, 3.0f);
  };
  const Image image = render(path({{"GLPT_SPP", "16"}}), scene, 2, "path");
  for (int y = 0; y < kSize; y += 5)
    for (int x = 0; x < kSize; x += 5) EXPECT_EQ(image.at(x, y), 204) << x << "," << y;
}

// The form factor from a point with normal n to a planar polygon fully above its horizon
// (Lambert's formula): (1 / 2 pi) * sum over edges of the edge's angle times the cosine of its
// plane with n.
double polygon_form_factor(glm::dvec3 point, glm::dvec3 n, const std::vector<glm::dvec3>& polygon) {
  double sum = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec3 a = glm::normalize(polygon[i] - point);
    const glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - point);
    const glm::dvec3 c = glm::cross(a, b);
    const double length = glm::length(c);
    if (length < 1e-12) continue;
    sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, c / length);
  }
  return std::abs(sum) / (2 * M_PI);
}

TEST(LightTransport, AmbientOcclusionOfARightAngleCorner) {
  // A floor facing the camera (z = -5) and a wall standing on it at x = -1 (height 2, facing
  // +x). A floor point at distance delta from the wall sees the wall over the form factor F of
  // its rectangle, so its ambient visibility is 1 - F (at the crease 1/2).
  const float kWallHeight = 2.0f;
  auto scene = [&] {
    camera();
    material(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.8f));
    const float white[] = {1, 1, 1, 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, white);
    facing_plane(-5.0f, 3.0f);
    quad({-1, -3, -5}, {-1, 3, -5}, {-1, 3, -5 + kWallHeight}, {-1, -3, -5 + kWallHeight});
  };
  const Image image = render(path({{"GLPT_SPP", "64"}}), scene, 16, "path");
  for (int px = 24; px < 48; px += 3) {
    double measured = 0, expected = 0;
    int n = 0;
    for (int py = 22; py < 42; ++py) {
      const glm::dvec3 p = on_plane(px, py, -5.0f);
      if (p.x <= -1.0) continue;
      const std::vector<glm::dvec3> wall = {
          {-1, -3, -5}, {-1, 3, -5}, {-1, 3, -5 + kWallHeight}, {-1, -3, -5 + kWallHeight}};
      expected += 0.8 * 255 * (1.0 - polygon_form_factor(p, {0, 0, 1}, wall));
      measured += image.at(px, py);
      ++n;
    }
    if (n == 0) continue;
    expect_close(measured / n, expected / n, 0.02, 1.0,
                 "column " + std::to_string(px) + " (delta " +
                     std::to_string(on_plane(px, 32, -5.0f).x + 1.0f) + ")");
  }
}

// ---- emissive surfaces -------------------------------------------------------------------------

// A Lambertian plane z = -5 (albedo 1) under an emissive square (GL emission 3, black otherwise)
// 1.5 above it: the plane's radiance is L_e times the form factor from the point to the square
// (Lambert's formula). The camera sees the square itself over the plane's middle.
constexpr float kEmitterZ = -3.5f, kEmitterHalf = 1.0f, kEmission = 3.0f;

void plane_under_emissive_square() {
  camera();
  material(glm::vec3(1.0f));
  facing_plane(-5.0f, 3.0f);
  material(glm::vec3(0.0f), glm::vec3(kEmission));
  const float h = kEmitterHalf, z = kEmitterZ;
  quad({-h, -h, z}, {-h, h, z}, {h, h, z}, {h, -h, z});  // facing the plane
}

// The plane's expected value at pixel (px, py), or -1 where the camera sees the square.
double plane_under_square_radiance(int px, int py) {
  const glm::dvec3 p = on_plane(px, py, -5.0f);
  const glm::dvec3 through = p * double(kEmitterZ / -5.0f);  // where the pixel's ray meets z_e
  if (std::abs(through.x) < kEmitterHalf + 0.1 && std::abs(through.y) < kEmitterHalf + 0.1)
    return -1;
  const double h = kEmitterHalf, z = kEmitterZ;
  const std::vector<glm::dvec3> square = {{-h, -h, z}, {-h, h, z}, {h, h, z}, {h, -h, z}};
  return 255 * kEmission * polygon_form_factor(p, {0, 0, 1}, square);
}

TEST(LightTransport, EmissiveSurfaceLightsAPlaneAsItsFormFactorSays) {
  // Next-event estimation of the emitter alone (no bounces), then with bounces, which also hit
  // it: MIS weighs the two techniques, so the light is counted once and the image is the same.
  // Uniform points on the square have a relative deviation of about 0.7-1.1 per sample here:
  // 896 samples per pixel averaged over 6 x 6 pixel blocks leave about 0.5 %.
  constexpr int kBlock = 6;
  for (const char* bounces : {"0", "1"}) {
    const Image image =
        render(path({{"GLPT_BOUNCES", bounces}, {"GLPT_SPP", "128"}}), plane_under_emissive_square,
               8, (std::string("bounces") + bounces).c_str());
    int checked = 0;
    for (int by = 0; by + kBlock <= kSize; by += kBlock)
      for (int bx = 0; bx + kBlock <= kSize; bx += kBlock) {
        double measured = 0, expected = 0;
        bool on_plane_only = true;
        for (int y = by; y < by + kBlock; ++y)
          for (int x = bx; x < bx + kBlock; ++x) {
            const double e = plane_under_square_radiance(x, y);
            on_plane_only = on_plane_only && e >= 0;
            expected += e;
            measured += image.at(x, y);
          }
        if (!on_plane_only) continue;
        ++checked;
        constexpr double kPixels = kBlock * kBlock;
        expect_close(measured / kPixels, expected / kPixels, 0.025, 1.0,
                     std::string("bounces ") + bounces + ", block at " + std::to_string(bx) + "," +
                         std::to_string(by));
      }
    EXPECT_GT(checked, 50);
  }
}

// ---- specular ----------------------------------------------------------------------------------

TEST(LightTransport, MirrorLikeSurfaceReflectsAStripePattern) {
  // A black surface of GL shininess 128 and white specular facing the camera at z = -5; just
  // behind the camera, at z = +0.2, a wall of emissive vertical stripes 4 wide. The mirror pixel
  // at x shows the wall at (1 + 5.2 / 5) x along the reflected ray, dimmed to GL's lobe
  // reflectance 8 / 130 (15.7 / 255 for an emitter of 1) and blurred by the lobe's roughness
  // (alpha = 0.12, a few tenths of a unit on the wall): the stripes show, each at its place.
  auto scene = [] {
    camera();
    material(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(1.0f), 128.0f);
    facing_plane(-5.0f, 3.0f);
    for (int stripe = -4; stripe < 4; ++stripe) {
      const float e = (stripe & 1) == 0 ? 1.0f : 0.0f;
      material(glm::vec3(0.0f), glm::vec3(e));
      const float x0 = 4.0f * stripe, x1 = x0 + 4.0f;
      quad({x0, -20, 0.2f}, {x0, 20, 0.2f}, {x1, 20, 0.2f}, {x1, -20, 0.2f});  // facing -z
    }
  };
  const Image image = render(path({{"GLPT_SPP", "32"}, {"GLPT_BOUNCES", "1"}}), scene, 4, "path");
  double bright = 0, dark = 0, all = 0;
  int bright_n = 0, dark_n = 0, all_n = 0;
  for (int px = 0; px < kSize; ++px) {
    const float wall_x = 2.04f * on_plane(px, 32, -5.0f).x;
    const float in_stripe = wall_x / 4.0f - std::floor(wall_x / 4.0f);
    const bool emitting = (static_cast<int>(std::floor(wall_x / 4.0f)) & 1) == 0;
    for (int py = 28; py < 36; ++py) {
      all += image.at(px, py);
      ++all_n;
      if (in_stripe < 0.35f || in_stripe > 0.65f) continue;  // away from the stripes' edges
      (emitting ? bright : dark) += image.at(px, py);
      (emitting ? bright_n : dark_n) += 1;
    }
  }
  ASSERT_GT(bright_n, 0);
  ASSERT_GT(dark_n, 0);
  bright /= bright_n;
  dark /= dark_n;
  all /= all_n;
  std::printf("mirror: stripe centres %.1f (emitting) and %.1f (dark), mean %.1f\n", bright, dark,
              all);
  EXPECT_GT(bright, 3.0 * dark);
  EXPECT_GE(bright, 10.0);
  EXPECT_LE(bright, 15.7 + 1.5);  // never more than the lobe's reflectance
  // Half the wall emits: the mirror's mean is half the reflectance (less the lobe's
  // single-scattering loss, a few per cent at this roughness).
  EXPECT_NEAR(all, 0.5 * 15.7, 1.5);
}

// ---- textures in rays
// ----------------------------------------------------------------------------

// A 2 x 1 RGBA texture (nearest filtering) of the two colours, modulating.
void bind_two_texel_texture(const uint8_t left[4], const uint8_t right[4]) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  const uint8_t texels[8] = {left[0],  left[1],  left[2],  left[3],
                             right[0], right[1], right[2], right[3]};
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
}

void textured_quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
  const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p3 - p0));
  glBegin(GL_QUADS);
  glNormal3f(n.x, n.y, n.z);
  const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const glm::vec3 corners[4] = {p0, p1, p2, p3};
  for (int k = 0; k < 4; ++k) {
    glTexCoord2f(uv[k][0], uv[k][1]);
    glVertex3f(corners[k].x, corners[k].y, corners[k].z);
  }
  glEnd();
}

// The scene of the cut-out tests: a floor (z = -5, albedo 0.8) under a point light of colour 8
// at (0, 0, -1), and its unoccluded value at pixel (x, y): kd * colour * cos / d^2 with
// cos = 4 / d (the light is 4 above the floor).
void floor_under_low_light() {
  camera();
  material(glm::vec3(0.8f));
  inverse_square_light(GL_LIGHT0, {0.0f, 0.0f, -1.0f}, glm::vec3(8.0f));
  facing_plane(-5.0f, 3.0f);
}

double unoccluded_floor(int x, int y) {
  const glm::vec3 to_light = glm::vec3(0, 0, -1) - on_plane(x, y, -5.0f);
  const double d2 = glm::dot(to_light, to_light);
  return std::min(255.0, 255 * 0.8 * 8.0 * (4.0 / std::sqrt(d2)) / d2);
}

TEST(LightTransport, AlphaTestedQuadCastsTheShadowOfItsCutOut) {
  // A floor (z = -5) under a point light at (0, 0, -1); between them at z = -3 a quad whose
  // texture's left half is opaque and right half transparent, alpha-tested (GL_GREATER 0.5). Its
  // shadow on the floor is the left half's, scaled by 2: x in [-2, 0]; the cut-out casts none.
  auto scene = [](bool alpha_test) {
    return [alpha_test] {
      floor_under_low_light();
      const uint8_t opaque[4] = {255, 255, 255, 255}, clear[4] = {255, 255, 255, 0};
      bind_two_texel_texture(opaque, clear);
      if (alpha_test) {
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(GL_GREATER, 0.5f);
      }
      textured_quad({-1, -1, -3}, {1, -1, -3}, {1, 1, -3}, {-1, 1, -3});
      glDisable(GL_ALPHA_TEST);
      glDisable(GL_TEXTURE_2D);
    };
  };
  const Settings settings =
      path({{"GLPT_LIGHT_RADIUS", "0"}, {"GLPT_BOUNCES", "0"}, {"GLPT_AO", "0"}});
  const Image cut = render(settings, scene(true), 1, "alpha_test");
  const Image solid = render(settings, scene(false), 1, "solid");
  // Floor pixels in the left half's shadow but outside the quad's own image (x = -1.85).
  const int shadow_x = 10, y = 32;
  ASSERT_LT(on_plane(shadow_x, y, -5.0f).x, -1.6f);
  EXPECT_LT(cut.at(shadow_x, y), 10) << "the opaque half shadows the floor";
  // Floor seen through the cut-out at x = +1: lit; under the solid quad it was in shadow.
  const int lit_x = 43;
  ASSERT_GT(on_plane(lit_x, y, -5.0f).x, 0.8f);
  expect_close(cut.at(lit_x, y), unoccluded_floor(lit_x, y), 0.02, 2.0,
               "floor through the cut-out");
  // The solid (not alpha-tested) quad shadows the floor there too.
  EXPECT_LT(solid.at(shadow_x, y), 10);
}

TEST(LightTransport, ABlendedSolidWithSeeThroughTexelsIsTracedWhereItIsOpaque) {
  // The cut-out scene's quad drawn blended (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) with depth
  // writes, its texture's left half opaque and its right half of alpha 0.5, as a car with
  // windows: split by alpha (DrawClass::kSplitByAlpha), the left half is traced and shadows the
  // floor, the right half is blended over the trace and casts none. Before the split the whole
  // quad was drawn over the trace and shadowed nothing.
  auto scene = [] {
    floor_under_low_light();
    const uint8_t opaque[4] = {255, 255, 255, 255}, glass[4] = {255, 255, 255, 128};
    bind_two_texel_texture(opaque, glass);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    textured_quad({-1, -1, -3}, {1, -1, -3}, {1, 1, -3}, {-1, 1, -3});
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);
  };
  glpt::rt::FrameStats stats;
  const Image image =
      render(path({{"GLPT_LIGHT_RADIUS", "0"}, {"GLPT_BOUNCES", "0"}, {"GLPT_AO", "0"}}), scene, 1,
             "split", &stats);
  EXPECT_EQ(stats.traced_draws, 2u) << "the floor and the split quad";
  // Floor pixels in the opaque half's shadow (x in [-2, 0]) outside the quad's image, and beside
  // the see-through half's would-be shadow (x > 1.6).
  const int shadow_x = 12, lit_x = 53, y = 32;
  ASSERT_LT(on_plane(shadow_x, y, -5.0f).x, -1.6f);
  ASSERT_GT(on_plane(lit_x, y, -5.0f).x, 1.6f);
  EXPECT_LT(image.at(shadow_x, y), 10) << "the opaque half shadows the floor";
  expect_close(image.at(lit_x, y), unoccluded_floor(lit_x, y), 0.02, 2.0,
               "the floor beside the see-through half's shadow");
  // Under GL's own lighting (GL parity) the see-through half, blended over the traced floor, is
  // raster mode's: within half of what lighting the floor per pixel (GL parity) rather than per
  // vertex (raster mode) changes (about 8 levels on the floor under the quad here).
  const Image parity =
      render(path({{"GLPT_SHADOWS", "0"}, {"GLPT_BOUNCES", "0"}, {"GLPT_AO", "0"}}), scene, 1,
             "split_parity");
  const Image raster = render({{"GLPT_MODE", "raster"}}, scene, 1, "split_raster");
  // The see-through half's pixels: x in (0, 1) at z = -3, pixels 33 to 49.
  for (int py = 16; py < 48; py += 3)
    for (int px = 34; px < 49; px += 2)
      EXPECT_NEAR(parity.at(px, py), raster.at(px, py), 6) << px << "," << py;
  // ... which is the quad blended over the floor, not the floor alone.
  EXPECT_GT(raster.at(40, y), parity.at(60, y) + 50);
}

TEST(LightTransport, ClippedAwayPartsCastNoShadow) {
  // The alpha test's scene with an untextured quad whose right half (x > 0) a user clip plane
  // removes: the floor under the removed half is lit, the kept half still shadows.
  auto scene = [](bool clipped) {
    return [clipped] {
      floor_under_low_light();
      const double keep_left[] = {-1, 0, 0, 0};  // -x >= 0 (eye space: the modelview is I)
      glClipPlane(GL_CLIP_PLANE2, keep_left);
      if (clipped) glEnable(GL_CLIP_PLANE2);
      quad({-1, -1, -3}, {1, -1, -3}, {1, 1, -3}, {-1, 1, -3});
      glDisable(GL_CLIP_PLANE2);
    };
  };
  const Settings settings =
      path({{"GLPT_LIGHT_RADIUS", "0"}, {"GLPT_BOUNCES", "0"}, {"GLPT_AO", "0"}});
  const Image cut = render(settings, scene(true), 1, "clipped");
  const Image whole = render(settings, scene(false), 1, "whole");
  // Floor pixels in the shadows of the two halves, outside the quad's own image (x = -+1.85).
  const int left_x = 10, right_x = 53, y = 32;
  ASSERT_LT(on_plane(left_x, y, -5.0f).x, -1.6f);
  ASSERT_GT(on_plane(right_x, y, -5.0f).x, 1.6f);
  EXPECT_LT(cut.at(left_x, y), 10) << "the kept half shadows the floor";
  EXPECT_LT(whole.at(right_x, y), 10) << "unclipped, the right half shadows it too";
  // Clipped, the floor there is lit as if nothing were above it.
  for (int x : {right_x, 43})  // 43: seen through where the clipped half was
    expect_close(cut.at(x, y), unoccluded_floor(x, y), 0.02, 2.0,
                 "floor under the clipped-away half, x " + std::to_string(x));
}

TEST(LightTransport, BounceRaysSeeTheTexturesOfWhatTheyHit) {
  // A white floor lit from above beside a wall whose texture is pure red: light bouncing off the
  // wall onto the floor is red. The same wall with a white texture bounces white light. The red
  // texture on unit 0, or on unit 1 over a white one on unit 0 (a lightmap through
  // ARB_multitexture): rays see both units.
  enum class Red { kNone, kUnit0, kUnit1 };
  auto scene = [](Red red) {
    return [red] {
      camera();
      material(glm::vec3(0.8f));
      const float down[] = {-0.6f, 1.0f, 0.3f, 0.0f},
                  white[] = {1, 1, 1, 1};  // lights the wall's face too
      glLightfv(GL_LIGHT0, GL_POSITION, down);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
      glEnable(GL_LIGHT0);
      quad({-3, -1, -2}, {3, -1, -2}, {3, -1, -8}, {-3, -1, -8});  // floor, facing +y
      const uint8_t r[4] = {255, 0, 0, 255}, w[4] = {255, 255, 255, 255};
      bind_two_texel_texture(red == Red::kUnit0 ? r : w, red == Red::kUnit0 ? r : w);
      if (red == Red::kUnit1) {
        glActiveTexture(GL_TEXTURE1);
        bind_two_texel_texture(r, r);
        glActiveTexture(GL_TEXTURE0);
      }
      // The wall, facing -x (textured_quad gives unit 0 its coordinates; unit 1 samples its
      // constant texture at the current (0, 0)).
      textured_quad({0.5f, -1, -2}, {0.5f, 2, -2}, {0.5f, 2, -8}, {0.5f, -1, -8});
      glActiveTexture(GL_TEXTURE1);
      glDisable(GL_TEXTURE_2D);
      glActiveTexture(GL_TEXTURE0);
      glDisable(GL_TEXTURE_2D);
    };
  };
  const Settings settings = path({{"GLPT_SPP", "32"}, {"GLPT_BOUNCES", "1"}, {"GLPT_AO", "0"}});
  const Image white = render(settings, scene(Red::kNone), 2, "white_wall");
  for (Red which : {Red::kUnit0, Red::kUnit1}) {
    const char* name = which == Red::kUnit0 ? "red_unit0" : "red_unit1";
    const Image red = render(settings, scene(which), 2, name);
    // The floor just left of the wall (which stands at x = 0.5 and covers columns 35 and up).
    double red_g = 0, red_r = 0, white_g = 0, white_r = 0;
    for (int x = 24; x < 34; ++x)
      for (int y = 8; y < 20; ++y) {
        red_r += red.at(x, y, 0);
        red_g += red.at(x, y, 1);
        white_r += white.at(x, y, 0);
        white_g += white.at(x, y, 1);
      }
    std::printf("floor by the wall (%s): red wall r %.0f g %.0f, white wall r %.0f g %.0f\n", name,
                red_r / 120, red_g / 120, white_r / 120, white_g / 120);
    EXPECT_GT(red_r - red_g, 0.3 * (white_r - white_g) + 120 * 3.0)
        << name << ": red light bounces off the red texture";
    EXPECT_LT(red_g, white_g) << name << ": the red wall bounces no green";
  }
}

// The floor by the wall of BounceRaysSeeTheTexturesOfWhatTheyHit: mean red and green over the
// pixels just left of the wall (which stands at x = 0.5 and covers columns 35 and up).
glm::dvec2 floor_by_the_wall(const Image& image) {
  glm::dvec2 sum(0.0);
  for (int x = 24; x < 34; ++x)
    for (int y = 8; y < 20; ++y) sum += glm::dvec2(image.at(x, y, 0), image.at(x, y, 1));
  return sum / 120.0;
}

void nearest_filtering(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

TEST(LightTransport, BounceRaysSeeEveryTextureTargetUnitAndCoordinateGeneration) {
  // The scene of BounceRaysSeeTheTexturesOfWhatTheyHit with the wall's red from each texture
  // target and from unit 3, and from textures that are red only where GL's coordinate
  // generation points: cube maps red on one face only (green elsewhere), under GL_NORMAL_MAP
  // the -X face (the wall faces -x) and under GL_REFLECTION_MAP the -Z face (the view vectors
  // (x > 0, y, z << 0) reflect to (-x, y, z): mostly -Z; the normal would pick -X, the quad's
  // own coordinates +X or +Y), and a 2-texel texture red on the left under GL_SPHERE_MAP (the
  // reflected vectors have x < 0: s < 0.5; unreflected ones x > 0; the quad's coordinates span
  // both texels). Each must bounce the light of a plain red 2-D texture: wrong coordinates
  // bounce green or yellow light.
  const uint8_t red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255},
                white[4] = {255, 255, 255, 255};
  enum class Red { kNone, k2D, k1D, k3D, kUnit3, kCubeNormalMap, kCubeReflectionMap, kSphereMap };
  auto scene = [&](Red which) {
    return [&, which] {
      camera();
      material(glm::vec3(0.8f));
      const float down[] = {-0.6f, 1.0f, 0.3f, 0.0f}, one[] = {1, 1, 1, 1};
      glLightfv(GL_LIGHT0, GL_POSITION, down);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, one);
      glEnable(GL_LIGHT0);
      quad({-3, -1, -2}, {3, -1, -2}, {3, -1, -8}, {-3, -1, -8});  // floor, facing +y
      GLuint texture = 0;
      glGenTextures(1, &texture);
      GLenum target = GL_TEXTURE_2D;
      std::vector<GLenum> generated;  // GL_TEXTURE_GEN_* enabled
      GLint mode = 0;
      switch (which) {
        case Red::kNone:
          bind_two_texel_texture(white, white);
          break;
        case Red::k2D:
          bind_two_texel_texture(red, red);
          break;
        case Red::k1D:
          target = GL_TEXTURE_1D;
          glBindTexture(target, texture);
          nearest_filtering(target);
          glTexImage1D(target, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
          break;
        case Red::k3D:
          target = GL_TEXTURE_3D;
          glBindTexture(target, texture);
          nearest_filtering(target);
          glTexImage3D(target, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
          break;
        case Red::kUnit3:
          bind_two_texel_texture(white, white);
          glActiveTexture(GL_TEXTURE3);
          bind_two_texel_texture(red, red);
          glActiveTexture(GL_TEXTURE0);
          break;
        case Red::kCubeNormalMap:
        case Red::kCubeReflectionMap:
          target = GL_TEXTURE_CUBE_MAP;
          glBindTexture(target, texture);
          nearest_filtering(target);
          mode = which == Red::kCubeNormalMap ? GL_NORMAL_MAP : GL_REFLECTION_MAP;
          for (GLenum face = 0; face < 6; ++face) {
            // Faces in the order +X, -X, +Y, -Y, +Z, -Z.
            const bool red_face = face == (mode == GL_NORMAL_MAP ? 1u : 5u);
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, 1, 1, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, red_face ? red : green);
          }
          generated = {GL_S, GL_T, GL_R};
          break;
        case Red::kSphereMap:
          bind_two_texel_texture(red, green);
          generated = {GL_S, GL_T};
          mode = GL_SPHERE_MAP;
          break;
      }
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      glEnable(target);
      for (GLenum coord : generated) {
        glTexGeni(coord, GL_TEXTURE_GEN_MODE, mode);
        glEnable(coord == GL_S   ? GL_TEXTURE_GEN_S
                 : coord == GL_T ? GL_TEXTURE_GEN_T
                                 : GL_TEXTURE_GEN_R);
      }
      textured_quad({0.5f, -1, -2}, {0.5f, 2, -2}, {0.5f, 2, -8}, {0.5f, -1, -8});  // faces -x
      glDisable(GL_TEXTURE_GEN_S);
      glDisable(GL_TEXTURE_GEN_T);
      glDisable(GL_TEXTURE_GEN_R);
      glDisable(target);
      glActiveTexture(GL_TEXTURE3);
      glDisable(GL_TEXTURE_2D);
      glActiveTexture(GL_TEXTURE0);
    };
  };
  const Settings settings = path({{"GLPT_SPP", "32"}, {"GLPT_BOUNCES", "1"}, {"GLPT_AO", "0"}});
  const glm::dvec2 white_floor =
      floor_by_the_wall(render(settings, scene(Red::kNone), 2, "white_wall"));
  const glm::dvec2 red_floor = floor_by_the_wall(render(settings, scene(Red::k2D), 2, "red_2d"));
  std::printf("floor by the wall: white wall r %.1f g %.1f, plain red wall r %.1f g %.1f\n",
              white_floor.x, white_floor.y, red_floor.x, red_floor.y);
  ASSERT_GT(white_floor.y - red_floor.y, 10.0) << "the red wall's bounce is visible at all";
  const std::pair<Red, const char*> cases[] = {{Red::k1D, "red_1d"},
                                               {Red::k3D, "red_3d"},
                                               {Red::kUnit3, "red_unit3"},
                                               {Red::kCubeNormalMap, "red_cube_normal_map"},
                                               {Red::kCubeReflectionMap, "red_cube_reflection_map"},
                                               {Red::kSphereMap, "red_sphere_map"}};
  for (const auto& [which, name] : cases) {
    const glm::dvec2 floor = floor_by_the_wall(render(settings, scene(which), 2, name));
    std::printf("floor by the wall (%s): r %.1f g %.1f\n", name, floor.x, floor.y);
    // Green missing from the floor as the plain red wall takes it (to 10 %), red kept.
    EXPECT_GT(white_floor.y - floor.y, 0.9 * (white_floor.y - red_floor.y))
        << name << ": the wall bounces green light: its red texels were missed";
    EXPECT_NEAR(floor.x, red_floor.x, 2.0) << name;
  }
}

// ---- the sky
// -------------------------------------------------------------------------------------

TEST(LightTransport, TheSkyIsSeenInReflectionsAndBlocksNoSun) {
  // A sky box around the camera (unlit, uniform colour c, drawn first without depth writes: the
  // sky class) over a floor. A diffuse floor (albedo 0.8) under a sun straight above (diffuse
  // 0.5) is GL's 0.8 x 0.5 exactly, sample by sample: the sky box, not being world geometry,
  // casts no shadow, and the diffuse light of the surroundings at the primary vertex is GL's
  // ambient term (0 here), not counted again from the sky. A mirror-like floor (specular 1,
  // shininess 128, no diffuse) under a white sky reflects it at GL's lobe reflectance (8 / 130:
  // 15.7 / 255, less a few per cent of single-scattering loss). Traced as world, as before the
  // sky class, the box shadowed the sun and reflected nothing: a black floor both times.
  const glm::vec3 sky(0.25f, 0.5f, 0.75f);
  auto scene = [&](bool mirror) {
    return [&, mirror] {
      camera();
      glDisable(GL_LIGHTING);
      glDepthMask(GL_FALSE);
      if (mirror)
        glColor3f(1.0f, 1.0f, 1.0f);
      else
        glColor3f(sky.r, sky.g, sky.b);
      const float h = 20.0f;
      quad({-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h});
      quad({-h, -h, h}, {-h, h, h}, {h, h, h}, {h, -h, h});
      quad({-h, -h, -h}, {-h, h, -h}, {-h, h, h}, {-h, -h, h});
      quad({h, -h, -h}, {h, -h, h}, {h, h, h}, {h, h, -h});
      quad({-h, -h, -h}, {-h, -h, h}, {h, -h, h}, {h, -h, -h});
      quad({-h, h, -h}, {h, h, -h}, {h, h, h}, {-h, h, h});
      glDepthMask(GL_TRUE);
      if (mirror) {
        material(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(1.0f), 128.0f);
      } else {
        material(glm::vec3(0.8f));
        const float up[] = {0, 1, 0, 0}, half[] = {0.5f, 0.5f, 0.5f, 1};
        glLightfv(GL_LIGHT0, GL_POSITION, up);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, half);
        glEnable(GL_LIGHT0);
      }
      quad({-3, -1, -2}, {3, -1, -2}, {3, -1, -8}, {-3, -1, -8});  // floor, facing +y
    };
  };
  const Settings settings = path({{"GLPT_SPP", "16"}, {"GLPT_BOUNCES", "1"}, {"GLPT_AO", "0"}});
  auto floor_mean = [](const Image& image, int channel) {
    double sum = 0;
    for (int y = 4; y < 14; ++y)
      for (int x = 20; x < 44; ++x) sum += image.at(x, y, channel);
    return sum / 240.0;
  };
  const Image sunlit = render(settings, scene(false), 2, "sky_and_sun");
  const Image mirror = render(settings, scene(true), 2, "sky_in_a_mirror");
  for (int c = 0; c < 3; ++c) {
    const std::string channel = "channel " + std::to_string(c);
    EXPECT_EQ(sunlit.at(32, 60, c), std::lround(sky[c] * 255.0f)) << "the sky as GL draws it";
    expect_close(floor_mean(sunlit, c), 0.8 * 0.5 * 255.0, 0.01, 1.0, "sunlit floor, " + channel);
    const double reflected = floor_mean(mirror, c);
    std::printf("mirror floor under a white sky, %s: %.2f\n", channel.c_str(), reflected);
    EXPECT_GE(reflected, 12.0) << "the mirror reflects the sky, " << channel;
    EXPECT_LE(reflected, 15.7 + 1.5) << "never more than the lobe's reflectance, " << channel;
  }
}

// ---- many lights -------------------------------------------------------------------------------

// A floor of 10 x 10 tiles, each its own draw lit by 8 of 100 positional lights: tile i by the
// lights i .. i + 7 (mod 100), of strengths spanning two orders of magnitude.
void hundred_lights() {
  camera();
  material(glm::vec3(0.8f));
  for (int tile = 0; tile < 100; ++tile) {
    const int tx = tile % 10, ty = tile / 10;
    const float x = -3.0f + 0.6f * tx, y = -3.0f + 0.6f * ty;
    for (int k = 0; k < 8; ++k) {
      const int l = (tile + k * 13) % 100;
      const float lx = -3.0f + 0.6f * (l % 10) + 0.3f, ly = -3.0f + 0.6f * (l / 10) + 0.3f;
      const float strength = 0.02f * std::pow(10.0f, 2.0f * ((l * 37) % 100) / 100.0f);
      inverse_square_light(GL_LIGHT0 + k, {lx, ly, -4.0f}, glm::vec3(strength));
    }
    quad({x, y, -5}, {x + 0.6f, y, -5}, {x + 0.6f, y + 0.6f, -5}, {x, y + 0.6f, -5});
  }
}

double mean_squared_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    const double d = double(a.rgba[i]) - double(b.rgba[i]);
    sum += d * d;
  }
  return sum / (a.rgba.size() / 4);
}

TEST(LightTransport, HundredLightsConvergeToLoopingOverAllWithLessNoiseThanUniformChoice) {
  const Settings base = {{"GLPT_BOUNCES", "0"}, {"GLPT_LIGHT_RADIUS", "0.15"}};
  auto with = [&](const char* choice, const char* spp, int frames) {
    Settings s = path(base);
    s.push_back({"GLPT_LIGHT_CHOICE", choice});
    s.push_back({"GLPT_SPP", spp});
    return render(s, hundred_lights, frames, choice);
  };
  const Image reference = with("all", "64", 4);
  const Image contribution = with("contribution", "4", 1);
  const Image uniform = with("uniform", "4", 1);
  const Image contribution_converged = with("contribution", "64", 4);
  // The same image in expectation: converged, the choice matches looping over every light.
  EXPECT_NEAR(contribution_converged.mean(), reference.mean(), 0.01 * reference.mean() + 0.3);
  EXPECT_LT(mean_squared_difference(contribution_converged, reference), 2.0);
  // At equal samples (and equal shadow rays: one per sample), choosing by contribution is less
  // noisy than choosing uniformly.
  const double error_contribution = mean_squared_difference(contribution, reference);
  const double error_uniform = mean_squared_difference(uniform, reference);
  std::printf(
      "100 lights, 4 spp: mean squared error %.2f (by contribution) vs %.2f (uniform), "
      "ratio %.2f\n",
      error_contribution, error_uniform, error_uniform / error_contribution);
  EXPECT_LT(error_contribution, 0.5 * error_uniform);
}

// ---- GL parity ---------------------------------------------------------------------------------

// A finely tessellated lit sphere (Gouraud interpolation then differs little from per-pixel
// lighting) under a positional light with attenuation and a coloured directional spot, with
// specular, two-sided lighting and a local viewer.
// A finely tessellated lit sphere with two lights, specular and a local viewer; `textured`: with
// a checker texture (GL_MODULATE) and a little emission, under GL_LIGHT_MODEL_COLOR_CONTROL
// `color_control`.
void lit_sphere_with(bool textured, GLenum color_control) {
  camera();
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  const float ambient[] = {0.1f, 0.1f, 0.15f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  const float p0[] = {2, 2, -2, 1}, d0[] = {0.9f, 0.8f, 0.7f, 1}, a0[] = {0.05f, 0.05f, 0.05f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, p0);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, d0);
  glLightfv(GL_LIGHT0, GL_AMBIENT, a0);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1f);
  glEnable(GL_LIGHT0);
  const float p1[] = {-1, 0.5f, 1, 0}, d1[] = {0.2f, 0.3f, 0.6f, 1};
  glLightfv(GL_LIGHT1, GL_POSITION, p1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, d1);
  glLightfv(GL_LIGHT1, GL_SPECULAR, d1);
  glEnable(GL_LIGHT1);
  const float diffuse[] = {0.7f, 0.5f, 0.3f, 1}, specular[] = {0.6f, 0.6f, 0.6f, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  const float no_emission[] = {0, 0, 0, 1}, emission[] = {0.1f, 0.15f, 0.05f, 1};
  glMaterialfv(GL_FRONT, GL_EMISSION, textured ? emission : no_emission);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, color_control);
  if (textured) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    uint8_t texels[8 * 8 * 3];
    for (int i = 0; i < 8 * 8; ++i) {
      const bool dark = ((i % 8) + (i / 8)) % 2 == 0;
      texels[3 * i + 0] = dark ? 40 : 250;
      texels[3 * i + 1] = dark ? 60 : 230;
      texels[3 * i + 2] = dark ? 120 : 200;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
  }
  const int kRings = 96, kSegments = 192;
  const float r = 1.5f;
  const glm::vec3 c(0, 0, -5);
  for (int i = 0; i < kRings; ++i) {
    const float t0 = M_PI * i / kRings, t1 = M_PI * (i + 1) / kRings;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= kSegments; ++j) {
      const float phi = 2 * M_PI * j / kSegments;
      for (float t : {t1, t0}) {
        const glm::vec3 n(std::sin(t) * std::cos(phi), std::cos(t), std::sin(t) * std::sin(phi));
        glNormal3f(n.x, n.y, n.z);
        glTexCoord2f(phi / float(2 * M_PI), t / float(M_PI));
        const glm::vec3 p = c + r * n;
        glVertex3f(p.x, p.y, p.z);
      }
    }
    glEnd();
  }
  if (textured) glDisable(GL_TEXTURE_2D);
}

void lit_sphere() { lit_sphere_with(false, GL_SINGLE_COLOR); }

double psnr(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.rgba[i]) - double(b.rgba[i]);
    sum += d * d;
  }
  const double mse = sum / (a.rgba.size() / 4 * 3);
  return mse == 0 ? 99.0 : 10 * std::log10(255.0 * 255.0 / mse);
}

TEST(LightTransport, WithoutShadowsBouncesAndAoThePathTracerIsGlsLighting) {
  const Image gl = render({{"GLPT_MODE", "raster"}}, lit_sphere, 1, "raster");
  const Image parity =
      render(path({{"GLPT_SHADOWS", "0"}, {"GLPT_BOUNCES", "0"}, {"GLPT_AO", "0"}}), lit_sphere, 1,
             "parity");
  const double db = psnr(gl, parity);
  std::printf("GL parity: PSNR %.1f dB against raster mode (= Mesa)\n", db);
  EXPECT_GT(db, 40.0);
}

TEST(LightTransport, GlParityHoldsForTexturedSurfacesUnderBothColourControls) {
  // GL textures the lit colour: emission always, specular too under GL_SINGLE_COLOR (GL 1.5
  // 2.14.1, 3.9); under GL_SEPARATE_SPECULAR_COLOR specular is added after texturing.
  for (GLenum control : {GLenum(GL_SINGLE_COLOR), GLenum(GL_SEPARATE_SPECULAR_COLOR)}) {
    auto scene = [control] { lit_sphere_with(true, control); };
    const Image gl = render({{"GLPT_MODE", "raster"}}, scene, 1, "raster");
    const Image parity = render(
        path({{"GLPT_SHADOWS", "0"}, {"GLPT_BOUNCES", "0"}, {"GLPT_AO", "0"}}), scene, 1, "parity");
    const double db = psnr(gl, parity);
    std::printf("textured GL parity (%s): PSNR %.1f dB against raster mode\n",
                control == GL_SINGLE_COLOR ? "GL_SINGLE_COLOR" : "GL_SEPARATE_SPECULAR_COLOR", db);
    EXPECT_GT(db, 40.0) << control;
  }
}

// ---- bad input ---------------------------------------------------------------------------------

TEST(LightTransport, NonFiniteLightAndMaterialStatePutsNoNanIntoTheImage) {
  auto scene = [] {
    camera();
    material(glm::vec3(0.8f));
    const float nan = std::nanf(""), inf = INFINITY;
    const float p[] = {nan, 0, -3, 1}, d[] = {inf, 1, 1, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, p);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, d);
    glEnable(GL_LIGHT0);
    facing_plane(-5.0f, 3.0f);
    glBegin(GL_TRIANGLES);  // zero-area and zero-normal triangles
    glNormal3f(0, 0, 0);
    glVertex3f(0, 0, -4);
    glVertex3f(0, 0, -4);
    glVertex3f(1, 0, -4);
    glEnd();
  };
  const Image image = render(path({{"GLPT_SPP", "4"}}), scene, 2, "path");
  // Whatever GL makes of such a light, every pixel has a defined colour: the clear colour's
  // black or the plane's; not the garbage a NaN would leave in the accumulation.
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ASSERT_EQ(image.at(x, y, 3), 255) << x << "," << y;
}

TEST(LightTransport, ANonFiniteSampleIsDroppedAndCountedNotShownAsBlack) {
  // A lit plane whose bounce rays reach a surface of infinite emission behind the camera's view
  // (GL takes any float): those paths carry infinite radiance. They are dropped and counted; the
  // plane's pixels keep the light of the paths that stay finite.
  auto scene = [] {
    camera();
    material(glm::vec3(0.8f));
    inverse_square_light(GL_LIGHT0, {0.0f, 0.0f, -3.0f}, glm::vec3(3.0f));
    facing_plane(-5.0f, 3.0f);
    material(glm::vec3(0.0f), glm::vec3(INFINITY));
    quad({-3, -3, -2}, {-3, 3, -2}, {-3, 3, 0.5f}, {-3, -3, 0.5f});  // a wall at the left edge
  };
  glpt::rt::FrameStats stats;
  const Image image = render(path({{"GLPT_SPP", "4"}}), scene, 1, "path", &stats);
  EXPECT_GT(stats.non_finite_samples, 0u);
  std::printf("non-finite samples dropped: %llu\n",
              static_cast<unsigned long long>(stats.non_finite_samples));
  // The middle of the plane, lit directly (3 cos / d^2 = 0.75 of white at albedo 0.8: about
  // 153): never black, never saturated by an infinity.
  for (int y = 24; y < 40; y += 3)
    for (int x = 24; x < 40; x += 3) {
      EXPECT_GT(image.at(x, y), 100) << x << "," << y;
      EXPECT_LT(image.at(x, y), 250) << x << "," << y;
    }
}

// ---- GLPT_SCALE
// ----------------------------------------------------------------------------------

TEST(LightTransport, ATraceScaleOfAHalfTracesAQuarterOfThePixelsAndKeepsEdgesAndThinObjects) {
  // The plane under a point light (direct light only: every sample is exact, so the images of the
  // two scales differ only by what the fill pass makes of the untraced pixels), a square casting
  // a sharp shadow twice its size onto the plane, and a bar a pixel or two high on its own plane:
  // none of its pixels' neighbours on the grid lies on its surface, so the fill pass traces them.
  auto scene = [] {
    camera();
    material(glm::vec3(1.0f));
    inverse_square_light(GL_LIGHT0, {0.0f, 0.0f, -3.0f}, glm::vec3(3.0f));
    facing_plane(-5.0f, 3.0f);
    quad({-0.4f, -0.4f, -4.0f}, {0.4f, -0.4f, -4.0f}, {0.4f, 0.4f, -4.0f}, {-0.4f, 0.4f, -4.0f});
    quad({-1.5f, -1.65f, -4.5f}, {1.5f, -1.65f, -4.5f}, {1.5f, -1.55f, -4.5f},
         {-1.5f, -1.55f, -4.5f});
  };
  Settings settings = path({{"GLPT_LIGHT_RADIUS", "0"},
                            {"GLPT_BOUNCES", "0"},
                            {"GLPT_AO", "0"},
                            {"GLPT_DENOISER", "off"}});
  glpt::rt::FrameStats full_stats, half_stats;
  const Image full = render(settings, scene, 1, "full", &full_stats);
  settings.push_back({"GLPT_SCALE", "0.5"});
  const Image half = render(settings, scene, 1, "half", &half_stats);
  std::printf("rays: scale 1 %llu, scale 0.5 %llu\n",
              static_cast<unsigned long long>(full_stats.rays),
              static_cast<unsigned long long>(half_stats.rays));
  ASSERT_GT(full_stats.rays, 0u);
  // A quarter of the pixels, plus those the fill pass traces itself (the bar, silhouettes).
  EXPECT_LT(static_cast<double>(half_stats.rays), 0.35 * static_cast<double>(full_stats.rays));
  // Away from edges the fill pass interpolates a smooth field: within 1 % + 1 level. Edges (of
  // geometry or shadow: pixels within 2 of a jump of 10 % in the scale-1 image) may move by up
  // to a cell, and the last row and column extrapolate from one side.
  auto jump = [&](int x, int y) {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int u = x + dx, v = y + dy;
        if (u < 1 || v < 1 || u >= kSize || v >= kSize) continue;
        for (const auto& [a, b] : {std::pair{full.at(u, v), full.at(u - 1, v)},
                                   std::pair{full.at(u, v), full.at(u, v - 1)}})
          if (std::abs(a - b) > 0.1 * std::max(a, b) + 2) return true;
      }
    return false;
  };
  int differing = 0, differing_smooth = 0, bar_pixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const int a = full.at(x, y), b = half.at(x, y);
      if (std::abs(a - b) > 0.01 * a + 1) {
        ++differing;
        const bool border = x == 0 || y == 0 || x == kSize - 1 || y == kSize - 1;
        if (!border && !jump(x, y)) ++differing_smooth;
      }
      // The bar: nearer than the plane, lit brighter; every one of its pixels as at scale 1.
      const glm::vec3 p = on_plane(x, y, -4.5f);
      if (p.y > -1.65f && p.y < -1.55f && std::abs(p.x) < 1.4f) {
        ++bar_pixels;
        expect_close(b, a, 0.01, 1.0, "bar pixel " + std::to_string(x) + "," + std::to_string(y));
      }
    }
  std::printf("pixels beyond 1 %% + 1 level: %d of %d, %d of them away from edges\n", differing,
              kSize * kSize, differing_smooth);
  EXPECT_GT(bar_pixels, 20);
  EXPECT_LE(differing_smooth, kSize * kSize / 200);
  EXPECT_LE(differing, kSize * kSize / 20);
}

}  // namespace
