// LDR-FLIP, PSNR and the heat map on images whose answers are known by hand.
#include "flip.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "heatmap.hpp"
#include "psnr.hpp"

namespace glpt::diff {
namespace {

using Rgb = std::array<uint8_t, 3>;

std::vector<uint8_t> uniform(uint32_t w, uint32_t h, Rgb c) {
  std::vector<uint8_t> p;
  for (uint32_t i = 0; i < w * h; ++i) p.insert(p.end(), c.begin(), c.end());
  return p;
}

// A deterministic test picture with edges, points and colour.
std::vector<uint8_t> pattern(uint32_t w, uint32_t h, int seed) {
  std::vector<uint8_t> p;
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const int v = ((x / 5 + y / 7 + seed) % 3) * 120;
      p.push_back(static_cast<uint8_t>(v));
      p.push_back(static_cast<uint8_t>((x * 7 + seed * 31) % 256));
      p.push_back(static_cast<uint8_t>((y * 11) % 256));
    }
  }
  return p;
}

Rgb8View view(uint32_t w, uint32_t h, const std::vector<uint8_t>& p, uint32_t channels = 3) {
  return {w, h, channels, p.data()};
}

TEST(Flip, DefaultPixelsPerDegreeIsThePapers) {
  // 0.7 m from a 0.7 m wide, 3840 px monitor: 3840 px/m * 0.7 m * pi/180 per degree.
  EXPECT_NEAR(default_pixels_per_degree(), 3840.0 * std::numbers::pi / 180.0, 1e-9);
  EXPECT_NEAR(default_pixels_per_degree(), 67.0206, 1e-4);
  EXPECT_NEAR(pixels_per_degree(1.4, 0.7, 3840), 2 * default_pixels_per_degree(), 1e-9);
}

TEST(Flip, IdenticalImagesGiveZeroEverywhere) {
  const std::vector<uint8_t> img = pattern(40, 30, 1);
  FlipResult r;
  std::string error;
  ASSERT_TRUE(compute_flip(view(40, 30, img), view(40, 30, img), 67.0, &r, &error)) << error;
  ASSERT_EQ(r.error.size(), 40u * 30u);
  EXPECT_EQ(r.width, 40u);
  EXPECT_EQ(r.height, 30u);
  for (float e : r.error) ASSERT_EQ(e, 0.0f);
  EXPECT_EQ(r.mean, 0.0);
  EXPECT_EQ(r.max, 0.0);
  EXPECT_EQ(fraction_over(r, 0.0), 0.0);
}

TEST(Flip, IsSymmetricAndInUnitRange) {
  const std::vector<uint8_t> a = pattern(33, 21, 0), b = pattern(33, 21, 1);
  FlipResult ab, ba;
  ASSERT_TRUE(compute_flip(view(33, 21, a), view(33, 21, b), 40.0, &ab, nullptr));
  ASSERT_TRUE(compute_flip(view(33, 21, b), view(33, 21, a), 40.0, &ba, nullptr));
  for (size_t i = 0; i < ab.error.size(); ++i) {
    ASSERT_NEAR(ab.error[i], ba.error[i], 1e-6);
    ASSERT_GE(ab.error[i], 0.0f);
    ASSERT_LE(ab.error[i], 1.0f);
  }
  EXPECT_GT(ab.mean, 0.0);
}

TEST(Flip, AlphaIsIgnored) {
  const std::vector<uint8_t> a = pattern(16, 12, 0), b = pattern(16, 12, 2);
  std::vector<uint8_t> a4, b4;
  for (size_t i = 0; i < a.size(); i += 3) {
    a4.insert(a4.end(), {a[i], a[i + 1], a[i + 2], 255});
    b4.insert(b4.end(), {b[i], b[i + 1], b[i + 2], static_cast<uint8_t>(i % 256)});
  }
  FlipResult rgb, rgba;
  ASSERT_TRUE(compute_flip(view(16, 12, a), view(16, 12, b), 67.0, &rgb, nullptr));
  ASSERT_TRUE(compute_flip(view(16, 12, a4, 4), view(16, 12, b4, 4), 67.0, &rgba, nullptr));
  EXPECT_EQ(rgb.error, rgba.error);
}

