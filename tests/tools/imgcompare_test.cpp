#include "imgcompare.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace glpt::imgcompare {
namespace {

constexpr Rgb kBg{64, 0, 64};

ImageRGBA8 filled(uint32_t w, uint32_t h, Rgb c) {
  ImageRGBA8 img;
  img.width = w;
  img.height = h;
  img.pixels.resize(size_t{w} * h * 4);
  for (size_t i = 0; i < img.pixels.size(); i += 4) {
    img.pixels[i] = c.r;
    img.pixels[i + 1] = c.g;
    img.pixels[i + 2] = c.b;
    img.pixels[i + 3] = 255;
  }
  return img;
}

void paint(ImageRGBA8* img, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1, Rgb c) {
  for (uint32_t y = y0; y < y1; ++y) {
    for (uint32_t x = x0; x < x1; ++x) {
      uint8_t* p = &img->pixels[(size_t{y} * img->width + x) * 4];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
    }
  }
}

TEST(ParseRgb, AcceptsTripletsAndRejectsJunk) {
  Rgb c;
  ASSERT_TRUE(parse_rgb("64,0,255", &c));
  EXPECT_EQ(c.r, 64);
  EXPECT_EQ(c.g, 0);
  EXPECT_EQ(c.b, 255);
  EXPECT_FALSE(parse_rgb("64,0", &c));
  EXPECT_FALSE(parse_rgb("64,0,256", &c));
  EXPECT_FALSE(parse_rgb("64,0,1,2", &c));
  EXPECT_FALSE(parse_rgb("a,b,c", &c));
  EXPECT_FALSE(parse_rgb("", &c));
}

TEST(Coverage, ToleranceIsAStrictMaxChannelBound) {
  const uint8_t at_tol[4] = {64 + 10, 0, 64, 255};
  const uint8_t above[4] = {64, 11, 64, 255};
  EXPECT_FALSE(is_covered(at_tol, kBg, 10));
  EXPECT_TRUE(is_covered(above, kBg, 10));
}

TEST(Coverage, IouOfKnownMasks) {
  // A covers columns 0..5 of rows 0..9 (60 px), B covers columns 2..7 (60 px): overlap 40 px,
  // union 80 px, IoU 0.5.
  ImageRGBA8 a = filled(10, 10, kBg), b = filled(10, 10, kBg);
  paint(&a, 0, 0, 6, 10, Rgb{200, 10, 0});
  paint(&b, 2, 0, 8, 10, Rgb{0, 200, 40});
  CoverageResult r;
  ImageRGBA8 diff;
  std::string error;
  ASSERT_TRUE(coverage(a, b, kBg, 24, &r, &diff, &error)) << error;
  EXPECT_EQ(r.both, 40u);
  EXPECT_EQ(r.only_a, 20u);
  EXPECT_EQ(r.only_b, 20u);
  EXPECT_EQ(r.neither, 20u);
  EXPECT_DOUBLE_EQ(r.iou, 0.5);
  // Diff colours: (0,0) only A = red, (4,0) both = white, (7,0) only B = green, (9,0) neither.
  EXPECT_EQ(diff.pixels[0 * 4 + 0], 255);
  EXPECT_EQ(diff.pixels[0 * 4 + 1], 0);
  EXPECT_EQ(diff.pixels[4 * 4 + 1], 255);
  EXPECT_EQ(diff.pixels[4 * 4 + 2], 255);
  EXPECT_EQ(diff.pixels[7 * 4 + 0], 0);
  EXPECT_EQ(diff.pixels[7 * 4 + 1], 255);
  EXPECT_EQ(diff.pixels[9 * 4 + 0], 0);
  EXPECT_EQ(diff.pixels[9 * 4 + 1], 0);
}

TEST(Coverage, IdenticalMasksGiveOneAndEmptyMasksGiveZero) {
  ImageRGBA8 a = filled(8, 8, kBg);
  paint(&a, 1, 1, 5, 5, Rgb{10, 10, 200});
  ImageRGBA8 b = a;
  paint(&b, 1, 1, 5, 5, Rgb{200, 200, 200});  // different colour, same coverage
  CoverageResult r;
  std::string error;
  ASSERT_TRUE(coverage(a, b, kBg, 24, &r, nullptr, &error));
  EXPECT_DOUBLE_EQ(r.iou, 1.0);
  const ImageRGBA8 empty = filled(8, 8, kBg);
  ASSERT_TRUE(coverage(empty, empty, kBg, 24, &r, nullptr, &error));
  EXPECT_DOUBLE_EQ(r.iou, 0.0);  // nothing to compare is not a match
}

TEST(Coverage, SizeMismatchIsAnError) {
  CoverageResult r;
  std::string error;
  EXPECT_FALSE(coverage(filled(4, 4, kBg), filled(4, 5, kBg), kBg, 24, &r, nullptr, &error));
  EXPECT_NE(error.find("sizes differ"), std::string::npos);
}

// Facing oracle: left half lit (white), right half away (black); a background border.
ImageRGBA8 facing_oracle() {
  ImageRGBA8 f = filled(20, 10, kBg);
  paint(&f, 2, 2, 10, 8, Rgb{230, 230, 230});
  paint(&f, 10, 2, 18, 8, Rgb{0, 0, 0});
  return f;
}

TEST(LitVsAway, PassesWhenLitFacesAreBrighter) {
  ImageRGBA8 shaded = filled(20, 10, kBg);
  paint(&shaded, 2, 2, 10, 8, Rgb{200, 20, 0});  // lit red
  paint(&shaded, 10, 2, 18, 8, Rgb{40, 5, 0});   // ambient-only red
  LitAwayResult r;
  std::string error;
  ASSERT_TRUE(lit_vs_away(shaded, facing_oracle(), kBg, LitAwayOptions{}, &r, &error)) << error;
  EXPECT_EQ(r.covered, 96u);
  EXPECT_EQ(r.lit, 48u);
  EXPECT_EQ(r.away, 48u);
  EXPECT_NEAR(r.mean_lit, (0.2126 * 200 + 0.7152 * 20) / 255.0, 1e-9);
  EXPECT_NEAR(r.mean_away, (0.2126 * 40 + 0.7152 * 5) / 255.0, 1e-9);
  EXPECT_TRUE(r.pass) << r.reason;
}

TEST(LitVsAway, FailsWhenLightingIsInverted) {
  ImageRGBA8 shaded = filled(20, 10, kBg);
  paint(&shaded, 2, 2, 10, 8, Rgb{40, 5, 0});
  paint(&shaded, 10, 2, 18, 8, Rgb{200, 20, 0});
  LitAwayResult r;
  std::string error;
  ASSERT_TRUE(lit_vs_away(shaded, facing_oracle(), kBg, LitAwayOptions{}, &r, &error));
  EXPECT_FALSE(r.pass);
  EXPECT_LT(r.mean_lit, r.mean_away);
}

TEST(LitVsAway, FailsWhenShadingIsFlat) {
  // Constant colour everywhere: no difference between the classes.
  ImageRGBA8 shaded = filled(20, 10, kBg);
  paint(&shaded, 2, 2, 18, 8, Rgb{120, 120, 120});
  LitAwayResult r;
  std::string error;
  ASSERT_TRUE(lit_vs_away(shaded, facing_oracle(), kBg, LitAwayOptions{}, &r, &error));
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.reason.find("margin"), std::string::npos) << r.reason;
}

