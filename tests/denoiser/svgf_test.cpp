// The SVGF denoiser (rt_core/passes/svgf_denoiser.hpp) measured against converged references
// (issue 17, item 5): GL scenes path-traced at 1 sample per pixel through glpt's front end, the
// denoised frames compared with GLPT_REFERENCE renders and with the raw frames (GLPT_DENOISER=off)
// of the same seeds. docs/denoiser.md records the numbers these tests print.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "../common/gl_scene.hpp"
#include "../common/headless_gl_render.hpp"
#include "common/image_io.hpp"
#include "flip.hpp"
#include "gl/gl_enums.h"
#include "gl_shim/gl_entry_decls.h"

namespace {

using glpt::test::Settings;
using Frames = std::vector<std::vector<uint8_t>>;

constexpr int kSize = 96;
constexpr int kReferenceSamples = 1024;

// Camera above a floor looking down at a box lit by a small sphere light: soft shadow edges,
// box edges, indirect light between box and floor.
void scene_camera(float eye_x, float eye_y = 3.0f) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // The camera folded into the modelview, as GL programs do.
  glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(-eye_x, -eye_y, -4.5f);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
}

void material(glm::vec3 diffuse, float specular = 0.0f) {
  const float d[] = {diffuse.r, diffuse.g, diffuse.b, 1};
  const float black[] = {0, 0, 0, 1};
  const float s[] = {specular, specular, specular, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, d);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, black);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
}

// What the scene's positions pass through before GL sees them: the identity, or the camera where
// the program transforms its vertices itself (SceneOptions::camera_in_vertices).
glm::mat4 vertex_transform(1.0f);

void quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
  auto at = [](glm::vec3 p) { return glm::vec3(vertex_transform * glm::vec4(p, 1.0f)); };
  glpt::test::quad(at(p0), at(p1), at(p2), at(p3));
}

void box(glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 a = lo, b = hi;
  quad({a.x, b.y, a.z}, {a.x, b.y, b.z}, {b.x, b.y, b.z}, {b.x, b.y, a.z});  // top
  quad({a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z});  // front
  quad({b.x, a.y, a.z}, {a.x, a.y, a.z}, {a.x, b.y, a.z}, {b.x, b.y, a.z});  // back
  quad({a.x, a.y, a.z}, {a.x, a.y, b.z}, {a.x, b.y, b.z}, {a.x, b.y, a.z});  // left
  quad({b.x, a.y, b.z}, {b.x, a.y, a.z}, {b.x, b.y, a.z}, {b.x, b.y, b.z});  // right
}

struct SceneOptions {
  float eye_x = 0.0f;
  bool light_on = true;
  float box_x = 0.0f;
  float box_specular = 0.0f;  // the box's GL_SPECULAR (grey), shininess 24
  float eye_y = 3.0f;         // the camera's height
  // The program transforms its vertices and lights by the camera itself and draws under an
  // identity modelview (software transform): every draw deforms when the camera moves.
  bool camera_in_vertices = false;
  bool floor = true;  // without it the box stands over the cleared background
  float box_scale = 1.0f;
  // Black stripes on the box (a texture modulating its colours, GL_SINGLE_COLOR: its specular
  // too), as lettering on a shiny car body.
  bool box_striped = false;
};

// A texture of black stripes on white (one black texel in four), nearest, repeating; S from
// object x, four stripes across the box.
void stripes() {
  static const uint8_t texels[8 * 4] = {255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                        255, 0,   0,   0,   255, 255, 255, 255, 255, 255, 255,
                                        255, 255, 255, 255, 255, 255, 0,   0,   0,   255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const float s_plane[] = {1.6667f, 0.0f, 0.0f, 1.0f}, t_plane[] = {0.0f, 0.0f, 0.0f, 0.5f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, s_plane);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, t_plane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_2D);
}

void draw_scene(const SceneOptions& o) {
  scene_camera(o.eye_x, o.eye_y);
  vertex_transform = glm::mat4(1.0f);
  if (o.camera_in_vertices) {
    glGetFloatv(GL_MODELVIEW_MATRIX, &vertex_transform[0][0]);
    glLoadIdentity();
  }
  auto at = [](glm::vec3 p) { return glm::vec3(vertex_transform * glm::vec4(p, 1.0f)); };
  glEnable(GL_LIGHTING);
  const float ambient[] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glpt::test::inverse_square_light(GL_LIGHT0, at({1.5f, 3.0f, 1.0f}), glm::vec3(9.0f));
  if (!o.light_on) glDisable(GL_LIGHT0);
  // A second, dim light that stays on, so switching the first leaves a lit scene.
  glpt::test::inverse_square_light(GL_LIGHT1, at({-2.0f, 2.5f, 2.0f}), glm::vec3(2.0f));
  material({0.7f, 0.7f, 0.7f});
  // The floor in tiles: separate draws, as programs draw levels.
  for (int i = -3; i < 3 && o.floor; ++i)
    for (int j = -3; j < 3; ++j)
      quad({float(i), 0, float(j + 1)}, {float(i + 1), 0, float(j + 1)},
           {float(i + 1), 0, float(j)}, {float(i), 0, float(j)});
  material({0.8f, 0.3f, 0.2f}, o.box_specular);
  glPushMatrix();
  glTranslatef(o.box_x, 0.0f, 0.0f);
  glScalef(o.box_scale, o.box_scale, o.box_scale);
  if (o.box_striped) stripes();
  box({-0.6f, 0.0f, -0.6f}, {0.6f, 1.0f, 0.6f});
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glPopMatrix();
}