TEST(Flip, RejectsBadInput) {
  const std::vector<uint8_t> a = uniform(8, 8, {0, 0, 0}), b = uniform(8, 4, {0, 0, 0});
  FlipResult r;
  std::string error;
  EXPECT_FALSE(compute_flip(view(8, 8, a), view(8, 4, b), 67.0, &r, &error));
  EXPECT_NE(error.find("8x8"), std::string::npos) << error;
  EXPECT_NE(error.find("8x4"), std::string::npos) << error;
  EXPECT_FALSE(compute_flip(view(8, 8, a), view(8, 8, a), 0.0, &r, &error));
  EXPECT_FALSE(compute_flip(view(8, 8, a), view(8, 8, a), -3.0, &r, &error));
  EXPECT_FALSE(compute_flip(view(8, 8, a), view(8, 8, a), std::numeric_limits<double>::quiet_NaN(),
                            &r, &error));
  EXPECT_FALSE(compute_flip(view(0, 0, a), view(0, 0, a), 67.0, &r, &error));
  EXPECT_FALSE(compute_flip(view(8, 8, a, 2), view(8, 8, a, 2), 67.0, &r, &error));
  EXPECT_FALSE(compute_flip({8, 8, 3, nullptr}, view(8, 8, a), 67.0, &r, &error));
}

