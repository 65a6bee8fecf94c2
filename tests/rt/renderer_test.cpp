// Renders of tiny synthetic frames through the public API, checking behaviour that breaks visibly
// when a part of the tracer (camera, shading, shadow rays, accumulation, caching) is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>

#include "rt_core/passes/path_tracer.hpp"

namespace glpt::rt {
namespace {

constexpr uint32_t kSize = 64;

struct Rgba {
  int r, g, b, a;
  int luminance() const { return r + g + b; }
};

std::ostream& operator<<(std::ostream& out, const Rgba& c) {
  return out << "(" << c.r << "," << c.g << "," << c.b << "," << c.a << ")";
}

struct Image {
  std::vector<uint8_t> rgba;
  FrameStats stats;
  // (x, y) in GL window coordinates: y = 0 is the bottom row.
  Rgba at(uint32_t x, uint32_t y) const {
    const uint8_t* p = &rgba[(size_t{y} * kSize + x) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
};

// Each test uses its own content hashes so the shared renderer's BLAS cache never mixes them up.
uint64_t next_hash() {
  static uint64_t hash = 0x5eed0000;
  return ++hash;
}

// A parallelogram from `corner` spanned by edges u and v; its front face and normal point along
// cross(u, v), or the normals point the other way with `flip_normal` ("facing away").
std::shared_ptr<const Geometry> quad(glm::vec3 corner, glm::vec3 u, glm::vec3 v,
                                     glm::vec4 color = glm::vec4(1.0f),
                                     const Material& material = Material{},
                                     bool flip_normal = false) {
  auto geometry = std::make_shared<Geometry>();
  const glm::vec3 p00 = corner, p10 = corner + u, p01 = corner + v, p11 = corner + u + v;
  geometry->positions = {p00, p10, p11, p00, p11, p01};
  glm::vec3 normal = glm::normalize(glm::cross(u, v));
  if (flip_normal) normal = -normal;
  geometry->normals.assign(6, normal);
  geometry->colors.assign(6, color);
  geometry->material_ids = {0, 0};
  geometry->materials = {material};
  geometry->content_hash = next_hash();
  return geometry;
}

TraceScene base_frame() {
  TraceScene frame;
  frame.width = frame.height = kSize;
  frame.viewport = {0, 0, kSize, kSize};
  frame.projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  frame.clear_color = glm::vec4(0.2f, 0.4f, 0.6f, 0.0f);
  frame.global_ambient = glm::vec4(0.2f, 0.2f, 0.2f, 1.0f);
  return frame;
}

Light directional_light(glm::vec3 towards_light) {
  Light light;
  light.position = glm::vec4(glm::normalize(towards_light), 0.0f);
  return light;
}

// Pixel (x, y) where eye-space point p lands with base_frame()'s projection.
glm::ivec2 project(const TraceScene& frame, glm::vec3 p) {
  glm::vec4 clip = frame.projection * glm::vec4(p, 1.0f);
  glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return glm::ivec2((ndc * 0.5f + 0.5f) * float(kSize));
}

class RenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // GLPT_VALIDATION=1 in the environment runs these tests under the validation layer.
    RenderSettings settings = RenderSettings::from_environment();
    settings.samples_per_pixel = 1;
    settings.bounces = 1;
    settings.accumulate = true;
    renderer_ = PathTracer::create(settings, &error_);
  }
  static void TearDownTestSuite() { renderer_.reset(); }

  void SetUp() override {
    // No ray-query device is a failure, not a skip: the message says what to install.
    ASSERT_NE(renderer_, nullptr) << error_;
  }

  static Image render(const TraceScene& frame) {
    Image image;
    std::string error;
    EXPECT_TRUE(renderer_->render(frame, image.rgba, image.stats, &error)) << error;
    EXPECT_EQ(image.rgba.size(), size_t{frame.width} * frame.height * 4);
    return image;
  }