Settings path(Settings extra) {
  extra.insert(extra.begin(), {"GLPT_MODE", "path"});
  extra.push_back({"GLPT_LIGHT_RADIUS", "0.3"});
  return extra;
}

Frames render(const Settings& settings, int frames, const std::function<SceneOptions(int)>& at,
              std::vector<glpt::rt::FrameStats>* stats = nullptr) {
  return glpt::test::render_headless_frames(
      kSize, settings, [&](int frame) { draw_scene(at(frame)); }, frames, stats);
}

std::vector<uint8_t> reference(const SceneOptions& o) {
  return render(path({{"GLPT_REFERENCE", std::to_string(kReferenceSamples)}}), 1,
                [&](int) { return o; })
      .back();
}

// Relative MSE over the RGB values (the relMSE of the denoising literature: squared error over
// the squared reference, with a small epsilon for dark pixels), optionally within a mask.
double rel_mse(const std::vector<uint8_t>& image, const std::vector<uint8_t>& ref,
               const std::vector<uint8_t>* mask = nullptr) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    if (i % 4 == 3 || (mask != nullptr && !(*mask)[i / 4])) continue;
    const double r = ref[i] / 255.0, d = image[i] / 255.0 - r;
    sum += d * d / (r * r + 1e-2);
    ++n;
  }
  return n > 0 ? sum / double(n) : 0.0;
}

glpt::diff::FlipResult flip(const std::vector<uint8_t>& image, const std::vector<uint8_t>& ref) {
  glpt::diff::FlipResult result;
  std::string error;
  const glpt::diff::Rgb8View a{kSize, kSize, 4, ref.data()}, b{kSize, kSize, 4, image.data()};
  EXPECT_TRUE(
      glpt::diff::compute_flip(a, b, glpt::diff::default_pixels_per_degree(), &result, &error))
      << error;
  return result;
}

double masked_flip(const glpt::diff::FlipResult& f, const std::vector<uint8_t>& mask) {
  double sum = 0.0;
  size_t n = 0;
  // FLIP's rows are top first, the images' (and the mask's) bottom first.
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (mask[size_t(y) * kSize + x]) {
        sum += f.error[size_t(kSize - 1 - y) * kSize + x];
        ++n;
      }
  return n > 0 ? sum / double(n) : 0.0;
}

// Pixels within one pixel of a strong edge of the reference (geometry and shadow edges).
std::vector<uint8_t> edge_mask(const std::vector<uint8_t>& ref) {
  std::vector<uint8_t> mask(size_t(kSize) * kSize, 0);
  auto lum = [&](int x, int y) {
    const uint8_t* p = &ref[(size_t(y) * kSize + x) * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  };
  for (int y = 1; y + 1 < kSize; ++y)
    for (int x = 1; x + 1 < kSize; ++x) {
      const double gx = lum(x + 1, y) - lum(x - 1, y), gy = lum(x, y + 1) - lum(x, y - 1);
      if (std::sqrt(gx * gx + gy * gy) > 40.0)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) mask[size_t(y + dy) * kSize + x + dx] = 1;
    }
  return mask;
}

void keep(const std::string& tag, const std::vector<uint8_t>& rgba) {
  if (const char* dir = std::getenv("GLPT_TEST_IMAGES")) {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    glpt::write_png_rgba8(std::string(dir) + "/" + test->name() + "_" + tag + ".png", kSize, kSize,
                          rgba.data(), true, nullptr);
  }
}

// Mean absolute change per 8-bit value between consecutive frames from `first` on.
double frame_to_frame_change(const Frames& frames, size_t first) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t f = first + 1; f < frames.size(); ++f)
    for (size_t i = 0; i < frames[f].size(); ++i) {
      if (i % 4 == 3) continue;
      sum += std::abs(int(frames[f][i]) - int(frames[f - 1][i]));
      ++n;
    }
  return n > 0 ? sum / double(n) : 0.0;
}

const Settings kOneSample = {{"GLPT_SPP", "1"}, {"GLPT_ACCUMULATE", "0"}};

Settings with(Settings base, Settings extra) {
  base.insert(base.end(), extra.begin(), extra.end());
  return path(base);
}