TEST(LitVsAway, FailsWithoutAnAwayClass) {
  ImageRGBA8 facing = filled(20, 10, kBg);
  paint(&facing, 2, 2, 18, 8, Rgb{230, 230, 230});
  LitAwayResult r;
  std::string error;
  ASSERT_TRUE(lit_vs_away(facing, facing, kBg, LitAwayOptions{}, &r, &error));
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.reason.find("away"), std::string::npos) << r.reason;
}

TEST(LitVsAway, IgnoresPixelsMissingFromTheShadedImage) {
  // A shaded image with nothing drawn has no pixel covered in both: it must fail.
  LitAwayResult r;
  std::string error;
  ASSERT_TRUE(lit_vs_away(filled(20, 10, kBg), facing_oracle(), kBg, LitAwayOptions{}, &r, &error));
  EXPECT_EQ(r.covered, 0u);
  EXPECT_FALSE(r.pass);
}

TEST(Psnr, IdenticalIsInfinite) {
  const ImageRGBA8 a = filled(5, 5, Rgb{1, 2, 3});
  double db = 0.0;
  std::string error;
  ASSERT_TRUE(psnr(a, a, &db, &error));
  EXPECT_TRUE(std::isinf(db) && db > 0);
}

TEST(Psnr, KnownError) {
  // Every channel off by 1: MSE 1, PSNR = 20 log10(255) = 48.1308 dB. Alpha is ignored.
  ImageRGBA8 a = filled(5, 5, Rgb{10, 20, 30}), b = filled(5, 5, Rgb{11, 21, 31});
  b.pixels[3] = 0;
  double db = 0.0;
  std::string error;
  ASSERT_TRUE(psnr(a, b, &db, &error));
  EXPECT_NEAR(db, 20.0 * std::log10(255.0), 1e-9);
}