  static std::unique_ptr<PathTracer> renderer_;
  static std::string error_;
};

std::unique_ptr<PathTracer> RenderTest::renderer_;
std::string RenderTest::error_;

TEST_F(RenderTest, MissPixelsShowTheClearColour) {
  TraceScene frame = base_frame();
  frame.instances.push_back({quad({-0.5f, -0.5f, -5.0f}, {1, 0, 0}, {0, 1, 0}), glm::mat4(1.0f)});
  frame.lights.push_back(directional_light({0, 0, 1}));
  Image image = render(frame);
  const Rgba expected{51, 102, 153, 0};  // 0.2, 0.4, 0.6, 0.0 as GL rounds them
  for (auto [x, y] : {std::pair{0u, 0u}, {63u, 63u}, {5u, 60u}}) {
    Rgba c = image.at(x, y);
    EXPECT_EQ(c.r, expected.r) << c;
    EXPECT_EQ(c.g, expected.g) << c;
    EXPECT_EQ(c.b, expected.b) << c;
    EXPECT_EQ(c.a, expected.a) << c;
  }
  EXPECT_EQ(image.at(32, 32).a, 255);  // traced pixels are opaque
  EXPECT_GT(image.stats.rays, 0u);
  EXPECT_EQ(image.stats.triangles, 2u);
}

TEST_F(RenderTest, PixelsOutsideTheViewportShowTheClearColour) {
  TraceScene frame = base_frame();
  frame.viewport = {16, 16, 32, 32};
  // A quad filling the whole view: every viewport pixel hits it.
  Material unlit;
  unlit.lit = false;
  frame.instances.push_back(
      {quad({-50, -50, -5}, {100, 0, 0}, {0, 100, 0}, glm::vec4(1, 0, 0, 1), unlit),
       glm::mat4(1.0f)});
  Image image = render(frame);
  EXPECT_EQ(image.at(32, 32).r, 255);
  EXPECT_EQ(image.at(16, 16).r, 255);
  EXPECT_EQ(image.at(47, 47).r, 255);
  for (auto [x, y] : {std::pair{15u, 32u}, {48u, 32u}, {32u, 15u}, {32u, 48u}}) {
    Rgba c = image.at(x, y);
    EXPECT_EQ(c.r, 51) << x << "," << y << " " << c;
    EXPECT_EQ(c.a, 0) << x << "," << y << " " << c;
  }
}

TEST_F(RenderTest, UnlitQuadShowsItsExactVertexColour) {
  TraceScene frame = base_frame();
  Material unlit;
  unlit.lit = false;
  frame.instances.push_back(
      {quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(0.25f, 0.75f, 0.2f, 1.0f), unlit),
       glm::mat4(1.0f)});
  frame.lights.push_back(directional_light({1, 1, 1}));  // must not matter
  Image image = render(frame);
  for (auto [x, y] : {std::pair{32u, 32u}, {28u, 36u}, {36u, 28u}}) {
    Rgba c = image.at(x, y);
    EXPECT_EQ(c.r, 64) << c;
    EXPECT_EQ(c.g, 191) << c;
    EXPECT_EQ(c.b, 51) << c;
    EXPECT_EQ(c.a, 255) << c;
  }
}

TEST_F(RenderTest, QuadFacingTheLightIsBrighterThanQuadFacingAway) {
  TraceScene frame = base_frame();
  Material white;
  white.diffuse = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  // Same geometry side by side, both seen from the front; the right one's normals point away.
  frame.instances.push_back(
      {quad({-2.2f, -1, -5}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1), white), glm::mat4(1.0f)});
  frame.instances.push_back(
      {quad({0.2f, -1, -5}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1), white, true), glm::mat4(1.0f)});
  frame.lights.push_back(directional_light({0, 0, 1}));
  Image image = render(frame);
  const glm::ivec2 facing = project(frame, {-1.2f, 0, -5}), away = project(frame, {1.2f, 0, -5});
  const Rgba lit = image.at(facing.x, facing.y), unlit = image.at(away.x, away.y);
  EXPECT_GT(lit.luminance(), unlit.luminance() + 300) << lit << " vs " << unlit;
  // GL: 0.8 diffuse * 1.0 light + 0.2 * 0.2 ambient = 0.84 -> 214 (plus a little bounce light).
  EXPECT_NEAR(lit.r, 214, 12) << lit;
}