TEST(Svgf, StillSceneAtOneSampleHasAFifthOfTheRawRelMseAndHardlyFlickers) {
  const SceneOptions still;
  const std::vector<uint8_t> ref = reference(still);
  const int frames = 16;
  const Frames denoised = render(with(kOneSample, {}), frames, [&](int) { return still; });
  const Frames raw =
      render(with(kOneSample, {{"GLPT_DENOISER", "off"}}), frames, [&](int) { return still; });
  keep("reference", ref);
  keep("denoised", denoised.back());
  keep("raw", raw.back());
  const double mse_denoised = rel_mse(denoised.back(), ref), mse_raw = rel_mse(raw.back(), ref);
  const double flip_denoised = flip(denoised.back(), ref).mean,
               flip_raw = flip(raw.back(), ref).mean;
  const std::vector<uint8_t> edges = edge_mask(ref);
  const double edge_denoised = masked_flip(flip(denoised.back(), ref), edges),
               edge_raw = masked_flip(flip(raw.back(), ref), edges);
  std::printf(
      "still: relMSE raw %.5f denoised %.5f (%.1fx); FLIP raw %.4f denoised %.4f (%.1fx); "
      "edge FLIP raw %.4f denoised %.4f\n",
      mse_raw, mse_denoised, mse_raw / mse_denoised, flip_raw, flip_denoised,
      flip_raw / flip_denoised, edge_raw, edge_denoised);
  EXPECT_LE(mse_denoised * 5.0, mse_raw);
  // FLIP: the reference is anti-aliased (jittered samples), a 1-sample frame samples pixel
  // centres; the converged centre-sampled image alone is this far from it, a floor no denoiser
  // of 1-sample frames goes below (issue 17 asks for 5x in FLIP: not reached, docs/denoiser.md).
  const std::vector<uint8_t> centres =
      render(path({{"GLPT_SPP", "1024"}, {"GLPT_ACCUMULATE", "0"}, {"GLPT_DENOISER", "off"}}), 1,
             [&](int) { return still; })
          .back();
  std::printf("still: FLIP of the converged pixel-centre image %.4f (the floor)\n",
              flip(centres, ref).mean);
  // Measured 1.9x (1.7x before the integrated colour's variance and the clamp's stand-in).
  EXPECT_LE(flip_denoised * 1.75, flip_raw);
  // Edges stay: on the reference's edges the denoised image is no worse than raw samples.
  EXPECT_LE(edge_denoised, edge_raw);
  // Without accumulation the raw frames flicker; the denoised ones hardly change.
  const double change_denoised = frame_to_frame_change(denoised, 8),
               change_raw = frame_to_frame_change(raw, 8);
  std::printf("still: frame-to-frame change raw %.3f denoised %.3f (%.1fx)\n", change_raw,
              change_denoised, change_raw / change_denoised);
  EXPECT_LE(change_denoised * 5.0, change_raw);
}

TEST(Svgf, TemporalAntiAliasingAveragesJitteredEdgesOverFrames) {
  // GLPT_TAA (temporal_aa.comp): frames the denoiser runs on are jittered and blended with their
  // reprojected history at edges, so edges converge to the pixel's coverage, as the reference's
  // jittered samples do; a frame at pixel centres shows each edge as a step. Still and moving.
  const SceneOptions still;
  const std::vector<uint8_t> ref = reference(still);
  const int frames = 16;
  const Frames with_taa = render(with(kOneSample, {}), frames, [&](int) { return still; });
  const Frames without =
      render(with(kOneSample, {{"GLPT_TAA", "0"}}), frames, [&](int) { return still; });
  auto at = [](int frame) {
    SceneOptions o;
    o.eye_x = -0.6f + 0.08f * float(frame);
    return o;
  };
  const std::vector<uint8_t> moving_ref = reference(at(frames - 1));
  const Frames moving = render(with(kOneSample, {}), frames, at);
  const Frames moving_without = render(with(kOneSample, {{"GLPT_TAA", "0"}}), frames, at);
  keep("with", with_taa.back());
  keep("without", without.back());
  const std::vector<uint8_t> edges = edge_mask(ref);
  const double still_with = rel_mse(with_taa.back(), ref),
               still_without = rel_mse(without.back(), ref),
               edge_with = rel_mse(with_taa.back(), ref, &edges),
               edge_without = rel_mse(without.back(), ref, &edges),
               moving_with = rel_mse(moving.back(), moving_ref),
               moving_no = rel_mse(moving_without.back(), moving_ref);
  std::printf(
      "anti-aliasing: still relMSE %.5f against %.5f without (edges %.4f against %.4f), FLIP "
      "%.4f against %.4f; moving camera %.5f against %.5f\n",
      still_with, still_without, edge_with, edge_without, flip(with_taa.back(), ref).mean,
      flip(without.back(), ref).mean, moving_with, moving_no);
  EXPECT_LE(still_with * 2.5, still_without);  // measured 3.3x
  EXPECT_LE(edge_with * 2.5, edge_without);    // measured 4.0x
  EXPECT_LE(moving_with * 1.2, moving_no);     // measured 1.4x
}

