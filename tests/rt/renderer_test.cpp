// Path-traced renders of small hand-built frame records through the public API (Renderer in
// path-traced mode: G-buffer pass, trace pass, raster overlays), checking behaviour that breaks
// visibly when a part (classification, G-buffer, shading, shadow rays, accumulation, caching) is
// wrong. Expected values come from GL's lighting equations by hand.
#include "rt_core/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>
#include <string>
#include <tuple>

#include "record_builder.hpp"
#include "rt_core/scene/scene_builder.hpp"

namespace glpt::rt {
namespace {

using test::RecordBuilder;

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
  Rgba at(int x, int y) const {
    const uint8_t* p = &rgba[(size_t(y) * kSize + size_t(x)) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
};

// A 3-D camera: perspective, depth test on, clear colour (0.2, 0.4, 0.6, 0).
RecordBuilder base_frame() {
  RecordBuilder b(kSize, kSize);
  b.transform.projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  b.raster.ops.depth_test = true;
  b.clear(glm::vec4(0.2f, 0.4f, 0.6f, 0.0f));
  return b;
}

// Pixel (x, y) where eye-space point p lands with base_frame()'s projection.
glm::ivec2 project(const RecordBuilder& b, glm::vec3 p) {
  glm::vec4 clip = b.transform.projection * glm::vec4(p, 1.0f);
  glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return glm::ivec2((ndc * 0.5f + 0.5f) * float(kSize));
}

std::unique_ptr<Renderer> make_renderer(RenderSettings settings, std::string* error) {
  settings.mode = RenderMode::kPathTraced;
  // GLPT_VALIDATION=1 in the environment runs these tests under the validation layer.
  settings.validation = RenderSettings::from_environment().validation;
  // These tests check what the tracer computes per pixel; the denoiser has its own
  // (tests/denoiser).
  settings.denoise.denoiser = Denoiser::kOff;
  return Renderer::create(settings, error);
}

// Each render draws into a new drawable (its record clears what it needs).
Image render_with(Renderer& renderer, const RecordBuilder& b) {
  Image image;
  std::string error;
  const std::shared_ptr<DrawableBuffers> buffers = create_drawable_buffers();
  EXPECT_TRUE(renderer.execute(b.record, *buffers, b.drawable, image.stats, &error)) << error;
  EXPECT_TRUE(renderer.read_color(*buffers, GL_FRONT, 0, 0, kSize, kSize, image.rgba, &error))
      << error;
  return image;
}

class RenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    RenderSettings settings;
    settings.samples_per_pixel = 1;
    settings.bounces = 1;
    settings.accumulate = true;
    renderer_ = make_renderer(settings, &error_);
  }
  static void TearDownTestSuite() { renderer_.reset(); }

  void SetUp() override {
    // No ray-query device is a failure, not a skip: the message says what to install.
    ASSERT_NE(renderer_, nullptr) << error_;
    ASSERT_EQ(renderer_->mode(), RenderMode::kPathTraced) << "no ray queries: " << error_;
  }

  static Image render(const RecordBuilder& b) { return render_with(*renderer_, b); }

  static std::unique_ptr<Renderer> renderer_;
  static std::string error_;
};

std::unique_ptr<Renderer> RenderTest::renderer_;
std::string RenderTest::error_;

TEST_F(RenderTest, UncoveredPixelsKeepTheClearColourAndCoveredOnesAreTraced) {
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 0, 1});
  b.quad({-0.5f, -0.5f, -5.0f}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  Image image = render(b);
  const Rgba expected{51, 102, 153, 0};  // 0.2, 0.4, 0.6, 0.0 as GL rounds them
  for (auto [x, y] : {std::pair{0, 0}, {63, 63}, {5, 60}}) {
    Rgba c = image.at(x, y);
    EXPECT_EQ(c.r, expected.r) << c;
    EXPECT_EQ(c.g, expected.g) << c;
    EXPECT_EQ(c.b, expected.b) << c;
    EXPECT_EQ(c.a, expected.a) << c;
  }
  EXPECT_EQ(image.at(32, 32).a, 255);  // GL's alpha: the material's diffuse alpha
  EXPECT_GT(image.stats.rays, 0u);
  EXPECT_EQ(image.stats.triangles, 2u);
}

TEST_F(RenderTest, UnlitSurfacesAreExactlyWhatRasterModeDraws) {
  RecordBuilder b = base_frame();
  b.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(0.25f, 0.75f, 0.3f, 1.0f));
  b.quad({-3, -2, -6}, {2.5f, 0, 0}, {0, 4, 0}, glm::vec4(0.1f, 0.2f, 0.9f, 0.5f));
  b.directional_light(1, {1, 1, 1});  // lit draws follow; the unlit ones must not care
  b.lighting.enabled = false;
  b.quad({1, -1, -5}, {1, 0, 0}, {0, 1, 0}, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  Image traced = render(b);
  RenderSettings raster_settings;
  raster_settings.mode = RenderMode::kRaster;
  std::string error;
  auto raster = Renderer::create(raster_settings, &error);
  ASSERT_NE(raster, nullptr) << error;
  Image rasterized = render_with(*raster, b);
  EXPECT_EQ(traced.rgba, rasterized.rgba);
  EXPECT_EQ(traced.at(32, 32).r, 64);  // 0.25 -> 63.75
}

TEST_F(RenderTest, QuadFacingTheLightIsBrighterThanQuadFacingAway) {
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 0, 1});
  // Same geometry side by side, both seen from the front; the right one's normals point away.
  b.quad({-2.2f, -1, -5}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  b.quad({0.2f, -1, -5}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1), glm::vec3(0, 0, -1));
  Image image = render(b);
  const glm::ivec2 facing = project(b, {-1.2f, 0, -5}), away = project(b, {1.2f, 0, -5});
  const Rgba lit = image.at(facing.x, facing.y), unlit = image.at(away.x, away.y);
  EXPECT_GT(lit.luminance(), unlit.luminance() + 300) << lit << " vs " << unlit;
  // GL: 0.8 diffuse * 1.0 light + 0.2 * 0.2 ambient = 0.84 -> 214 (plus a little bounce light).
  EXPECT_NEAR(lit.r, 214, 12) << lit;
}

TEST_F(RenderTest, OccluderShadowsThePlaneBehindIt) {
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 1, 0});
  // A floor at y = -1 lit from straight above, and a small horizontal quad hovering over it.
  b.quad({-4, -1, -2}, {8, 0, 0}, {0, 0, -8}, glm::vec4(1));
  b.quad({-0.5f, -0.5f, -4.5f}, {1, 0, 0}, {0, 0, -1}, glm::vec4(1));
  Image image = render(b);
  const glm::ivec2 shadowed = project(b, {0, -1, -5}), open = project(b, {2, -1, -5});
  const Rgba in_shadow = image.at(shadowed.x, shadowed.y), in_light = image.at(open.x, open.y);
  EXPECT_LT(in_shadow.luminance() * 2, in_light.luminance()) << in_shadow << " vs " << in_light;
}

TEST_F(RenderTest, PassesOfAFrameFollowEachOtherWithoutTheHostWaiting) {
  // The G-buffer pass, the BLAS and TLAS builds, the trace and the raster pass after it are
  // submitted back to back, each one's host work overlapping the device work before it: the
  // host waits for the device once per frame, at its end (it waited after every pass before:
  // four times a frame with new geometry). Frames into one drawable, each with a new occluder
  // (a BLAS and a TLAS build every frame); the first also creates the drawable's buffers.
  const std::shared_ptr<DrawableBuffers> buffers = create_drawable_buffers();
  std::string error;
  for (int frame = 0; frame < 4; ++frame) {
    RecordBuilder b = base_frame();
    b.directional_light(0, {0, 1, 0});
    b.quad({-4, -1, -2}, {8, 0, 0}, {0, 0, -8}, glm::vec4(1));
    b.quad({-0.45f + 0.1f * float(frame), -0.5f, -4.5f}, {1, 0, 0}, {0, 0, -1}, glm::vec4(1));
    FrameStats stats;
    // As the shim asks: with room for occlusion query results (none counted here).
    std::vector<QuerySamples> queries;
    ASSERT_TRUE(
        renderer_->execute(b.record, *buffers, b.drawable, stats, &error, nullptr, &queries))
        << error;
    EXPECT_GE(stats.blas_builds, 1u) << "frame " << frame;
    EXPECT_GT(stats.rays, 0u) << "frame " << frame << ": counted once the frame completed";
    EXPECT_GT(stats.trace_ms, 0.0) << "frame " << frame << ": the trace's device time";
    if (frame > 0) {
      EXPECT_EQ(stats.host_waits, 1u) << "frame " << frame;
    }
  }
  // The frames' results are complete when execute returns: read them without further ado.
  std::vector<uint8_t> rgba;
  ASSERT_TRUE(renderer_->read_color(*buffers, GL_FRONT, 0, 0, kSize, kSize, rgba, &error)) << error;
  const std::vector<uint8_t> clear = {51, 102, 153, 0};
  const auto top_left = rgba.begin() + std::ptrdiff_t{(kSize - 1) * kSize * 4};
  EXPECT_TRUE(std::equal(clear.begin(), clear.end(), top_left)) << "the sky keeps the clear colour";
  const int floor = rgba[(4 * kSize + kSize / 2) * 4];  // near the bottom, middle: lit floor
  EXPECT_GT(floor, 100);
}