TEST_F(RenderTest, OccluderShadowsThePlaneBehindIt) {
  TraceScene frame = base_frame();
  // A floor at y = -1 lit from straight above, and a small horizontal quad hovering over it.
  frame.instances.push_back({quad({-4, -1, -2}, {8, 0, 0}, {0, 0, -8}), glm::mat4(1.0f)});
  frame.instances.push_back({quad({-0.5f, -0.5f, -4.5f}, {1, 0, 0}, {0, 0, -1}), glm::mat4(1.0f)});
  frame.lights.push_back(directional_light({0, 1, 0}));
  Image image = render(frame);
  const glm::ivec2 shadowed = project(frame, {0, -1, -5}), open = project(frame, {2, -1, -5});
  const Rgba in_shadow = image.at(shadowed.x, shadowed.y), in_light = image.at(open.x, open.y);
  EXPECT_LT(in_shadow.luminance() * 2, in_light.luminance()) << in_shadow << " vs " << in_light;
}

TEST_F(RenderTest, DefaultLightWhenLitSurfacesHaveNoLight) {
  TraceScene frame = base_frame();
  frame.instances.push_back({quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}), glm::mat4(1.0f)});
  Image image = render(frame);
  // Ambient alone would give 0.2 * 0.2 = 0.04 (10); the default light adds 0.8 * N.L.
  EXPECT_GT(image.at(32, 32).r, 60) << image.at(32, 32);
}

TEST_F(RenderTest, PositionalLightIsAttenuatedWithDistance) {
  Material white;
  white.ambient = glm::vec4(0.0f);
  auto render_with_attenuation = [&](float quadratic) {
    TraceScene frame = base_frame();
    frame.global_ambient = glm::vec4(0.0f);
    frame.instances.push_back(
        {quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1), white), glm::mat4(1.0f)});
    Light light;
    light.position = glm::vec4(0, 0, -2, 1);  // 2 units in front of the quad
    light.quadratic_attenuation = quadratic;
    frame.lights.push_back(light);
    return render(frame).at(32, 32);
  };
  const Rgba bright = render_with_attenuation(0.0f), dim = render_with_attenuation(0.25f);
  EXPECT_NEAR(bright.r, 204, 6) << bright;  // 0.8 * N.L = 1
  EXPECT_NEAR(dim.r, 102, 6) << dim;        // / (1 + 0.25 * 2^2)
}

TEST_F(RenderTest, OrthographicProjection) {
  TraceScene frame = base_frame();
  frame.projection = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 10.0f);
  Material unlit;
  unlit.lit = false;
  // Covers x in [-2, 0]: the left half of the image.
  frame.instances.push_back(
      {quad({-2, -2, -5}, {2, 0, 0}, {0, 4, 0}, glm::vec4(0, 1, 0, 1), unlit), glm::mat4(1.0f)});
  Image image = render(frame);
  EXPECT_EQ(image.at(16, 32).g, 255);
  EXPECT_EQ(image.at(48, 32).g, 102);  // clear colour
}