TEST(Within, CountsPixelsWithEveryChannelInsideTheTolerance) {
  // 10x10: 90 pixels identical, 5 off by exactly 2 in green (within), 4 off by 3 in blue and 1
  // off by 40 in alpha only (both outside): 95% within, largest difference 40.
  ImageRGBA8 ref = filled(10, 10, Rgb{100, 100, 100}), test = ref;
  for (int i = 0; i < 5; ++i) test.pixels[i * 4 + 1] = 102;
  for (int i = 5; i < 9; ++i) test.pixels[i * 4 + 2] = 97;
  test.pixels[9 * 4 + 3] = 215;
  WithinResult r;
  std::string error;
  ASSERT_TRUE(within_tolerance(ref, test, 2, &r, nullptr, &error));
  EXPECT_EQ(r.pixels, 100u);
  EXPECT_EQ(r.within, 95u);
  EXPECT_DOUBLE_EQ(r.fraction, 0.95);
  EXPECT_EQ(r.max_diff, 40);
  ASSERT_TRUE(within_tolerance(ref, test, 3, &r, nullptr, &error));
  EXPECT_EQ(r.within, 99u);
  ASSERT_TRUE(within_tolerance(ref, ref, 0, &r, nullptr, &error));
  EXPECT_EQ(r.within, 100u);
  EXPECT_EQ(r.max_diff, 0);
}

TEST(Within, DiffImageShowsBothInputsTheDifferenceAndTheMask) {
  ImageRGBA8 ref = filled(4, 2, Rgb{40, 80, 120}), test = ref;
  test.pixels[0] = 50;  // pixel (0,0): red off by 10, outside a tolerance of 2
  test.pixels[5] = 81;  // pixel (1,0): green off by 1, within
  WithinResult r;
  ImageRGBA8 diff;
  std::string error;
  ASSERT_TRUE(within_tolerance(ref, test, 2, &r, &diff, &error));
  ASSERT_EQ(diff.width, 16u);
  ASSERT_EQ(diff.height, 2u);
  const auto px = [&](uint32_t x, uint32_t y) { return &diff.pixels[(y * diff.width + x) * 4]; };
  EXPECT_EQ(px(0, 0)[0], 40);   // reference panel
  EXPECT_EQ(px(4, 0)[0], 50);   // test panel
  EXPECT_EQ(px(8, 0)[0], 160);  // |difference| x16
  EXPECT_EQ(px(9, 0)[1], 16);
  EXPECT_EQ(px(10, 0)[0], 0);
  EXPECT_EQ(px(12, 0)[0], 255);  // mask: outside the tolerance is red
  EXPECT_EQ(px(12, 0)[1], 0);
  EXPECT_EQ(px(13, 0)[2], 255);  // within but different is blue
  EXPECT_EQ(px(13, 0)[0], 0);
  EXPECT_EQ(px(14, 0)[0], px(14, 0)[2]);  // identical is grey
  EXPECT_LT(px(14, 0)[0], 64);
  for (size_t i = 3; i < diff.pixels.size(); i += 4) EXPECT_EQ(diff.pixels[i], 255);
}

TEST(Within, SizeMismatchIsAnError) {
  WithinResult r;
  std::string error;
  EXPECT_FALSE(within_tolerance(filled(4, 4, kBg), filled(4, 5, kBg), 2, &r, nullptr, &error));
  EXPECT_FALSE(error.empty());
}

TEST(Nonblank, CountsPixelsDifferentFromTheCorner) {
  ImageRGBA8 img = filled(10, 10, kBg);
  EXPECT_DOUBLE_EQ(fraction_differing_from_corner(img, 0), 0.0);
  paint(&img, 0, 5, 10, 10, Rgb{64, 1, 64});
  EXPECT_DOUBLE_EQ(fraction_differing_from_corner(img, 0), 0.5);
  EXPECT_DOUBLE_EQ(fraction_differing_from_corner(img, 1), 0.0);
}

}  // namespace
}  // namespace glpt::imgcompare