TEST_F(RenderTest, DefaultLightOnlyWhenAskedFor) {
  RecordBuilder b = base_frame();
  b.lighting.enabled = true;  // and no light enabled
  b.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  // GL lights it by ambient alone: 0.2 * 0.2 = 0.04 (10).
  EXPECT_NEAR(render(b).at(32, 32).r, 10, 1) << render(b).at(32, 32);
  // GLPT_DEFAULT_LIGHT=1 adds a white directional light: 0.8 * N.L more.
  RenderSettings settings;
  settings.default_light = true;
  std::string error;
  auto renderer = make_renderer(settings, &error);
  ASSERT_NE(renderer, nullptr) << error;
  EXPECT_GT(render_with(*renderer, b).at(32, 32).r, 60);
}

TEST_F(RenderTest, PositionalLightIsAttenuatedWithDistance) {
  auto render_with_attenuation = [&](float quadratic) {
    RecordBuilder b = base_frame();
    b.lighting.enabled = true;
    b.lighting.light_mask = 1;
    b.lighting.model_ambient = glm::vec4(0.0f);
    b.lighting.material[0].ambient = glm::vec4(0.0f);
    b.lighting.lights[0].position = glm::vec4(0, 0, -2, 1);  // 2 units in front of the quad
    b.lighting.lights[0].quadratic_attenuation = quadratic;
    b.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
    return render(b).at(32, 32);
  };
  const Rgba bright = render_with_attenuation(0.0f), dim = render_with_attenuation(0.25f);
  EXPECT_NEAR(bright.r, 204, 6) << bright;  // 0.8 * N.L = 1
  EXPECT_NEAR(dim.r, 102, 6) << dim;        // / (1 + 0.25 * 2^2)
}

TEST_F(RenderTest, OrthographicProjection) {
  RecordBuilder b = base_frame();
  b.transform.projection = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 10.0f);
  b.directional_light(0, {0, 0, 1});
  b.lighting.model_ambient = glm::vec4(0.0f);
  b.lighting.material[0].ambient = glm::vec4(0.0f);
  // Covers x in [-2, 0]: the left half of the image.
  b.quad({-2, -2, -5}, {2, 0, 0}, {0, 4, 0}, glm::vec4(1));
  Image image = render(b);
  EXPECT_NEAR(image.at(16, 32).r, 204, 3) << image.at(16, 32);
  EXPECT_EQ(image.at(48, 32).g, 102);  // clear colour
}

TEST_F(RenderTest, AccumulatesUnchangedFramesAndRestartsOnChange) {
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 0, 1});
  b.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  EXPECT_EQ(render(b).stats.accumulated_samples, 1u);
  EXPECT_EQ(render(b).stats.accumulated_samples, 2u);
  EXPECT_EQ(render(b).stats.accumulated_samples, 3u);

  auto redraw = [&](auto change) {
    b = base_frame();
    change(b);
    b.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  };
  redraw([](RecordBuilder& f) {
    f.directional_light(0, {0, 0, 1});
    f.transform.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0, 0));
  });
  EXPECT_EQ(render(b).stats.accumulated_samples, 1u);
  EXPECT_EQ(render(b).stats.accumulated_samples, 2u);
  redraw([](RecordBuilder& f) { f.directional_light(0, {0, 0, 1}, glm::vec4(0.5f)); });
  EXPECT_EQ(render(b).stats.accumulated_samples, 1u);
  // A record that traces nothing (the rest of a frame after glReadPixels) keeps the
  // accumulation.
  RecordBuilder nothing(kSize, kSize);
  render(nothing);
  EXPECT_EQ(render(b).stats.accumulated_samples, 2u);
}

TEST_F(RenderTest, ReusesBlasOfUnchangedGeometryAndOfRecolouredGeometry) {
  auto frame = [](glm::vec4 color, float x) {
    RecordBuilder b = base_frame();
    b.directional_light(0, {0, 0, 1});
    b.transform.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0, 0));
    b.quad({-1, -1, -4.25f}, {2, 0, 0}, {0, 2, 0}, color);
    return b;
  };
  Image first = render(frame(glm::vec4(1), 0.0f));
  EXPECT_EQ(first.stats.blas_builds, 1u);
  EXPECT_EQ(first.stats.triangles, 2u);
  Image moved = render(frame(glm::vec4(1), 0.1f));
  EXPECT_EQ(moved.stats.blas_builds, 0u);
  EXPECT_GT(moved.stats.blas_reused, 0u);
  // GL_COLOR_MATERIAL is off: the colour is an attribute only, the shape is the same.
  RecordBuilder recoloured = frame(glm::vec4(1, 0, 0, 1), 0.1f);
  recoloured.lighting.color_material = true;
  recoloured.record.clear();
  recoloured.clear(glm::vec4(0.2f, 0.4f, 0.6f, 0.0f));
  recoloured.quad({-1, -1, -4.25f}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1, 0, 0, 1));
  Image red = render(recoloured);
  EXPECT_EQ(red.stats.blas_builds, 0u);  // recolouring never rebuilds a BLAS
  EXPECT_GT(red.at(32, 32).r, 150) << red.at(32, 32);
  EXPECT_LT(red.at(32, 32).g, 20) << red.at(32, 32);
}

TEST_F(RenderTest, LightsAreThoseOfEachPixelsOwnDraw) {
  RecordBuilder b = base_frame();
  b.lighting.model_ambient = glm::vec4(0.0f);
  b.lighting.material[0].ambient = glm::vec4(0.0f);
  b.lighting.enabled = true;
  // Left quad: GL_LIGHT0 (red) only. Right quad: GL_LIGHT1 (green) only.
  b.lighting.lights[0].position = glm::vec4(0, 0, 1, 0);
  b.lighting.lights[0].diffuse = glm::vec4(1, 0, 0, 1);
  b.lighting.lights[1].position = glm::vec4(0, 0, 1, 0);
  b.lighting.lights[1].diffuse = glm::vec4(0, 1, 0, 1);
  b.lighting.light_mask = 1;
  b.quad({-2.2f, -1, -5}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  b.lighting.light_mask = 2;
  b.quad({0.2f, -1, -5}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  Image image = render(b);
  const glm::ivec2 left = project(b, {-1.2f, 0, -5}), right = project(b, {1.2f, 0, -5});
  const Rgba l = image.at(left.x, left.y), r = image.at(right.x, right.y);
  EXPECT_NEAR(l.r, 204, 4) << l;  // 0.8 * red
  EXPECT_LT(l.g, 10) << l;
  EXPECT_NEAR(r.g, 204, 4) << r;  // 0.8 * green
  EXPECT_LT(r.r, 10) << r;
}

TEST_F(RenderTest, ColourBleedsFromTheSurfaceEachBounceHits) {
  // A grey floor lit from above between a glowing red wall (left) and a glowing green wall
  // (right), among scrambled small tiles: each bounce must read the shading data of the instance
  // it hit (the TLAS orders instances spatially, the instance table keeps draw order).
  RenderSettings settings;
  settings.samples_per_pixel = 16;
  std::string error;
  auto renderer = make_renderer(settings, &error);
  ASSERT_NE(renderer, nullptr) << error;
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 1, 0});
  b.lighting.model_ambient = glm::vec4(0.0f);
  b.lighting.material[0].ambient = glm::vec4(0.0f);
  b.lighting.color_material = true;
  b.lighting.color_material_mode = GL_EMISSION;
  for (int k = 0; k < 8; ++k) {  // distant tiles, drawn in a scrambled order
    const int i = (k * 5) % 8;
    b.transform.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(i - 4.0f, 3.0f, -20.0f));
    b.quad({0, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, glm::vec4(i / 8.0f, 0.2f, 0.7f, 1.0f));
  }
  b.transform.modelview = glm::mat4(1.0f);
  b.quad({-1, -1, -3}, {0, 0, -3}, {0, 2, 0}, glm::vec4(1, 0, 0, 1));  // red, x = -1
  b.quad({1, -1, -6}, {0, 0, 3}, {0, 2, 0}, glm::vec4(0, 1, 0, 1));    // green, x = 1
  b.lighting.color_material = false;
  b.lighting.material[0].diffuse = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 0, -3}, glm::vec4(1));  // floor
  Image image = render_with(*renderer, b);
  const glm::ivec2 near_red = project(b, {-0.8f, -1, -4.5f});
  const glm::ivec2 near_green = project(b, {0.8f, -1, -4.5f});
  const Rgba by_red = image.at(near_red.x, near_red.y);
  const Rgba by_green = image.at(near_green.x, near_green.y);
  EXPECT_GT(by_red.r, by_red.g + 15) << by_red;
  EXPECT_GT(by_green.g, by_green.r + 15) << by_green;
  EXPECT_NEAR(by_red.b, 128, 8) << by_red;  // the floor's own 0.5 * 1: nothing blue bounces
}