TEST_F(RenderTest, AccumulatesUnchangedFramesAndRestartsOnChange) {
  TraceScene frame = base_frame();
  frame.instances.push_back({quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}), glm::mat4(1.0f)});
  frame.lights.push_back(directional_light({0, 0, 1}));
  EXPECT_EQ(render(frame).stats.accumulated_samples, 1u);
  EXPECT_EQ(render(frame).stats.accumulated_samples, 2u);
  EXPECT_EQ(render(frame).stats.accumulated_samples, 3u);
  frame.instances[0].modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0, 0));
  EXPECT_EQ(render(frame).stats.accumulated_samples, 1u);
  EXPECT_EQ(render(frame).stats.accumulated_samples, 2u);
  frame.lights[0].diffuse = glm::vec4(0.5f);
  EXPECT_EQ(render(frame).stats.accumulated_samples, 1u);
  frame.clear_color = glm::vec4(1.0f);
  EXPECT_EQ(render(frame).stats.accumulated_samples, 1u);
}

TEST_F(RenderTest, ReusesBlasOfUnchangedGeometry) {
  TraceScene frame = base_frame();
  frame.instances.push_back({quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}), glm::mat4(1.0f)});
  // A second instance of the same geometry shares its BLAS.
  frame.instances.push_back(
      {frame.instances[0].geometry, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -3))});
  Image first = render(frame);
  EXPECT_EQ(first.stats.blas_builds, 1u);
  EXPECT_EQ(first.stats.blas_reused, 0u);
  EXPECT_EQ(first.stats.triangles, 4u);

  frame.instances[1].modelview = glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, -3));
  Image second = render(frame);
  EXPECT_EQ(second.stats.blas_builds, 0u);
  EXPECT_GT(second.stats.blas_reused, 0u);
  EXPECT_GT(second.stats.rays, 0u);
}

TEST_F(RenderTest, ManyInstancesEachFindTheirOwnShadingData) {
  // 8x8 unlit tiles drawn in a scrambled order, each with its own colour: the TLAS reorders
  // instances spatially, and every hit must still reach its own geometry's data.
  TraceScene frame = base_frame();
  frame.projection = glm::ortho(0.0f, 8.0f, 0.0f, 8.0f, 0.1f, 10.0f);
  Material unlit;
  unlit.lit = false;
  auto colour_of = [](int i, int j) { return glm::vec4(i / 8.0f, j / 8.0f, 0.5f, 1.0f); };
  for (int k = 0; k < 64; ++k) {
    const int scrambled = (k * 37) % 64, i = scrambled % 8, j = scrambled / 8;
    auto tile = quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, colour_of(i, j), unlit);
    frame.instances.push_back(
        {tile, glm::translate(glm::mat4(1.0f), glm::vec3(float(i), float(j), -5.0f))});
  }
  Image image = render(frame);
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      const Rgba c = image.at(uint32_t(i * 8 + 4), uint32_t(j * 8 + 4));
      ASSERT_EQ(c.r, std::lround(i / 8.0 * 255)) << i << "," << j << " " << c;
      ASSERT_EQ(c.g, std::lround(j / 8.0 * 255)) << i << "," << j << " " << c;
    }
  }
}

TEST_F(RenderTest, EmptyAndDegenerateFramesRenderTheClearColour) {
  TraceScene frame = base_frame();
  Image empty = render(frame);  // no instances: an empty TLAS
  EXPECT_EQ(empty.at(32, 32).b, 153);
  EXPECT_EQ(empty.stats.triangles, 0u);

  auto no_triangles = std::make_shared<Geometry>();
  no_triangles->content_hash = next_hash();
  frame.instances.push_back({nullptr, glm::mat4(1.0f)});
  frame.instances.push_back({no_triangles, glm::mat4(1.0f)});
  auto broken = std::const_pointer_cast<Geometry>(quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}));
  broken->positions[1].x = std::nanf("");
  broken->normals.clear();  // missing attributes get GL defaults
  broken->colors.clear();
  broken->material_ids.clear();
  frame.instances.push_back({broken, glm::mat4(1.0f)});
  Image degenerate = render(frame);
  EXPECT_EQ(degenerate.stats.triangles, 2u);

  frame.projection = glm::mat4(0.0f);  // singular: no pixel can be unprojected
  EXPECT_EQ(render(frame).at(32, 32).b, 153);
  frame.viewport = {0, 0, 0, 0};
  EXPECT_EQ(render(frame).at(32, 32).b, 153);
  frame.width = 0;
  Image nothing = render(frame);
  EXPECT_TRUE(nothing.rgba.empty());
}