TEST(Svgf, AnObjectOverTheBackgroundIsFilteredInTheTilesTheTracerShaded) {
  // The box alone over the cleared background: the trace pass lists the 32x8 tiles with a pixel
  // to filter and the denoiser's passes run over those alone (GLPT_DN_BINDING_TILES). A tile
  // left off the list would show what its work slots held before (black here), and a-trous
  // iterations over no tile would leave the temporal result: both are measured.
  SceneOptions box;
  box.floor = false;
  box.box_scale = 1.6f;
  const std::vector<uint8_t> ref = reference(box);
  // Errors over the box's pixels (the background's are 0 in every image).
  std::vector<uint8_t> covered(size_t(kSize) * kSize);
  for (size_t p = 0; p < covered.size(); ++p)
    covered[p] = ref[4 * p] != 0 || ref[4 * p + 1] != 0 || ref[4 * p + 2] != 0;
  const int frames = 12;
  std::vector<glpt::rt::FrameStats> stats;
  const Frames denoised = render(
      with(kOneSample, {}), frames, [&](int) { return box; }, &stats);
  // The iterations' share, without the anti-aliasing pass (which, averaging edges over frames,
  // makes up for much of what the temporal pass alone leaves: 0.0052 against 0.0053).
  const Frames no_taa =
      render(with(kOneSample, {{"GLPT_TAA", "0"}}), frames, [&](int) { return box; });
  const Frames temporal =
      render(with(kOneSample, {{"GLPT_DENOISE_ITERATIONS", "0"}, {"GLPT_TAA", "0"}}), frames,
             [&](int) { return box; });
  const Frames raw =
      render(with(kOneSample, {{"GLPT_DENOISER", "off"}}), frames, [&](int) { return box; });
  // Traced on a coarse grid and filled (GLPT_SCALE): the fill pass lists the tiles.
  const Frames scaled =
      render(with(kOneSample, {{"GLPT_SCALE", "0.5"}}), frames, [&](int) { return box; });
  const Frames scaled_raw =
      render(with(kOneSample, {{"GLPT_SCALE", "0.5"}, {"GLPT_DENOISER", "off"}}), frames,
             [&](int) { return box; });
  keep("reference", ref);
  keep("denoised", denoised.back());
  keep("temporal", temporal.back());
  keep("scaled", scaled.back());
  const double mse_denoised = rel_mse(denoised.back(), ref, &covered),
               mse_temporal = rel_mse(temporal.back(), ref, &covered),
               mse_no_taa = rel_mse(no_taa.back(), ref, &covered),
               mse_raw = rel_mse(raw.back(), ref, &covered),
               mse_scaled = rel_mse(scaled.back(), ref, &covered),
               mse_scaled_raw = rel_mse(scaled_raw.back(), ref, &covered);
  constexpr uint32_t kTiles = (kSize + 31) / 32 * ((kSize + 7) / 8);
  std::printf(
      "box alone: %u of %u tiles filtered; relMSE raw %.5f denoised %.5f (%.1fx); without "
      "anti-aliasing %.5f, the temporal pass alone %.5f; at GLPT_SCALE=0.5 raw %.5f denoised "
      "%.5f (%.1fx)\n",
      stats.back().denoised_tiles, kTiles, mse_raw, mse_denoised, mse_raw / mse_denoised,
      mse_no_taa, mse_temporal, mse_scaled_raw, mse_scaled, mse_scaled_raw / mse_scaled);
  EXPECT_GT(stats.back().denoised_tiles, 0u);
  EXPECT_LT(stats.back().denoised_tiles, kTiles);
  EXPECT_LE(mse_denoised * 5.0, mse_raw);
  EXPECT_LE(mse_no_taa * 1.3, mse_temporal);
  EXPECT_LE(mse_scaled * 3.0, mse_scaled_raw);
  // The background stays as GL cleared it.
  size_t background = 0, changed = 0;
  for (size_t p = 0; p < covered.size(); ++p)
    if (!covered[p]) {
      ++background;
      changed += denoised.back()[4 * p] != 0 || denoised.back()[4 * p + 1] != 0 ||
                 denoised.back()[4 * p + 2] != 0;
    }
  EXPECT_GT(background, covered.size() / 4);
  EXPECT_EQ(changed, 0u);
}

TEST(Svgf, AStillSceneUnderAccumulationShowsTheAverageOfItsDenoisedFrames) {
  // With accumulation on (the default) a still scene's G-buffer is jittered frame by frame for
  // anti-aliasing. Until GLPT_DENOISE_UNTIL samples the denoised frames are shown, and the last
  // one alone would show its jittered edges (a still image wobbling by up to half a pixel): the
  // composite shows the average of the denoised frames since the accumulation began.
  const SceneOptions still;
  const std::vector<uint8_t> ref = reference(still);
  const int frames = 16;
  const Frames averaged = render(path({{"GLPT_SPP", "1"}, {"GLPT_DENOISE_UNTIL", "1000"}}), frames,
                                 [&](int) { return still; });
  const Frames single = render(with(kOneSample, {}), frames, [&](int) { return still; });
  const Frames raw_average = render(path({{"GLPT_SPP", "1"}, {"GLPT_DENOISER", "off"}}), frames,
                                    [&](int) { return still; });
  keep("averaged", averaged.back());
  keep("raw_average", raw_average.back());
  const double mse_averaged = rel_mse(averaged.back(), ref),
               mse_single = rel_mse(single.back(), ref),
               mse_raw_average = rel_mse(raw_average.back(), ref);
  std::printf(
      "still, accumulating: relMSE of the %d denoised frames' average %.5f (FLIP %.4f), the "
      "last denoised frame without accumulation %.5f, the raw samples' average %.5f (FLIP "
      "%.4f)\n",
      frames, mse_averaged, flip(averaged.back(), ref).mean, mse_single, mse_raw_average,
      flip(raw_average.back(), ref).mean);
  EXPECT_LE(mse_averaged * 2.0, mse_single);
  EXPECT_LE(mse_averaged * 1.5, mse_raw_average);
  // A pixel's samples are stratified over frames (shaders/trace/rng.h): 16 of them average to
  // about 1/50 of one sample's relMSE, where independent numbers reach 1/16 (measured 1/15) and
  // numbers that repeat from frame to frame 1/1.
  EXPECT_LE(mse_raw_average * 25.0, rel_mse(raw_average.front(), ref));
}