TEST_F(RenderTest, EmptyAndDegenerateRecords) {
  RecordBuilder b = base_frame();
  Image empty = render(b);  // no draws: the clear colour
  EXPECT_EQ(empty.at(32, 32).b, 153);
  EXPECT_EQ(empty.stats.triangles, 0u);

  b.directional_light(0, {0, 0, 1});
  auto no_vertices = std::make_shared<rec::VertexData>();
  no_vertices->mode = GL_TRIANGLES;
  b.draw(no_vertices);
  b.draw(GL_TRIANGLES, {{-1, -1, -4}, {1, -1, -4}, {std::nanf(""), 1, -4}}, {0, 0, 1},
         glm::vec4(1));
  b.draw(GL_TRIANGLES, {{-1, -1, -4}, {1, -1, -4}, {0, 1, -4}}, {0, 0, 0}, glm::vec4(1));
  Image degenerate = render(b);
  EXPECT_EQ(degenerate.stats.triangles, 1u);
  EXPECT_GT(degenerate.at(32, 28).r, degenerate.at(2, 2).r) << degenerate.at(32, 28);

  RecordBuilder singular = base_frame();
  singular.transform.projection = glm::mat4(0.0f);  // draws nothing
  singular.directional_light(0, {0, 0, 1});
  singular.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  EXPECT_EQ(render(singular).at(32, 32).b, 153);
  singular.transform.viewport = {0, 0, 0, 0};
  singular.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  EXPECT_EQ(render(singular).at(32, 32).b, 153);

  RecordBuilder nothing(0, 0);
  FrameStats stats;
  std::string error;
  EXPECT_TRUE(renderer_->execute(nothing.record, *create_drawable_buffers(), nothing.drawable,
                                 stats, &error))
      << error;
}

TEST_F(RenderTest, SpotLightLightsOnlyInsideItsCone) {
  RecordBuilder b = base_frame();
  b.lighting.enabled = true;
  b.lighting.light_mask = 1;
  b.lighting.model_ambient = glm::vec4(0.0f);
  b.lighting.material[0].ambient = glm::vec4(0.0f);
  b.lighting.lights[0].position = glm::vec4(0, 0, -2, 1);
  b.lighting.lights[0].spot_direction = glm::vec3(0, 0, -1);
  b.lighting.lights[0].spot_cutoff = 10.0f;
  b.quad({-2, -2, -4}, {4, 0, 0}, {0, 4, 0}, glm::vec4(1));
  Image image = render(b);
  const glm::ivec2 inside = project(b, {0, 0, -4}), outside = project(b, {1, 0, -4});
  EXPECT_NEAR(image.at(inside.x, inside.y).r, 204, 6) << image.at(inside.x, inside.y);
  EXPECT_LT(image.at(outside.x, outside.y).r, 20) << image.at(outside.x, outside.y);
}

TEST_F(RenderTest, MaterialTermsFollowGl) {
  auto centre_with = [&](const rec::Material& material, bool color_material,
                         glm::vec4 vertex_color) {
    RecordBuilder b = base_frame();
    b.directional_light(0, {0, 0, 1});  // head-on: N.L = N.H = 1 at the centre
    b.lighting.model_ambient = glm::vec4(0.0f);
    b.lighting.material[0] = material;
    b.lighting.color_material = color_material;
    b.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, vertex_color);
    return render(b).at(32, 32);
  };
  rec::Material diffuse_only;
  diffuse_only.diffuse = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  EXPECT_NEAR(centre_with(diffuse_only, false, glm::vec4(1)).r, 128, 3);

  // The specular lobe's peak is GL's (0.25), its reflectance 0.25 * 8 / 52 = 0.038 is taken from
  // the diffuse lobe's (energy conservation, docs/light-transport.md): 0.5 * 0.962 + 0.25.
  rec::Material shiny = diffuse_only;
  shiny.specular = glm::vec4(0.25f, 0.25f, 0.25f, 1.0f);
  shiny.shininess = 50.0f;
  EXPECT_NEAR(centre_with(shiny, false, glm::vec4(1)).r, 186, 3);

  rec::Material glowing = diffuse_only;
  glowing.emission = glm::vec4(0.25f, 0.0f, 0.0f, 1.0f);
  EXPECT_NEAR(centre_with(glowing, false, glm::vec4(1)).r, 191, 3);

  // GL_COLOR_MATERIAL, GL_AMBIENT_AND_DIFFUSE: the vertex colour is the diffuse colour.
  Rgba red = centre_with(diffuse_only, true, glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(red.r, 255, 3) << red;
  EXPECT_LT(red.g, 5) << red;
}