TEST_F(RenderTest, SpotLightLightsOnlyInsideItsCone) {
  TraceScene frame = base_frame();
  frame.global_ambient = glm::vec4(0.0f);
  Material white;
  white.ambient = glm::vec4(0.0f);
  frame.instances.push_back(
      {quad({-2, -2, -4}, {4, 0, 0}, {0, 4, 0}, glm::vec4(1), white), glm::mat4(1.0f)});
  Light spot;
  spot.position = glm::vec4(0, 0, -2, 1);
  spot.spot_direction = glm::vec3(0, 0, -1);
  spot.spot_cutoff = 10.0f;
  frame.lights.push_back(spot);
  Image image = render(frame);
  const glm::ivec2 inside = project(frame, {0, 0, -4}), outside = project(frame, {1, 0, -4});
  EXPECT_NEAR(image.at(inside.x, inside.y).r, 204, 6) << image.at(inside.x, inside.y);
  EXPECT_LT(image.at(outside.x, outside.y).r, 20) << image.at(outside.x, outside.y);
}

TEST_F(RenderTest, MaterialTermsFollowGl) {
  TraceScene frame = base_frame();
  frame.global_ambient = glm::vec4(0.0f);
  frame.lights.push_back(directional_light({0, 0, 1}));  // head-on: N.L = N.H = 1 at the centre
  auto centre_with = [&](const Material& material, glm::vec4 vertex_color) {
    TraceScene f = frame;
    f.instances.push_back(
        {quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, vertex_color, material), glm::mat4(1.0f)});
    return render(f).at(32, 32);
  };
  Material diffuse_only;
  diffuse_only.diffuse = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  EXPECT_NEAR(centre_with(diffuse_only, glm::vec4(1)).r, 128, 3);

  Material shiny = diffuse_only;
  shiny.specular = glm::vec4(0.25f, 0.25f, 0.25f, 1.0f);
  shiny.shininess = 50.0f;
  EXPECT_NEAR(centre_with(shiny, glm::vec4(1)).r, 191, 3);  // 0.5 + 0.25

  Material glowing = diffuse_only;
  glowing.emission = glm::vec4(0.25f, 0.0f, 0.0f, 1.0f);
  EXPECT_NEAR(centre_with(glowing, glm::vec4(1)).r, 191, 3);

  Material tracked = diffuse_only;  // GL_COLOR_MATERIAL, GL_AMBIENT_AND_DIFFUSE
  tracked.color_source = ColorSource::kAmbientAndDiffuse;
  Rgba red = centre_with(tracked, glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(red.r, 255, 3) << red;
  EXPECT_LT(red.g, 5) << red;
}

TEST_F(RenderTest, EvictsBlasUnusedForManyFrames) {
  TraceScene first = base_frame();
  first.instances.push_back({quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}), glm::mat4(1.0f)});
  EXPECT_EQ(render(first).stats.blas_builds, 1u);
  TraceScene other = base_frame();
  other.width = other.height = 8;  // keep the filler frames cheap
  other.viewport = {0, 0, 8, 8};
  other.instances.push_back({quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}), glm::mat4(1.0f)});
  for (int i = 0; i < 70; ++i) {
    std::vector<uint8_t> rgba;
    FrameStats stats;
    ASSERT_TRUE(renderer_->render(other, rgba, stats, nullptr));
  }
  EXPECT_EQ(render(first).stats.blas_builds, 1u);  // rebuilt: it had been evicted
}