TEST(Svgf, SpecularLightIsFilteredWhereASurfaceReflectsIt) {
  // The scenes above reflect nothing specularly: their specular channel is left out of the
  // filter (GLPT_DN_NO_SPECULAR). A shiny box brings it back: its highlights are filtered as the
  // diffuse light is.
  SceneOptions shiny;
  shiny.box_specular = 0.6f;
  const std::vector<uint8_t> ref = reference(shiny);
  const int frames = 16;
  const Frames denoised = render(with(kOneSample, {}), frames, [&](int) { return shiny; });
  const Frames raw =
      render(with(kOneSample, {{"GLPT_DENOISER", "off"}}), frames, [&](int) { return shiny; });
  const std::vector<uint8_t> matte = reference(SceneOptions{});
  keep("reference", ref);
  keep("denoised", denoised.back());
  // The highlight is there: the shiny reference differs from the matte one.
  EXPECT_GT(rel_mse(matte, ref), 1e-3);
  const double mse_denoised = rel_mse(denoised.back(), ref), mse_raw = rel_mse(raw.back(), ref);
  std::printf("specular: relMSE raw %.5f denoised %.5f (%.1fx)\n", mse_raw, mse_denoised,
              mse_raw / mse_denoised);
  EXPECT_LE(mse_denoised * 5.0, mse_raw);
}

TEST(Svgf, ATexturedHighlightKeepsItsTexture) {
  // GL_SINGLE_COLOR textures the specular colour too: a shiny box with black stripes reflects
  // nothing where they are (a rally car's lettering). Every channel holds light per unit of its
  // lobe's reflectance, estimated on the black texels too (path_trace.comp traces the primary
  // vertex with unit reflectance). When the specular channel held radiance and a black texel's
  // channels held 0, the filter spread the highlight over the stripes and the stripes' 0 into
  // their neighbours (grey lettering with dark outlines): relMSE 2.7x below the raw frame's,
  // edge FLIP 0.095 against the raw frame's 0.141.
  SceneOptions shiny;
  shiny.box_specular = 0.6f;
  shiny.box_striped = true;
  const std::vector<uint8_t> ref = reference(shiny);
  const int frames = 16;
  const Frames denoised = render(with(kOneSample, {}), frames, [&](int) { return shiny; });
  const Frames raw =
      render(with(kOneSample, {{"GLPT_DENOISER", "off"}}), frames, [&](int) { return shiny; });
  keep("reference", ref);
  keep("denoised", denoised.back());
  keep("raw", raw.back());
  const std::vector<uint8_t> edges = edge_mask(ref);
  const double edge_denoised = masked_flip(flip(denoised.back(), ref), edges),
               edge_raw = masked_flip(flip(raw.back(), ref), edges);
  const double mse_denoised = rel_mse(denoised.back(), ref), mse_raw = rel_mse(raw.back(), ref);
  std::printf(
      "textured highlight: relMSE raw %.5f denoised %.5f (%.1fx); edge FLIP raw %.4f denoised "
      "%.4f\n",
      mse_raw, mse_denoised, mse_raw / mse_denoised, edge_raw, edge_denoised);
  EXPECT_LE(mse_denoised * 5.0, mse_raw);
  EXPECT_LT(edge_denoised * 1.5, edge_raw);
}

TEST(Svgf, MovingCameraKeepsItsHistoryAndHasAFifthOfTheRawRelMse) {
  const int frames = 16;
  auto at = [](int frame) {
    SceneOptions o;
    o.eye_x = -0.6f + 0.08f * float(frame);
    return o;
  };
  const std::vector<uint8_t> ref = reference(at(frames - 1));
  std::vector<glpt::rt::FrameStats> stats;
  const Frames denoised = render(with(kOneSample, {}), frames, at, &stats);
  std::vector<glpt::rt::FrameStats> raw_stats;
  const Frames raw = render(with(kOneSample, {{"GLPT_DENOISER", "off"}}), frames, at, &raw_stats);
  keep("reference", ref);
  keep("denoised", denoised.back());
  keep("raw", raw.back());
  const double mse_denoised = rel_mse(denoised.back(), ref), mse_raw = rel_mse(raw.back(), ref);
  const double flip_denoised = flip(denoised.back(), ref).mean,
               flip_raw = flip(raw.back(), ref).mean;
  std::printf(
      "moving camera: relMSE raw %.5f denoised %.5f (%.1fx); FLIP raw %.4f denoised "
      "%.4f (%.1fx)\n",
      mse_raw, mse_denoised, mse_raw / mse_denoised, flip_raw, flip_denoised,
      flip_raw / flip_denoised);
  EXPECT_LE(mse_denoised * 5.0, mse_raw);
  EXPECT_LE(flip_denoised * 1.75, flip_raw);  // 2.0x measured; the still scene's test: FLIP's floor
  // The edge-stopping on the integrated colour's variance blurs less than on one sample's (the
  // 2017 paper's): measured 0.00493 against 0.00660.
  const Frames sample_variance =
      render(with(kOneSample, {{"GLPT_DENOISE_MEAN_VARIANCE", "0"}}), frames, at);
  const double mse_sample_variance = rel_mse(sample_variance.back(), ref);
  std::printf("moving camera: relMSE with one sample's variance %.5f\n", mse_sample_variance);
  EXPECT_LE(mse_denoised, 0.9 * mse_sample_variance);
  ASSERT_EQ(stats.size(), raw_stats.size());
  for (size_t f = 0; f < stats.size(); ++f) {
    EXPECT_EQ(stats[f].denoised, 1u);
    EXPECT_EQ(raw_stats[f].denoised, 0u);
    EXPECT_GT(stats[f].denoise_ms, 0.0);    // timed on the device
    EXPECT_GT(stats[f].composite_ms, 0.0);  // its own submission when denoising
    // The denoiser's passes follow the trace without the host waiting in between.
    EXPECT_EQ(stats[f].host_waits, raw_stats[f].host_waits) << "frame " << f;
  }
}