TEST_F(RenderTest, EvictsBlasUnusedForManyFrames) {
  RecordBuilder first = base_frame();
  first.quad({-1, -1, -4.5f}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  EXPECT_EQ(render(first).stats.blas_builds, 1u);
  RecordBuilder other(8, 8);  // keep the filler frames cheap
  other.transform.projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  other.quad({-1, -1, -4.75f}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  const std::shared_ptr<DrawableBuffers> buffers = create_drawable_buffers();
  for (int i = 0; i < 70; ++i) {
    FrameStats stats;
    ASSERT_TRUE(renderer_->execute(other.record, *buffers, other.drawable, stats, nullptr));
  }
  EXPECT_EQ(render(first).stats.blas_builds, 1u);  // rebuilt: it had been evicted
}

TEST_F(RenderTest, StopsAtMaxAccumulatedAndCanDisableAccumulation) {
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 0, 1});
  b.quad({-1, -1, -4}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  RenderSettings capped;
  capped.samples_per_pixel = 2;
  capped.max_accumulated = 3;
  std::string error;
  auto renderer = make_renderer(capped, &error);
  ASSERT_NE(renderer, nullptr) << error;
  EXPECT_EQ(render_with(*renderer, b).stats.accumulated_samples, 2u);
  Image second = render_with(*renderer, b);
  EXPECT_EQ(second.stats.accumulated_samples, 3u);
  Image third = render_with(*renderer, b);
  EXPECT_EQ(third.stats.accumulated_samples, 3u);
  EXPECT_EQ(third.stats.rays, 0u);  // nothing left to trace
  EXPECT_EQ(third.rgba, second.rgba);

  RenderSettings single;
  single.accumulate = false;
  renderer = make_renderer(single, &error);
  ASSERT_NE(renderer, nullptr) << error;
  EXPECT_EQ(render_with(*renderer, b).stats.accumulated_samples, 1u);
  EXPECT_EQ(render_with(*renderer, b).stats.accumulated_samples, 1u);
}

// An unlit white quad whose left edge is at x = 20.7 under a pixel-exact orthographic camera:
// pixel column 20 is 30 % covered. Depth-tested: a 3-D scene in parallel projection (unlit and
// without the depth test it would be a 2-D overlay, which is not traced).
RecordBuilder partly_covered_pixel() {
  RecordBuilder b(kSize, kSize);
  b.transform.projection = glm::ortho(0.0f, float(kSize), 0.0f, float(kSize), -1.0f, 1.0f);
  b.raster.ops.depth_test = true;
  b.clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  b.quad({20.7f, 10, 0}, {20, 0, 0}, {0, 20, 0}, glm::vec4(1.0f));
  return b;
}

TEST_F(RenderTest, JitterCoversThePixelAtAnySampleCount) {
  // With 4 samples per frame the sub-pixel offsets are indexed by the G-buffers accumulated, so
  // 32 frames cover the pixel evenly and the edge pixel converges to 30 % of the quad's colour
  // (indexed by the sample count, the offsets stayed in a quarter of the pixel: 0 here).
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  std::string error;
  auto renderer = make_renderer(settings, &error);
  ASSERT_NE(renderer, nullptr) << error;
  const RecordBuilder b = partly_covered_pixel();
  Image image;
  for (int frame = 0; frame < 32; ++frame) image = render_with(*renderer, b);
  EXPECT_EQ(image.stats.accumulated_samples, 128u);
  EXPECT_NEAR(image.at(20, 20).r, 0.3 * 255, 10) << image.at(20, 20);
  EXPECT_EQ(image.at(21, 20).r, 255);
}

TEST_F(RenderTest, ReferenceRendersItsSamplesEveryFrameFromScratch) {
  RenderSettings settings;
  settings.reference_samples = 32;
  std::string error;
  auto renderer = make_renderer(settings, &error);
  ASSERT_NE(renderer, nullptr) << error;
  const RecordBuilder b = partly_covered_pixel();
  for (int frame = 0; frame < 2; ++frame) {
    const Image image = render_with(*renderer, b);
    EXPECT_EQ(image.stats.accumulated_samples, 32u) << "frame " << frame;
    // 32 jittered G-buffer passes within the one frame: the edge pixel is anti-aliased already.
    EXPECT_NEAR(image.at(20, 20).r, 0.3 * 255, 12) << image.at(20, 20);
  }
}

TEST_F(RenderTest, AccumulationAntiAliasesEdgesAndKeepsInteriorsExact) {
  // An unlit quad whose left edge crosses pixel column 20 at its middle: every frame's G-buffer
  // is jittered by a sub-pixel offset, so the edge pixel converges to a mix of quad and
  // background while interior pixels stay exactly the quad's colour. Depth-tested: 3-D in
  // parallel projection, not a 2-D overlay.
  RecordBuilder b(kSize, kSize);
  b.transform.projection = glm::ortho(0.0f, float(kSize), 0.0f, float(kSize), -1.0f, 1.0f);
  b.raster.ops.depth_test = true;
  b.clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  b.quad({20.5f, 10, 0}, {20, 0, 0}, {0, 20, 0}, glm::vec4(1.0f));
  Image image;
  for (int frame = 0; frame < 16; ++frame) image = render(b);
  EXPECT_EQ(image.stats.accumulated_samples, 16u);
  EXPECT_EQ(image.at(30, 20).r, 255);
  EXPECT_EQ(image.at(19, 20).r, 0);
  EXPECT_GT(image.at(20, 20).r, 64) << image.at(20, 20);
  EXPECT_LT(image.at(20, 20).r, 192) << image.at(20, 20);
}

TEST_F(RenderTest, DiffuseBounceLightsSurfacesTheLightMisses) {
  // A white floor lit from straight above and a wall standing on it, edge-on to the light: the
  // wall only gets light bounced off the floor.
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 1, 0});
  b.lighting.model_ambient = glm::vec4(0.0f);
  b.lighting.material[0].ambient = glm::vec4(0.0f);
  b.lighting.material[0].diffuse = glm::vec4(1.0f);
  b.quad({-4, -1, -2}, {8, 0, 0}, {0, 0, -8}, glm::vec4(1));
  b.quad({-4, -1, -6}, {8, 0, 0}, {0, 3, 0}, glm::vec4(1));
  RenderSettings direct_only;
  direct_only.bounces = 0;
  direct_only.samples_per_pixel = 8;
  RenderSettings one_bounce = direct_only;
  one_bounce.bounces = 1;
  std::string error;
  auto direct_renderer = make_renderer(direct_only, &error);
  auto bounce_renderer = make_renderer(one_bounce, &error);
  ASSERT_TRUE(direct_renderer && bounce_renderer) << error;
  const glm::ivec2 wall = project(b, {0, -0.5f, -6});
  const Rgba without = render_with(*direct_renderer, b).at(wall.x, wall.y);
  const Rgba with = render_with(*bounce_renderer, b).at(wall.x, wall.y);
  EXPECT_LT(without.r, 5) << without;
  EXPECT_GT(with.r, 40) << with;
}

TEST_F(RenderTest, CoarseSmoothSphereShowsNoShadowTerminatorSteps) {
  // An 8 x 6 UV sphere with smooth normals, lit so that the terminator falls inside the facets
  // between 90 and 135 degrees of longitude, whose flat normal (at 112.5) already faces away from
  // the light (at 17.5: 95 degrees). GL lights that facet's near half smoothly (its vertex
  // normals face the light); without the terminator fix its shadow rays leave through its own
  // plane and it is black but for ambient.
  RecordBuilder b = base_frame();
  b.transform.projection = glm::ortho(-1.1f, 1.1f, -1.1f, 1.1f, 0.1f, 10.0f);
  const float light_longitude = glm::radians(17.5f);
  const glm::vec3 to_light(std::cos(light_longitude), 0.0f, std::sin(light_longitude));
  b.directional_light(0, to_light);
  b.transform.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -3));
  auto v = std::make_shared<rec::VertexData>();
  v->mode = GL_TRIANGLES;
  const int slices = 8, stacks = 6;
  auto point = [&](int i, int j) {
    const float theta = float(j) / stacks * 3.14159265f, phi = float(i) / slices * 6.2831853f;
    return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                     std::sin(theta) * std::sin(phi));
  };
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i)
      for (glm::vec3 p : {point(i, j), point(i + 1, j + 1), point(i + 1, j), point(i, j),
                          point(i, j + 1), point(i + 1, j + 1)}) {
        v->position.push_back(glm::vec4(p, 1.0f));
        v->normal.push_back(p);
      }
  v->color = {glm::vec4(1)};
  v->primitives.push_back({0, static_cast<uint32_t>(v->position.size())});
  b.draw(v);
  Image image = render(b);
  // Pixels of the row just above the equator whose smooth normal has N.L in [0.1, 0.3].
  int checked = 0, dark = 0;
  const int y = 32;
  for (int x = 0; x < int(kSize); ++x) {
    const float px = (x + 0.5f) / kSize * 2.2f - 1.1f, py = (y + 0.5f) / kSize * 2.2f - 1.1f;
    const float r2 = px * px + py * py;
    if (r2 >= 0.95f) continue;
    const glm::vec3 normal(px, py, std::sqrt(1.0f - r2));
    const float n_dot_l = glm::dot(normal, to_light);
    if (n_dot_l < 0.1f || n_dot_l > 0.3f) continue;
    ++checked;
    // GL: 0.8 * N.L + 0.04 >= 0.12 -> 31; a shadowed facet shows the ambient 0.04 (10).
    if (image.at(x, y).r < 20) ++dark;
  }
  EXPECT_GE(checked, 3);
  EXPECT_EQ(dark, 0) << "of " << checked;
}

TEST(ClassifyDraws, TracesOpaqueFilledTrianglesUnderTheMainCameraOnly) {
  RecordBuilder b(16, 16);
  b.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 10.0f);
  b.clear(glm::vec4(0));
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));  // 0 -> traced
  b.raster.ops.blend = true;  // GL's default factors (GL_ONE, GL_ZERO) would not mix
  b.raster.ops.blend_src_rgb = b.raster.ops.blend_src_alpha = GL_SRC_ALPHA;
  b.raster.ops.blend_dst_rgb = b.raster.ops.blend_dst_alpha = GL_ONE_MINUS_SRC_ALPHA;
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1, 1, 1, 0.5f));  // blended (alpha 0.5)
  b.raster.ops.blend = false;
  b.draw(GL_LINES, {{0, 0, -3}, {1, 1, -3}}, {0, 0, 1}, glm::vec4(1));  // lines
  b.raster.primitive.polygon_mode_back = GL_LINE;
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));  // unfilled
  b.raster.primitive.polygon_mode_back = GL_FILL;
  b.raster.ops.color_write[3] = false;
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));  // masked
  b.raster.ops.color_write[3] = true;
  const glm::mat4 perspective = b.transform.projection;
  b.transform.projection = glm::ortho(0.0f, 16.0f, 0.0f, 16.0f, -1.0f, 1.0f);
  for (int i = 0; i < 4; ++i)  // more triangles than the 3-D scene, but a parallel projection
    b.quad({0, 0, 0}, {16, 0, 0}, {0, 16, 0}, glm::vec4(1));
  b.transform.projection = perspective;
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));  // traced again

  SceneBuild build;
  build_trace_scene(b.record, b.drawable, build);
  const std::vector<DrawClass> expected = {
      DrawClass::kNotTriangles,  // the clear
      DrawClass::kTraced,       DrawClass::kBlended, DrawClass::kNotTriangles, DrawClass::kUnfilled,
      DrawClass::kMaskedColor,  DrawClass::kOverlay, DrawClass::kOverlay,      DrawClass::kOverlay,
      DrawClass::kOverlay,      DrawClass::kTraced};
  EXPECT_EQ(build.classes, expected);
  EXPECT_EQ(build.gbuffer_pass, (std::vector<size_t>{0, 1, 10}));
  EXPECT_EQ(build.after_trace, (std::vector<size_t>{2, 3, 4, 5, 6, 7, 8, 9}));
}