// Renderers with other settings (cheap to create: lavapipe compiles pipelines in ~50 ms).
std::unique_ptr<PathTracer> make_renderer(RenderSettings settings) {
  settings.validation = RenderSettings::from_environment().validation;
  std::string error;
  std::unique_ptr<PathTracer> renderer = PathTracer::create(settings, &error);
  EXPECT_NE(renderer, nullptr) << error;
  return renderer;
}

Image render_with(PathTracer& renderer, const TraceScene& frame) {
  Image image;
  std::string error;
  EXPECT_TRUE(renderer.render(frame, image.rgba, image.stats, &error)) << error;
  return image;
}

TEST_F(RenderTest, StopsAtMaxAccumulatedAndCanDisableAccumulation) {
  TraceScene frame = base_frame();
  frame.instances.push_back({quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}), glm::mat4(1.0f)});
  RenderSettings capped;
  capped.samples_per_pixel = 2;
  capped.max_accumulated = 3;
  auto renderer = make_renderer(capped);
  ASSERT_NE(renderer, nullptr);
  EXPECT_EQ(render_with(*renderer, frame).stats.accumulated_samples, 2u);
  Image second = render_with(*renderer, frame);
  EXPECT_EQ(second.stats.accumulated_samples, 3u);
  Image third = render_with(*renderer, frame);
  EXPECT_EQ(third.stats.accumulated_samples, 3u);
  EXPECT_EQ(third.stats.rays, 0u);  // nothing left to trace
  EXPECT_EQ(third.rgba, second.rgba);

  RenderSettings single;
  single.accumulate = false;
  renderer = make_renderer(single);
  ASSERT_NE(renderer, nullptr);
  EXPECT_EQ(render_with(*renderer, frame).stats.accumulated_samples, 1u);
  EXPECT_EQ(render_with(*renderer, frame).stats.accumulated_samples, 1u);
}

TEST_F(RenderTest, DiffuseBounceLightsSurfacesTheLightMisses) {
  // A white floor lit from straight above and a wall standing on it, edge-on to the light: the
  // wall only gets light bounced off the floor.
  TraceScene frame = base_frame();
  frame.global_ambient = glm::vec4(0.0f);
  Material white;
  white.ambient = glm::vec4(0.0f);
  white.diffuse = glm::vec4(1.0f);
  frame.instances.push_back(
      {quad({-4, -1, -2}, {8, 0, 0}, {0, 0, -8}, glm::vec4(1), white), glm::mat4(1.0f)});
  frame.instances.push_back(
      {quad({-4, -1, -6}, {8, 0, 0}, {0, 3, 0}, glm::vec4(1), white), glm::mat4(1.0f)});
  frame.lights.push_back(directional_light({0, 1, 0}));
  RenderSettings direct_only;
  direct_only.bounces = 0;
  direct_only.samples_per_pixel = 8;
  RenderSettings one_bounce = direct_only;
  one_bounce.bounces = 1;
  auto direct_renderer = make_renderer(direct_only);
  auto bounce_renderer = make_renderer(one_bounce);
  ASSERT_TRUE(direct_renderer && bounce_renderer);
  const glm::ivec2 wall = project(frame, {0, -0.5f, -6});
  const Rgba without = render_with(*direct_renderer, frame).at(wall.x, wall.y);
  const Rgba with = render_with(*bounce_renderer, frame).at(wall.x, wall.y);
  EXPECT_LT(without.r, 5) << without;
  EXPECT_GT(with.r, 40) << with;
}

TEST(RenderDeviceSelection, UnknownDeviceNameGivesAClearError) {
  ::setenv("GLPT_VK_DEVICE", "no-such-device-xyz", 1);
  std::string error;
  std::unique_ptr<PathTracer> renderer = PathTracer::create(RenderSettings{}, &error);
  ::unsetenv("GLPT_VK_DEVICE");
  EXPECT_EQ(renderer, nullptr);
  EXPECT_NE(error.find("GLPT_VK_DEVICE"), std::string::npos) << error;
}

}  // namespace
}  // namespace glpt::rt