TEST(Svgf, AMovingObjectTheCameraFollowsKeepsItsHistory) {
  // A car in a racing game: the box moves 0.08 a frame and the camera moves with it, so the box
  // stays where it is on screen while its modelview changes every frame (and the floor slides
  // under it). Its history must follow it through its draw's previous modelview: over the box,
  // the denoised frame is as close to the reference as when nothing moves.
  const int frames = 16;
  auto moving = [](int frame) {
    SceneOptions o;
    o.box_x = -0.6f + 0.08f * float(frame);
    o.eye_x = o.box_x;
    return o;
  };
  const SceneOptions last = moving(frames - 1);
  const std::vector<uint8_t> ref = reference(last);
  // The box: the reference's reddish pixels.
  std::vector<uint8_t> box_mask(size_t(kSize) * kSize, 0);
  size_t box_pixels = 0;
  for (size_t i = 0; i < box_mask.size(); ++i)
    if (ref[4 * i] > ref[4 * i + 1] + 30) box_mask[i] = 1, ++box_pixels;
  ASSERT_GT(box_pixels, 200u);
  const Frames denoised = render(with(kOneSample, {}), frames, moving);
  const Frames still = render(with(kOneSample, {}), frames, [&](int) { return last; });
  // The denoiser's history alone (the anti-aliasing pass averages the still box's edges over
  // 16 frames, the moving box's light changes as it moves: it helps the still frame more).
  const Settings no_taa = with(kOneSample, {{"GLPT_TAA", "0"}});
  const Frames denoised_no_taa = render(no_taa, frames, moving);
  const Frames still_no_taa = render(no_taa, frames, [&](int) { return last; });
  const Frames raw = render(with(kOneSample, {{"GLPT_DENOISER", "off"}}), frames, moving);
  // What the denoiser makes of one frame without history: the box had it lost.
  const Frames first = render(with(kOneSample, {}), 1, [&](int) { return last; });
  keep("reference", ref);
  keep("denoised", denoised.back());
  keep("still", still.back());
  const double box_moving = rel_mse(denoised.back(), ref, &box_mask),
               box_still = rel_mse(still.back(), ref, &box_mask),
               box_raw = rel_mse(raw.back(), ref, &box_mask),
               box_first = rel_mse(first.back(), ref, &box_mask),
               box_moving_no_taa = rel_mse(denoised_no_taa.back(), ref, &box_mask),
               box_still_no_taa = rel_mse(still_no_taa.back(), ref, &box_mask);
  std::printf(
      "moving object, camera following: relMSE over the box (%zu pixels) raw %.5f, denoised "
      "%.5f (%.1fx), the same frame still %.5f, a first frame without history %.5f\n",
      box_pixels, box_raw, box_moving, box_raw / box_moving, box_still, box_first);
  std::printf("moving object, without anti-aliasing: moving %.5f, still %.5f\n", box_moving_no_taa,
              box_still_no_taa);
  EXPECT_LE(box_moving * 5.0, box_raw);
  EXPECT_LE(box_moving_no_taa, 2.0 * box_still_no_taa);  // measured 1.4x
  EXPECT_LE(box_moving * 1.5, box_first);                // measured 2.0x
  // The anti-aliasing pass follows the box as the denoiser does: no worse than without it.
  EXPECT_LE(box_moving, box_moving_no_taa);
}

TEST(Svgf, BlueNoiseOffsetsLowerTheErrorOfAFrameWithoutHistory) {
  // GLPT_BLUE_NOISE=1 (shaders/trace/rng.h): neighbouring pixels' sample points spread apart,
  // so the a-trous filter averages stratified samples. Its gain shows where no history helps:
  // the first frame (a camera cut, a disocclusion), most over the box, whose light is noisy
  // (over the whole image the filter's blur of the shadows weighs more).
  const SceneOptions still;
  const std::vector<uint8_t> ref = reference(still);
  std::vector<uint8_t> box_mask(size_t(kSize) * kSize, 0);
  for (size_t i = 0; i < box_mask.size(); ++i) box_mask[i] = ref[4 * i] > ref[4 * i + 1] + 30;
  auto first_frame = [&](Settings extra) {
    return render(with(kOneSample, extra), 1, [&](int) { return still; }).back();
  };
  const std::vector<uint8_t> white = first_frame({}),
                             blue = first_frame({{"GLPT_BLUE_NOISE", "1"}}),
                             white_raw = first_frame({{"GLPT_DENOISER", "off"}}),
                             blue_raw =
                                 first_frame({{"GLPT_BLUE_NOISE", "1"}, {"GLPT_DENOISER", "off"}});
  keep("blue_noise_first", blue);
  const double box_white = rel_mse(white, ref, &box_mask), box_blue = rel_mse(blue, ref, &box_mask);
  const double all_white = rel_mse(white, ref), all_blue = rel_mse(blue, ref);
  const double raw_white = rel_mse(white_raw, ref), raw_blue = rel_mse(blue_raw, ref);
  std::printf(
      "first frame, blue noise: relMSE over the box %.5f -> %.5f, whole image %.5f -> %.5f, raw "
      "%.5f -> %.5f\n",
      box_white, box_blue, all_white, all_blue, raw_white, raw_blue);
  // The samples are as random one by one: the raw frame's error stays what it was.
  EXPECT_LE(raw_blue, 1.2 * raw_white);
  EXPECT_LE(box_blue * 1.4, box_white);
  EXPECT_LE(all_blue, all_white);
}