// The value the paper's colour pipeline gives for two uniform colours, derived here step by
// step in double precision from the textbook definitions (sRGB decoding, the sRGB-to-XYZ matrix
// of IEC 61966-2-1, CIELAB with the D65 white, Hunt adjustment, HyAB, q_c = 0.7, p_c = 0.4,
// p_t = 0.95, c_max between green and blue). On uniform images the CSF filters (normalized to
// 1) change nothing and the edge and point detectors (whose weights sum to 0) see nothing, so
// FLIP is exactly this colour error at every pixel.
double paper_uniform_flip(Rgb a, Rgb b) {
  constexpr double m[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                              {0.2126729, 0.7151522, 0.0721750},
                              {0.0193339, 0.1191920, 0.9503041}};
  auto lab_hunt = [&](Rgb c) {
    double lin[3], xyz[3], white[3];
    for (int i = 0; i < 3; ++i) {
      const double s = c[i] / 255.0;
      lin[i] = s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
    }
    for (int i = 0; i < 3; ++i) {
      xyz[i] = m[i][0] * lin[0] + m[i][1] * lin[1] + m[i][2] * lin[2];
      white[i] = m[i][0] + m[i][1] + m[i][2];
    }
    auto f = [](double t) {
      const double d = 6.0 / 29.0;
      return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
    const double l = 116 * fy - 16;
    return std::array<double, 3>{l, l / 100 * 500 * (fx - fy), l / 100 * 200 * (fy - fz)};
  };
  auto hyab = [](std::array<double, 3> p, std::array<double, 3> q) {
    return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
  };
  const double c_max = std::pow(hyab(lab_hunt({0, 255, 0}), lab_hunt({0, 0, 255})), 0.7);
  const double d = std::pow(hyab(lab_hunt(a), lab_hunt(b)), 0.7);
  const double cut = 0.4 * c_max;
  return d < cut ? d * 0.95 / cut : 0.95 + (d - cut) / (c_max - cut) * 0.05;
}

struct UniformCase {
  Rgb a, b;
  double by_hand;  // computed with pencil and calculator from the same formulas
};

class FlipUniform : public ::testing::TestWithParam<UniformCase> {};

TEST_P(FlipUniform, EqualsThePapersColourFormula) {
  const UniformCase& c = GetParam();
  const double expected = paper_uniform_flip(c.a, c.b);
  EXPECT_NEAR(expected, c.by_hand, 2e-3);  // the derivation above, checked by hand
  const std::vector<uint8_t> a = uniform(24, 20, c.a), b = uniform(24, 20, c.b);
  FlipResult r;
  ASSERT_TRUE(compute_flip(view(24, 20, a), view(24, 20, b), 67.0, &r, nullptr));
  for (float e : r.error) ASSERT_NEAR(e, expected, 5e-4);
  EXPECT_NEAR(r.mean, expected, 5e-4);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FlipUniform,
    ::testing::Values(
        // A full-contrast difference in a single channel: black against pure red, green,
        // blue (errors above p_c * c_max, the compressed (p_t, 1] part of the range).
        UniformCase{{0, 0, 0}, {255, 0, 0}, 0.9705}, UniformCase{{0, 0, 0}, {0, 255, 0}, 0.9970},
        UniformCase{{0, 0, 0}, {0, 0, 255}, 0.9583},
        // Two 8-bit steps of mid grey: the linear [0, p_t] part.
        UniformCase{{128, 128, 128}, {130, 130, 130}, 0.0485}));

TEST(Flip, FractionOverCountsStrictlyGreater) {
  FlipResult r;
  r.error = {0.0f, 0.05f, 0.06f, 1.0f};
  EXPECT_DOUBLE_EQ(fraction_over(r, 0.05), 0.5);
  EXPECT_DOUBLE_EQ(fraction_over(r, 0.0), 0.75);
  EXPECT_DOUBLE_EQ(fraction_over(FlipResult{}, 0.0), 0.0);
}

TEST(Psnr, IdenticalImagesAreInfinite) {
  const std::vector<uint8_t> img = pattern(10, 10, 3);
  EXPECT_TRUE(std::isinf(psnr_rgb8(view(10, 10, img), view(10, 10, img))));
}

TEST(Psnr, OneChannelOfOnePixel) {
  // 2x2 RGB: 12 channel values, one differs by 255: MSE = 255^2 / 12, PSNR = 10 log10(12).
  std::vector<uint8_t> a = uniform(2, 2, {10, 20, 30}), b = a;
  b[4] = 255;
  a[4] = 0;
  std::vector<uint8_t> a_same = a;
  a_same[4] = 255;
  EXPECT_NEAR(psnr_rgb8(view(2, 2, a), view(2, 2, b)), 10.0 * std::log10(12.0), 1e-9);
  EXPECT_TRUE(std::isinf(psnr_rgb8(view(2, 2, a_same), view(2, 2, b))));
}

TEST(Psnr, IgnoresAlpha) {
  std::vector<uint8_t> a = {1, 2, 3, 0, 4, 5, 6, 0}, b = {1, 2, 3, 255, 4, 5, 6, 9};
  EXPECT_TRUE(std::isinf(psnr_rgb8(view(2, 1, a, 4), view(2, 1, b, 4))));
}

TEST(Heatmap, BlackAtZeroBrighterWithError) {
  uint8_t c[3];
  heatmap_color(0.0f, c);
  EXPECT_LE(c[0] + c[1] + c[2], 10);
  double last_luma = -1;
  for (int i = 0; i <= 100; ++i) {
    heatmap_color(i / 100.0f, c);
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GE(luma, last_luma) << "at " << i / 100.0;
    last_luma = luma;
  }
  uint8_t over[3], one[3];
  heatmap_color(7.0f, over);
  heatmap_color(1.0f, one);
  EXPECT_EQ(std::vector<uint8_t>(over, over + 3), std::vector<uint8_t>(one, one + 3));
}

TEST(Heatmap, OpaqueOnePixelPerValue) {
  FlipResult r;
  r.width = 3;
  r.height = 1;
  r.error = {0.0f, 0.5f, 1.0f};
  const std::vector<uint8_t> rgba = heatmap_rgba8(r);
  ASSERT_EQ(rgba.size(), 12u);
  for (int i = 0; i < 3; ++i) {
    uint8_t c[3];
    heatmap_color(r.error[i], c);
    EXPECT_EQ(rgba[i * 4 + 0], c[0]);
    EXPECT_EQ(rgba[i * 4 + 1], c[1]);
    EXPECT_EQ(rgba[i * 4 + 2], c[2]);
    EXPECT_EQ(rgba[i * 4 + 3], 255);
  }
}

}  // namespace
}  // namespace glpt::diff