// The six faces of the axis-aligned box [lo, hi], one quad draw each (or one draw of all six).
std::vector<glm::vec3> box_faces(glm::vec3 lo, glm::vec3 hi) {
  std::vector<glm::vec3> corners;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {lo[axis], hi[axis]}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        glm::vec3 p;
        p[axis] = side;
        p[u] = a ? hi[u] : lo[u];
        p[v] = b ? hi[v] : lo[v];
        corners.push_back(p);
      }
    }
  return corners;
}

TEST(ClassifyDraws, TheSkyAroundTheCameraIsNotTracedAndTheWorldIs) {
  RecordBuilder b(16, 16);
  b.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
  b.clear(glm::vec4(0));
  // A sky box of six faces, unlit, without depth writes, before the world: no face holds the
  // eye, all six do.
  b.lighting.enabled = false;
  b.raster.ops.depth_test = true;
  b.raster.ops.depth_write = false;
  const std::vector<glm::vec3> sky = box_faces(glm::vec3(-50.0f), glm::vec3(50.0f));
  for (size_t face = 0; face < 6; ++face)
    b.draw(GL_QUADS, {sky.begin() + 4 * face, sky.begin() + 4 * face + 4}, {0, 0, 1},
           glm::vec4(0.5f));
  b.raster.ops.depth_write = true;
  b.directional_light(0, {0, 1, 0});
  b.quad({-4, -1, -2}, {8, 0, 0}, {0, 0, -8}, glm::vec4(1));  // 7: the lit floor: traced
  b.lighting.enabled = false;
  b.transform.depth_near = b.transform.depth_far = 1.0f;  // 8: at the far plane: sky
  b.quad({-40, -40, -40}, {80, 0, 0}, {0, 80, 0}, glm::vec4(0.3f));
  b.transform.depth_near = 0.0f;
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));  // 9: unlit world: traced
  SceneBuild build;
  build_trace_scene(b.record, b.drawable, build);
  std::vector<DrawClass> expected = {DrawClass::kNotTriangles};
  expected.insert(expected.end(), 6, DrawClass::kSky);
  expected.insert(expected.end(), {DrawClass::kTraced, DrawClass::kSky, DrawClass::kTraced});
  EXPECT_EQ(build.classes, expected);
  // The sky is drawn first by raster mode, the far-plane one after the trace.
  EXPECT_EQ(build.gbuffer_pass, (std::vector<size_t>{0, 1, 2, 3, 4, 5, 6, 7, 9}));
  EXPECT_EQ(build.after_trace, (std::vector<size_t>{8}));

  // Not sky: an unlit ground drawn first without depth writes (below the eye, it does not hold
  // it), then an unlit room around the eye with depth writes (not centred on it); a box centred
  // on the eye with depth writes, drawn before them, is.
  RecordBuilder n(16, 16);
  n.transform.projection = b.transform.projection;
  n.lighting.enabled = false;
  n.raster.ops.depth_test = true;
  n.draw(GL_QUADS, box_faces(glm::vec3(-30.0f), glm::vec3(30.0f)), {0, 0, 1}, glm::vec4(0.5f));
  n.raster.ops.depth_write = false;
  n.quad({-4, -1, -1}, {8, 0, 0}, {0, 0, -8}, glm::vec4(1));
  n.raster.ops.depth_write = true;
  n.draw(GL_QUADS, box_faces({-2, -1, -9}, {6, 3, 1}), {0, 0, 1}, glm::vec4(0.5f));
  build_trace_scene(n.record, n.drawable, build);
  EXPECT_EQ(build.classes,
            (std::vector<DrawClass>{DrawClass::kSky, DrawClass::kTraced, DrawClass::kTraced}));

  // A sky box without the depth test under a projection reaching farther than the world's (the
  // same view, other near and far planes) is the sky; the same box under a wider field of view
  // is another camera's.
  for (const float fov : {1.0f, 1.3f}) {
    RecordBuilder f(16, 16);
    f.transform.projection = glm::perspective(fov, 1.0f, 1.0f, 5000.0f);
    f.lighting.enabled = false;
    f.raster.ops.depth_test = false;
    f.draw(GL_QUADS, box_faces(glm::vec3(-500.0f), glm::vec3(500.0f)), {0, 0, 1}, glm::vec4(0.5f));
    f.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
    f.raster.ops.depth_test = true;
    f.directional_light(0, {0, 1, 0});
    // The world: over 5x the sky's triangles, so its camera is the main one.
    for (int k = 0; k < 40; ++k)
      f.quad({-4.0f + 0.2f * float(k), -1, -2}, {0.2f, 0, 0}, {0, 0, -8}, glm::vec4(1));
    build_trace_scene(f.record, f.drawable, build);
    EXPECT_EQ(build.classes[0], fov == 1.0f ? DrawClass::kSky : DrawClass::kOtherCamera)
        << "field of view " << fov;
    EXPECT_EQ(build.classes[1], DrawClass::kTraced);
  }

  // Depth ranges: the world in [0, 0.999], then a small unlit dome in [0.999, 1] (behind every
  // depth the world can have) is the sky; a gun in [0, 0.1] over a world in [0.1, 1] is not, nor
  // is a draw in the world's own range.
  for (const auto& [world, other, sky] :
       {std::tuple{glm::vec2(0.0f, 0.999f), glm::vec2(0.999f, 1.0f), true},
        std::tuple{glm::vec2(0.1f, 1.0f), glm::vec2(0.0f, 0.1f), false},
        std::tuple{glm::vec2(0.0f, 0.999f), glm::vec2(0.0f, 0.999f), false}}) {
    RecordBuilder d(16, 16);
    d.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
    d.transform.depth_near = world.x;
    d.transform.depth_far = world.y;
    d.directional_light(0, {0, 1, 0});
    for (int k = 0; k < 8; ++k)
      d.quad({-4.0f + float(k), -1, -2}, {1, 0, 0}, {0, 0, -8}, glm::vec4(1));
    d.lighting.enabled = false;
    d.transform.depth_near = other.x;
    d.transform.depth_far = other.y;
    d.quad({-1, -1, -2}, {2, 0, 0}, {0, 2, 0}, glm::vec4(0.3f));
    build_trace_scene(d.record, d.drawable, build);
    EXPECT_EQ(build.classes.back() == DrawClass::kSky, sky)
        << "world " << world.x << ".." << world.y << ", draw " << other.x << ".." << other.y;
    EXPECT_EQ(build.classes.front(), DrawClass::kTraced);
  }
}

TEST_F(RenderTest, AStillSceneBuildsNothingAfterItsFirstFrameAndACameraMoveNoBlas) {
  // Docs/classification.md, "model only what a scene requires": the same frame again builds no
  // BLAS and no TLAS; the camera moving (every modelview changes) builds no BLAS, only a new or
  // updated TLAS, and the world stays static.
  RecordBuilder b = base_frame();
  b.directional_light(0, {0, 0, 1});
  for (int k = 0; k < 3; ++k)
    b.quad({-2.0f + 1.5f * k, -1, -4}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  const std::shared_ptr<DrawableBuffers> buffers = create_drawable_buffers();
  const FrameEnd end;  // each execute ends a frame
  auto frame = [&](const RecordBuilder& record) {
    FrameStats stats;
    std::string error;
    EXPECT_TRUE(renderer_->execute(record.record, *buffers, record.drawable, stats, &error, &end))
        << error;
    return stats;
  };
  const FrameStats first = frame(b);
  EXPECT_GE(first.blas_builds, 1u);
  const FrameStats again = frame(b);
  EXPECT_EQ(again.blas_builds, 0u);
  // The BLAS inputs and shading data are not uploaded again (state uniforms and vertices are).
  EXPECT_GT(again.upload_bytes, 0u);
  EXPECT_LT(again.upload_bytes, first.upload_bytes);
  EXPECT_EQ(again.tlas_builds + again.tlas_updates, 0u);
  EXPECT_EQ(again.kind_draws[static_cast<size_t>(DrawKind::kStatic)], 3u);
  RecordBuilder moved = base_frame();
  moved.directional_light(0, {0, 0, 1});
  moved.transform.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, 0.1f, 0.0f));
  for (int k = 0; k < 3; ++k)
    moved.quad({-2.0f + 1.5f * k, -1, -4}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  const FrameStats after_move = frame(moved);
  EXPECT_EQ(after_move.blas_builds, 0u);
  EXPECT_EQ(after_move.tlas_builds + after_move.tlas_updates, 1u);
  EXPECT_EQ(after_move.kind_draws[static_cast<size_t>(DrawKind::kStatic)], 3u);
}