// Frames from the change at frame `change` until the error against the new reference is back at
// its steady level `steady`, up to 1 % of `stale` (the error of still showing the old image):
// the residue of an exponential history. A fixed alpha of 0.2 keeps 0.8^n of the step, whose
// square falls under 1 % after about ten frames (the figure for it).
int frames_to_recover(const Frames& frames, int change, const std::vector<uint8_t>& ref,
                      double steady, double stale) {
  for (int f = change; f < int(frames.size()); ++f)
    if (rel_mse(frames[size_t(f)], ref) <= steady + 0.01 * stale) return f - change + 1;
  return int(frames.size()) - change + 1;
}

// A scene that changes at frame `change` (`at` gives each frame's state), denoised with the
// default settings, against the final state's reference; its steady level is the same denoiser
// on the final state throughout, its stale error the error of the frame before the change.
struct Change {
  int change = 0;
  Frames frames;
  std::vector<uint8_t> ref;
  double steady = 0.0, stale = 0.0;

  int recovered(const Frames& f) const { return frames_to_recover(f, change, ref, steady, stale); }
};

Change measure_change(int change, int frames, const std::function<SceneOptions(int)>& at) {
  Change c;
  c.change = change;
  const SceneOptions final_state = at(frames - 1);
  c.ref = reference(final_state);
  c.frames = render(with(kOneSample, {}), frames, at);
  c.steady =
      rel_mse(render(with(kOneSample, {}), frames, [&](int) { return final_state; }).back(), c.ref);
  c.stale = rel_mse(c.frames[size_t(change) - 1], c.ref);
  return c;
}

TEST(Svgf, ALightSwitchedOffLeavesNoStaleLightAfterFourFrames) {
  const int change = 12, frames = 26;
  auto at = [&](int frame) {
    SceneOptions o;
    o.light_on = frame < change;
    return o;
  };
  const Change c = measure_change(change, frames, at);
  const Frames plain = render(with(kOneSample, {{"GLPT_DENOISE_CLAMP", "0"}}), frames, at);
  const int recovered = c.recovered(c.frames), recovered_plain = c.recovered(plain);
  std::printf(
      "light off: steady relMSE %.5f, stale %.3f; recovered after %d frames (clamp) and "
      "%d (fixed alpha)\n",
      c.steady, c.stale, recovered, recovered_plain);
  EXPECT_LE(recovered, 4);
  EXPECT_GT(recovered_plain, recovered);
}

TEST(Svgf, ALightSwitchedOnIsSeenWithinFourFrames) {
  const Change c = measure_change(12, 26, [&](int frame) {
    SceneOptions o;
    o.light_on = frame >= 12;
    return o;
  });
  const int recovered = c.recovered(c.frames);
  std::printf("light on: steady relMSE %.5f, stale %.3f; recovered after %d frames\n", c.steady,
              c.stale, recovered);
  EXPECT_LE(recovered, 4);
}

TEST(Svgf, DisoccludedFloorRecoversWithinEightFrames) {
  // The box jumps aside: the floor it covered has no history.
  const Change c = measure_change(10, 22, [&](int frame) {
    SceneOptions o;
    o.box_x = frame < 10 ? 0.0f : 1.4f;
    return o;
  });
  const int recovered = c.recovered(c.frames);
  std::printf("disocclusion: steady relMSE %.5f, stale %.3f; recovered after %d frames\n", c.steady,
              c.stale, recovered);
  EXPECT_LE(recovered, 8);
  // And no trail of the box where it was (stale history would keep its colour there).
  EXPECT_LE(rel_mse(c.frames.back(), c.ref), 1.5 * c.steady);
}

TEST(Svgf, StillImagesConvergeToTheAccumulatedAverageAndTheDenoiserStops) {
  // With accumulation on, from GLPT_DENOISE_UNTIL samples on the accumulated average alone is
  // shown: the image equals the one without denoiser, and the denoiser no longer runs.
  std::vector<glpt::rt::FrameStats> stats;
  const SceneOptions still;
  // (Without the anti-aliasing pass: the accumulation starts again at the second frame, whose
  // signature differs from the first's, and the pass, which has a history by then, jitters that
  // first accumulated frame where the accumulation alone does not: the two averages hold
  // different samples.)
  const Frames denoised = render(
      path({{"GLPT_DENOISE_UNTIL", "8"}, {"GLPT_TAA", "0"}}), 10, [&](int) { return still; },
      &stats);
  const Frames raw = render(path({{"GLPT_DENOISER", "off"}}), 10, [&](int) { return still; });
  EXPECT_EQ(stats.front().denoised, 1u);
  EXPECT_EQ(stats.back().denoised, 0u);
  EXPECT_EQ(denoised.back(), raw.back());
}