// Two new renderers (so both see the same random numbers frame by frame), one refitting the
// BLASes of deforming draws and one building every shape anew (GLPT_BLAS_REFIT=0), each with a
// drawable of its own: the same frames through both.
class RefitAndRebuild {
 public:
  RefitAndRebuild() {
    RenderSettings settings;
    std::string error;
    refitting_ = make_renderer(settings, &error);
    EXPECT_NE(refitting_, nullptr) << error;
    settings.blas_refit = false;
    rebuilding_ = make_renderer(settings, &error);
    EXPECT_NE(rebuilding_, nullptr) << error;
  }
  bool ready() const { return refitting_ && rebuilding_; }
  // The frame `b` describes, refit and built anew; every frame's images must be identical.
  std::pair<Image, Image> render(const RecordBuilder& b) {
    std::pair<Image, Image> images{render(*refitting_, *refit_buffers_, b),
                                   render(*rebuilding_, *rebuild_buffers_, b)};
    EXPECT_EQ(images.first.rgba, images.second.rgba) << "refit and built anew differ";
    return images;
  }

 private:
  Image render(Renderer& renderer, DrawableBuffers& buffers, const RecordBuilder& b) {
    Image image;
    std::string error;
    EXPECT_TRUE(renderer.execute(b.record, buffers, b.drawable, image.stats, &error, &end_))
        << error;
    EXPECT_TRUE(renderer.read_color(buffers, GL_FRONT, 0, 0, kSize, kSize, image.rgba, &error))
        << error;
    return image;
  }
  std::unique_ptr<Renderer> refitting_, rebuilding_;
  const std::shared_ptr<DrawableBuffers> refit_buffers_ = create_drawable_buffers();
  const std::shared_ptr<DrawableBuffers> rebuild_buffers_ = create_drawable_buffers();
  const FrameEnd end_;
};

TEST_F(RenderTest, ADeformingMeshRefitsItsBlasAndItsShadowFollowsIt) {
  // A wall lit from the right front and, under a modelview of its own, an occluder mesh (two
  // triangles) whose vertices move up every frame: the same topology with new positions, a
  // deforming draw. Its second shape is built refittable, every later one refits that BLAS in
  // place (no build), and its shadow on the wall follows it: the pixels it shades now are dark,
  // those it shaded a frame earlier lit again. Refit or built anew (GLPT_BLAS_REFIT=0), the
  // frames are the same.
  RefitAndRebuild renderers;
  ASSERT_TRUE(renderers.ready());
  auto frame = [&](float lift) {
    RecordBuilder b = base_frame();
    b.directional_light(0, {1, 0, 1});
    b.quad({-4, -3, -6}, {8, 0, 0}, {0, 6, 0}, glm::vec4(1));
    b.transform.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, -4.0f));
    const glm::vec3 low(-0.5f, -1.5f + lift, 0.0f);
    b.draw(GL_TRIANGLES,
           {low, low + glm::vec3(1, 0, 0), low + glm::vec3(1, 1, 0), low, low + glm::vec3(1, 1, 0),
            low + glm::vec3(0, 1, 0)},
           {0, 0, 1}, glm::vec4(1));
    return b;
  };
  // The wall point in the shadow of the occluder's centre (x 1, y: its middle) along the light.
  auto shadow_pixel = [&](const RecordBuilder& b, float lift) {
    return project(b, glm::vec3(-1.0f, -1.0f + lift, -6.0f));
  };
  for (int k = 0; k < 6; ++k) {
    const float lift = 0.4f * static_cast<float>(k);
    SCOPED_TRACE("frame " + std::to_string(k));
    const RecordBuilder b = frame(lift);
    const auto [image, rebuilt] = renderers.render(b);
    if (k == 0) {
      EXPECT_EQ(image.stats.blas_builds, 2u);
    } else if (k == 1) {
      EXPECT_EQ(image.stats.blas_builds, 1u);  // the second shape: refittable
    } else {
      EXPECT_EQ(image.stats.blas_builds, 0u);
      EXPECT_EQ(image.stats.blas_refits, 1u);
      EXPECT_EQ(rebuilt.stats.blas_refits, 0u);
      EXPECT_EQ(rebuilt.stats.blas_builds, 1u);
    }
    if (k >= 1) {
      EXPECT_EQ(image.stats.kind_draws[static_cast<size_t>(DrawKind::kDeforming)], 1u);
    }
    const glm::ivec2 now = shadow_pixel(b, lift);
    const glm::ivec2 before = shadow_pixel(b, lift - 1.0f);  // a whole occluder height lower
    EXPECT_LT(image.at(now.x, now.y).luminance(), 60) << image.at(now.x, now.y);
    EXPECT_GT(image.at(before.x, before.y).luminance(), 300) << image.at(before.x, before.y);
  }
}

TEST_F(RenderTest, ADeformingMeshWhoseTrianglesScatterIsBuiltAnewNotRefit) {
  // 64 small triangles on a wall, the same draw every frame, each frame at other places (a
  // permutation of their cells): the same topology, but a refit would keep a tree whose index
  // ranges now span the whole wall (BlasCache::refit_source weighs that against a build), so
  // every new shape is built anew. The same mesh merely moving up (every box moves with it)
  // keeps being refit. Either way the frames equal those of a renderer that always builds.
  RefitAndRebuild renderers;
  ASSERT_TRUE(renderers.ready());
  constexpr int kCells = 8;
  auto frame = [&](const std::vector<int>& cells, float lift) {
    RecordBuilder b = base_frame();
    b.directional_light(0, {0, 0, 1});
    std::vector<glm::vec3> positions;
    for (int cell : cells) {
      const glm::vec3 low(-2.0f + 0.5f * float(cell % kCells),
                          -2.0f + 0.5f * float(cell / kCells) + lift, -5.0f);
      positions.insert(positions.end(),
                       {low, low + glm::vec3(0.4f, 0, 0), low + glm::vec3(0.2f, 0.4f, 0)});
    }
    b.draw(GL_TRIANGLES, positions, {0, 0, 1}, glm::vec4(1));
    return b;
  };
  std::vector<int> cells(kCells * kCells);
  for (int i = 0; i < kCells * kCells; ++i) cells[size_t(i)] = i;
  std::mt19937 random(7);
  for (int k = 0; k < 8; ++k) {
    const bool scatter = k < 4;  // frames 0-3 scatter, 4-7 move the last arrangement up
    if (scatter) std::shuffle(cells.begin(), cells.end(), random);
    const float lift = scatter ? 0.0f : 0.05f * float(k - 3);
    SCOPED_TRACE("frame " + std::to_string(k));
    const Image image = renderers.render(frame(cells, lift)).first;
    if (k >= 2 && scatter) {
      EXPECT_EQ(image.stats.blas_builds, 1u);
      EXPECT_EQ(image.stats.blas_refits, 0u);
    } else if (k >= 4) {
      EXPECT_EQ(image.stats.blas_builds, 0u);
      EXPECT_EQ(image.stats.blas_refits, 1u);
    }
  }
}

TEST_F(RenderTest, AViewModelIsTracedInItsDepthRangeAndCastsNoShadowOnTheWorld) {
  // A white wall lit from the upper right and, drawn after it in glDepthRange(0, 0.1), a white
  // view-model quad between the wall and the light's direction: were it geometry for rays, its
  // shadow would fall on the wall around (-2, 0, -6). It is traced (lit like the wall: the same
  // normal and light) but not in the TLAS, so that part of the wall is as bright as its mirror
  // image (2, 0, -6).
  RecordBuilder b = base_frame();
  b.directional_light(0, {0.5f, 0.0f, 1.0f});
  b.quad({-4, -3, -6}, {8, 0, 0}, {0, 6, 0}, glm::vec4(1));
  b.transform.depth_far = 0.1f;
  b.quad({-0.5f, -0.5f, -2}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  const Image image = render(b);
  EXPECT_EQ(image.stats.traced_draws, 2u);
  EXPECT_EQ(image.stats.instances, 1u) << "the view model is no TLAS instance";
  EXPECT_EQ(image.stats.kind_draws[static_cast<size_t>(DrawKind::kViewmodel)], 1u);
  const glm::ivec2 shadowed = project(b, {-2, 0, -6}), mirror = project(b, {2, 0, -6});
  const glm::ivec2 model = project(b, {0, 0, -2});
  EXPECT_NEAR(image.at(shadowed.x, shadowed.y).r, image.at(mirror.x, mirror.y).r, 4)
      << image.at(shadowed.x, shadowed.y) << " vs " << image.at(mirror.x, mirror.y);
  EXPECT_NEAR(image.at(model.x, model.y).r, image.at(mirror.x, mirror.y).r, 4)
      << image.at(model.x, model.y);
  EXPECT_GT(image.at(model.x, model.y).r, 100);
}

TEST_F(RenderTest, StatsCountTheDrawsOfEachClass) {
  // A sky box of six faces, two traced quads (one geometry), a blended quad and a line.
  RecordBuilder b = base_frame();
  b.lighting.enabled = false;
  b.raster.ops.depth_write = false;
  const std::vector<glm::vec3> sky = box_faces(glm::vec3(-50.0f), glm::vec3(50.0f));
  for (size_t face = 0; face < 6; ++face)
    b.draw(GL_QUADS, {sky.begin() + 4 * face, sky.begin() + 4 * face + 4}, {0, 0, 1},
           glm::vec4(0.5f));
  b.raster.ops.depth_write = true;
  b.directional_light(0, {0, 0, 1});
  b.quad({-1, -1, -4}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  b.quad({0, 0, -4}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  b.raster.ops.blend = true;
  b.raster.ops.blend_src_rgb = b.raster.ops.blend_src_alpha = GL_SRC_ALPHA;
  b.raster.ops.blend_dst_rgb = b.raster.ops.blend_dst_alpha = GL_ONE_MINUS_SRC_ALPHA;
  // Unlit: its colour's alpha 0.5 reaches blending (lit, the material's alpha 1 would, and the
  // quad would be opaque).
  b.lighting.enabled = false;
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1, 1, 1, 0.5f));
  b.raster.ops.blend = false;
  b.draw(GL_LINES, {{0, 0, -3}, {1, 1, -3}}, {0, 0, 1}, glm::vec4(1));
  const Image image = render(b);
  EXPECT_EQ(image.stats.traced_draws, 2u);
  EXPECT_EQ(image.stats.sky_draws, 6u);
  EXPECT_EQ(image.stats.raster_draws, 2u);
  EXPECT_EQ(image.stats.instances, 2u) << "the world's two quads in one instance, the sky in one";
}

TEST(SceneBuilder, ProjectiveModelviewsGoToTheBlasInEyeSpace) {
  RecordBuilder b(16, 16);
  b.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 10.0f);
  glm::mat4 projective(1.0f);
  projective[1][3] = 0.5f;  // bottom row (0, 0.5, 0, 1): w = 1 + y / 2
  b.transform.modelview = projective;
  b.draw(GL_TRIANGLES, {{0, 0, -2}, {1, 0, -2}, {0, 2, -2}}, {0, 0, 1}, glm::vec4(1));
  SceneBuild build;
  build_trace_scene(b.record, b.drawable, build);
  ASSERT_EQ(build.scene.instances.size(), 1u);
  const Instance& instance = build.scene.instances[0];
  EXPECT_EQ(instance.modelview, glm::mat4(1.0f));
  ASSERT_EQ(instance.geometry->positions.size(), 3u);
  EXPECT_EQ(instance.geometry->positions[2], glm::vec3(0, 1, -1));  // (0, 2, -2) / w = 2
}

TEST(SceneBuilder, GeometryTheTracerHoldsIsNotDecomposedAgain) {
  RecordBuilder b(16, 16);
  b.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 10.0f);
  b.lighting.enabled = true;
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(1));
  b.transform.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0));
  b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, glm::vec4(0.5f));
  SceneBuild fresh, held;
  build_trace_scene(b.record, b.drawable, fresh);
  std::vector<std::pair<uint64_t, uint64_t>> asked;
  SceneOptions options;
  options.known_geometry = [&](uint64_t shape, uint64_t shading) {
    asked.emplace_back(shape, shading);
    return true;
  };
  build_trace_scene(b.record, b.drawable, held, options);
  ASSERT_EQ(fresh.scene.instances.size(), 2u);
  ASSERT_EQ(held.scene.instances.size(), 2u);
  ASSERT_EQ(asked.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const Geometry& a = *fresh.scene.instances[i].geometry;
    const Geometry& h = *held.scene.instances[i].geometry;
    EXPECT_FALSE(a.resident);
    EXPECT_EQ(a.triangle_count(), 2u);
    // The identity does not depend on whether the triangles were made.
    EXPECT_EQ(h.shape_hash, a.shape_hash);
    EXPECT_EQ(h.shading_hash, a.shading_hash);
    EXPECT_EQ(asked[i], std::make_pair(a.shape_hash, a.shading_hash));
    EXPECT_TRUE(h.resident);
    EXPECT_TRUE(h.positions.empty() && h.normals.empty() && h.colors.empty());
  }
  // The two quads share a shape (same vertices, other modelview) but not a shading.
  EXPECT_EQ(fresh.scene.instances[0].geometry->shape_hash,
            fresh.scene.instances[1].geometry->shape_hash);
  EXPECT_NE(fresh.scene.instances[0].geometry->shading_hash,
            fresh.scene.instances[1].geometry->shading_hash);
}

TEST(SceneBuilder, ShapeIdentityIgnoresColoursAndMaterials) {
  auto build_with = [](glm::vec4 color, float shininess) {
    RecordBuilder b(16, 16);
    b.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 10.0f);
    b.lighting.enabled = true;
    b.lighting.material[0].shininess = shininess;
    b.quad({-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, color);
    SceneBuild build;
    build_trace_scene(b.record, b.drawable, build);
    return *build.scene.instances.at(0).geometry;
  };
  const Geometry white = build_with(glm::vec4(1), 0.0f), red = build_with({1, 0, 0, 1}, 0.0f);
  const Geometry shiny = build_with(glm::vec4(1), 20.0f);
  EXPECT_EQ(white.shape_hash, red.shape_hash);
  EXPECT_EQ(white.shape_hash, shiny.shape_hash);
  EXPECT_NE(white.shading_hash, red.shading_hash);
  EXPECT_NE(white.shading_hash, shiny.shading_hash);
}