TEST(Svgf, GlsOwnLightingHasNoNoiseAndIsNotDenoised) {
  // GL parity (no shadows, bounces or AO) evaluates GL's equation once per pixel: the denoiser
  // has nothing to filter, does not run, and the image is the one without it.
  std::vector<glpt::rt::FrameStats> stats;
  const SceneOptions still;
  const Settings parity = {
      {"GLPT_SHADOWS", "0"}, {"GLPT_BOUNCES", "0"}, {"GLPT_AO", "0"}, {"GLPT_ACCUMULATE", "0"}};
  const Frames denoised = render(
      with(parity, {}), 3, [&](int) { return still; }, &stats);
  const Frames raw =
      render(with(parity, {{"GLPT_DENOISER", "off"}}), 3, [&](int) { return still; });
  for (const glpt::rt::FrameStats& s : stats) EXPECT_EQ(s.denoised, 0u);
  EXPECT_EQ(denoised.back(), raw.back());
}

// Item 1's deformed geometry: a program that transforms its vertices by the camera itself (an
// identity modelview, new eye-space positions every frame: every draw deforms, its BLAS refit)
// while the camera rises. Through its triangles' previous vertices the history follows the
// surfaces as it does when the camera is in the modelview; without that correspondence
// (GLPT_DENOISE_VERTEX_MOTION=0) each pixel looks for its history where the surface was not, and
// the floor (moving along its normal in eye space) loses it every frame.
TEST(Svgf, ACameraInTheVerticesKeepsTheHistoryThroughThePreviousVertices) {
  const int frames = 12;
  auto in_vertices = [](int frame) {
    SceneOptions o;
    o.eye_y = 3.0f + 0.12f * float(frame);
    o.camera_in_vertices = true;
    return o;
  };
  auto in_modelview = [&](int frame) {
    SceneOptions o = in_vertices(frame);
    o.camera_in_vertices = false;
    return o;
  };
  const std::vector<uint8_t> ref = reference(in_modelview(frames - 1));
  std::vector<glpt::rt::FrameStats> stats;
  const Frames through_vertices = render(with(kOneSample, {}), frames, in_vertices, &stats);
  const Frames without =
      render(with(kOneSample, {{"GLPT_DENOISE_VERTEX_MOTION", "0"}}), frames, in_vertices);
  const Frames through_modelview = render(with(kOneSample, {}), frames, in_modelview);
  const Frames raw = render(with(kOneSample, {{"GLPT_DENOISER", "off"}}), frames, in_vertices);
  // Built anew every frame instead of refit: the previous shape's positions still come along
  // (BlasCache::keep_previous_positions, reordered into the new BLAS's triangle order).
  const Frames rebuilt = render(with(kOneSample, {{"GLPT_BLAS_REFIT", "0"}}), frames, in_vertices);
  keep("reference", ref);
  keep("vertices", through_vertices.back());
  keep("without", without.back());
  keep("modelview", through_modelview.back());
  const double e_vertices = rel_mse(through_vertices.back(), ref),
               e_without = rel_mse(without.back(), ref),
               e_modelview = rel_mse(through_modelview.back(), ref),
               e_raw = rel_mse(raw.back(), ref), e_rebuilt = rel_mse(rebuilt.back(), ref);
  std::printf(
      "camera in the vertices, rising: relMSE raw %.5f, without vertex motion %.5f, through the "
      "previous vertices %.5f (%.2fx lower; BLASes built anew %.5f), camera in the modelview "
      "%.5f\n",
      e_raw, e_without, e_vertices, e_without / e_vertices, e_rebuilt, e_modelview);
  uint32_t refits = 0;
  for (size_t f = 2; f < stats.size(); ++f) refits += stats[f].blas_refits;
  EXPECT_GT(refits, 0u) << "the draws' new positions must refit their BLASes";
  EXPECT_LE(e_vertices * 1.5, e_without);
  EXPECT_LE(e_vertices, e_modelview * 1.25);
  EXPECT_LE(e_rebuilt * 1.5, e_without);
}

TEST(Svgf, ANewSizeAndACameraCutEveryFrameStartWithoutHistory) {
  // A new size every frame (a new drawable each time) and a cut every frame: no history may be
  // reused across them; each image shows the scene (not black, not a previous frame's pixels).
  for (int frame = 0; frame < 6; ++frame) {
    SceneOptions o;
    o.eye_x = (frame % 2 == 0) ? -2.0f : 2.0f;
    const int size = 48 + 8 * frame;
    const std::vector<uint8_t> image = glpt::test::render_headless(
        size, with(kOneSample, {}), [&] { draw_scene(o); }, 2, "cut");
    double sum = 0.0;
    for (size_t i = 0; i < image.size(); i += 4) sum += image[i];
    EXPECT_GT(sum, 0.0) << "frame " << frame;
  }
  // Cuts within one drawable: every frame's error stays near one raw frame's, never the
  // previous view's.
  auto at = [](int frame) {
    SceneOptions o;
    o.eye_x = (frame % 2 == 0) ? -2.0f : 2.0f;
    return o;
  };
  const Frames cuts = render(with(kOneSample, {}), 6, at);
  const std::vector<uint8_t> ref_left = reference(at(0)), ref_right = reference(at(1));
  for (int f = 1; f < 6; ++f) {
    const std::vector<uint8_t>& ref = f % 2 == 0 ? ref_left : ref_right;
    const std::vector<uint8_t>& other = f % 2 == 0 ? ref_right : ref_left;
    EXPECT_LT(rel_mse(cuts[size_t(f)], ref) * 4.0, rel_mse(cuts[size_t(f)], other))
        << "frame " << f << " looks like the other view";
  }
}

}  // namespace