TEST(SceneBuilder, EachStateListsItsOwnLights) {
  RecordBuilder b(16, 16);
  b.transform.projection = glm::perspective(1.0f, 1.0f, 0.1f, 10.0f);
  b.directional_light(0, {0, 0, 1});
  b.quad({-1, -1, -3}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  b.lighting.light_mask = 2;
  b.lighting.lights[1].position = glm::vec4(1, 0, 0, 0);
  b.quad({0, -1, -3}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  b.lighting.enabled = false;
  b.quad({0, 0, -3}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1));
  SceneBuild build;
  build_trace_scene(b.record, b.drawable, build);
  ASSERT_EQ(build.scene.lights.size(), 2u);
  const auto draw_state = [&](size_t command) {
    return std::get<rec::Draw>(b.record.commands[command]).state;
  };
  EXPECT_EQ(build.scene.states[draw_state(0)].lights, (std::vector<uint32_t>{0}));
  EXPECT_EQ(build.scene.states[draw_state(1)].lights, (std::vector<uint32_t>{1}));
  // Unlit: no GL lights; at bounce hits lit by the first lit state's.
  EXPECT_EQ(build.scene.states[draw_state(2)].lights, (std::vector<uint32_t>{0}));
  EXPECT_EQ(build.scene.lights[1].position, glm::vec4(1, 0, 0, 0));
  EXPECT_EQ(build.scene.instances.size(), 3u);  // a new light set starts a new instance
}

TEST(ClassifyDraws, ViewerOfAProjection) {
  EXPECT_EQ(viewer_of_projection(glm::frustum(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 10.0f)),
            glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(viewer_of_projection(glm::mat4(1.0f)), glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(viewer_of_projection(glm::ortho(0.0f, 4.0f, 4.0f, 0.0f, 1.0f, -1.0f)),
            glm::vec4(0, 0, 1, 0));
  // A perspective camera moved back by 5 (projection * translate): its centre is at z = 5.
  const glm::vec4 moved = viewer_of_projection(glm::perspective(1.0f, 1.0f, 0.1f, 10.0f) *
                                               glm::translate(glm::mat4(1.0f), {0, 0, -5}));
  EXPECT_NEAR(moved.z, 5.0f, 1e-4f);
  EXPECT_EQ(moved.w, 1.0f);
}

// Which projections reverse GL's window winding (rays' culling, scene_builder.hpp): those that
// mirror x or y, not those that swap near and far or move the camera.
TEST(ClassifyDraws, ProjectionsThatMirrorTheImage) {
  EXPECT_FALSE(projection_mirrors(glm::frustum(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 10.0f)));
  EXPECT_TRUE(projection_mirrors(glm::frustum(1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 10.0f)));
  EXPECT_TRUE(projection_mirrors(glm::frustum(-1.0f, 1.0f, 1.0f, -1.0f, 1.0f, 10.0f)));
  EXPECT_FALSE(projection_mirrors(glm::frustum(1.0f, -1.0f, 1.0f, -1.0f, 1.0f, 10.0f)));
  EXPECT_FALSE(projection_mirrors(glm::ortho(0.0f, 4.0f, 0.0f, 4.0f, -1.0f, 1.0f)));
  EXPECT_TRUE(projection_mirrors(glm::ortho(0.0f, 4.0f, 4.0f, 0.0f, -1.0f, 1.0f)));  // y down
  EXPECT_FALSE(projection_mirrors(glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, -1.0f)));
  EXPECT_FALSE(projection_mirrors(glm::mat4(1.0f)));
  EXPECT_FALSE(projection_mirrors(glm::perspective(1.0f, 1.0f, 0.1f, 10.0f) *
                                  glm::translate(glm::mat4(1.0f), {0, 0, -5})));
  EXPECT_TRUE(projection_mirrors(glm::perspective(1.0f, 1.0f, 0.1f, 10.0f) *
                                 glm::scale(glm::mat4(1.0f), {-1, 1, 1})));
  EXPECT_FALSE(projection_mirrors(glm::mat4(0.0f)));  // degenerate: no answer, no mirror
}

// Raster mode: a program walking through blend equations and factors, colour masks and logic
// ops compiles a pipeline per state only where the device can neither blend in the fragment
// shader (raster_framebuffer_ops.h; GLPT_VK_NO_SHADER_BLEND=1 hides it) nor set blend state per
// draw (VK_EXT_extended_dynamic_state3; GLPT_VK_NO_DYNAMIC_BLEND=1 hides it).
TEST(RenderDeviceSelection, BlendStatesShareOnePipelineWhereTheDeviceSetsThemPerDraw) {
  auto pipelines_for_blend_states = [](bool shader_blend, bool dynamic_blend) -> uint32_t {
    if (!shader_blend) ::setenv("GLPT_VK_NO_SHADER_BLEND", "1", 1);
    if (!dynamic_blend) ::setenv("GLPT_VK_NO_DYNAMIC_BLEND", "1", 1);
    RenderSettings settings;
    settings.mode = RenderMode::kRaster;
    std::string error;
    std::unique_ptr<Renderer> renderer = Renderer::create(settings, &error);
    ::unsetenv("GLPT_VK_NO_SHADER_BLEND");
    ::unsetenv("GLPT_VK_NO_DYNAMIC_BLEND");
    EXPECT_NE(renderer, nullptr) << error;
    if (renderer == nullptr) return 0;
    RecordBuilder b(16, 16);
    b.clear(glm::vec4(0.5f));
    b.raster.ops.blend = true;
    const uint32_t factors[] = {GL_ONE, GL_SRC_ALPHA, GL_DST_COLOR, GL_ONE_MINUS_SRC_ALPHA};
    for (uint32_t factor : factors) {
      b.raster.ops.blend_src_rgb = b.raster.ops.blend_src_alpha = factor;
      b.quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, glm::vec4(0.2f, 0.4f, 0.6f, 0.5f));
    }
    b.raster.ops.blend = false;
    b.raster.ops.color_write = {true, false, true, true};
    b.quad({-1, -1, 0}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1.0f));
    b.raster.ops.color_logic_op = true;
    b.raster.ops.logic_op = GL_XOR;
    b.quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::vec4(1.0f));
    FrameStats stats;
    const std::shared_ptr<DrawableBuffers> buffers = create_drawable_buffers();
    EXPECT_TRUE(renderer->execute(b.record, *buffers, b.drawable, stats, &error)) << error;
    return stats.pipelines_created;
  };
  // The clear is a transfer; the six draws differ only in blend, mask and logic op state.
  // Blending in the shader: one pipeline blends (the four blend states and the logic op), one
  // does not (the masked draw); without dynamic state the logic op's mask is a third.
  EXPECT_EQ(pipelines_for_blend_states(true, true), 2u);
  EXPECT_EQ(pipelines_for_blend_states(true, false), 3u);
  EXPECT_EQ(pipelines_for_blend_states(false, true), 1u);
  EXPECT_EQ(pipelines_for_blend_states(false, false), 6u);
}

// A blend state blends in the fragment shader in the first records that use it, then in the
// pipeline (RasterRenderer::shader_blends): the pixels are the same either way and the same as
// a device without shader blending gives, frame after frame.
TEST(RenderDeviceSelection, ABlendStateMovesFromTheShaderToThePipelineWithTheSamePixels) {
  auto raster_renderer = [](bool shader_blend) {
    if (!shader_blend) ::setenv("GLPT_VK_NO_SHADER_BLEND", "1", 1);
    RenderSettings settings;
    settings.mode = RenderMode::kRaster;
    settings.validation = RenderSettings::from_environment().validation;
    std::string error;
    std::unique_ptr<Renderer> renderer = Renderer::create(settings, &error);
    ::unsetenv("GLPT_VK_NO_SHADER_BLEND");
    EXPECT_NE(renderer, nullptr) << error;
    return renderer;
  };
  const std::unique_ptr<Renderer> shader = raster_renderer(true);
  const std::unique_ptr<Renderer> pipeline = raster_renderer(false);
  ASSERT_TRUE(shader && pipeline);
  const std::shared_ptr<DrawableBuffers> shader_buffers = create_drawable_buffers();
  const std::shared_ptr<DrawableBuffers> pipeline_buffers = create_drawable_buffers();
  std::vector<uint32_t> created;
  for (int record = 0; record < 7; ++record) {
    // Each record blends over the last one's pixels (no clear after the first).
    RecordBuilder b(16, 16);
    if (record == 0) b.clear(glm::vec4(0.1f, 0.5f, 0.9f, 1.0f));
    b.raster.ops.blend = true;
    b.raster.ops.blend_src_rgb = b.raster.ops.blend_src_alpha = GL_SRC_ALPHA;
    b.raster.ops.blend_dst_rgb = b.raster.ops.blend_dst_alpha = GL_ONE_MINUS_SRC_ALPHA;
    b.quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, glm::vec4(0.9f, 0.3f, 0.2f, 0.37f));
    std::string error;
    FrameStats stats, unused;
    std::vector<uint8_t> from_shader, from_pipeline;
    ASSERT_TRUE(shader->execute(b.record, *shader_buffers, b.drawable, stats, &error)) << error;
    ASSERT_TRUE(pipeline->execute(b.record, *pipeline_buffers, b.drawable, unused, &error))
        << error;
    ASSERT_TRUE(shader->read_color(*shader_buffers, GL_BACK, 0, 0, 16, 16, from_shader, &error));
    ASSERT_TRUE(
        pipeline->read_color(*pipeline_buffers, GL_BACK, 0, 0, 16, 16, from_pipeline, &error));
    EXPECT_EQ(from_shader, from_pipeline) << "record " << record;
    created.push_back(stats.pipelines_created);
  }
  // The shader's pipeline in the first record, the pipeline that blends from the fifth on.
  EXPECT_EQ(created, (std::vector<uint32_t>{1, 0, 0, 0, 1, 0, 0}));
}

TEST(RenderDeviceSelection, UnknownDeviceNameGivesAClearError) {
  ::setenv("GLPT_VK_DEVICE", "no-such-device-xyz", 1);
  std::string error;
  std::unique_ptr<Renderer> renderer = Renderer::create(RenderSettings{}, &error);
  ::unsetenv("GLPT_VK_DEVICE");
  EXPECT_EQ(renderer, nullptr);
  EXPECT_NE(error.find("GLPT_VK_DEVICE"), std::string::npos) << error;
}

}  // namespace
}  // namespace glpt::rt
