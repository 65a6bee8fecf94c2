// Image comparisons for glpt's end-to-end and conformance tests: coverage masks and their IoU,
// "lit vs away" shading checks against a facing oracle, per-channel tolerance against a
// reference image, PSNR, and a blank-frame check. The CLI
// glpt_imgcompare is a thin wrapper; the unit tests exercise these functions directly.
#pragma once

#include <cstdint>
#include <string>

#include "image_io.hpp"

namespace glpt::imgcompare {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
};

// Parses "R,G,B" (each 0..255). Returns false on malformed input.
bool parse_rgb(const std::string& text, Rgb* out);

// A pixel (RGBA, alpha ignored) is "covered" when some colour channel differs from the
// background by more than `tolerance` (0..255).
bool is_covered(const uint8_t* rgba, Rgb background, int tolerance);

// Rec. 709 luma of the 8-bit (sRGB-encoded) values, in 0..1. No linearisation: the checks only
// compare luminances of the same image, so the encoding does not matter.
double luminance(const uint8_t* rgba);

struct CoverageResult {
  uint64_t only_a = 0, only_b = 0, both = 0, neither = 0;
  // both / (only_a + only_b + both); 0 when neither image covers any pixel (nothing to compare
  // is a failure for a test, not a perfect match).
  double iou = 0.0;
};

// Compares the coverage masks of `a` and `b` (same size required). If `diff` is non-null it
// receives a visualisation: red = covered only in A, green = only in B, white = both,
// black = neither.
bool coverage(const ImageRGBA8& a, const ImageRGBA8& b, Rgb background, int tolerance,
              CoverageResult* out, ImageRGBA8* diff, std::string* error);

struct LitAwayOptions {
  int tolerance = 24;                // coverage tolerance, as for coverage()
  double lit_threshold = 0.25;       // facing luminance above this: the face turns to the light
  double away_threshold = 0.02;      // facing luminance below this: the face turns away
  double min_class_fraction = 0.01;  // each class needs this fraction of the covered pixels
  double min_margin = 0.05;          // mean(lit) - mean(away) in the shaded image, at least
  double min_ratio = 1.5;            // mean(lit) / mean(away) in the shaded image, at least
};

struct LitAwayResult {
  uint64_t covered = 0;  // covered in both FACING and SHADED
  uint64_t lit = 0, away = 0;
  double mean_lit = 0.0, mean_away = 0.0;  // mean luminance of SHADED over each class
  bool pass = false;
  std::string reason;  // why it failed (empty on success)
};

// Classifies the pixels covered in both images by the FACING oracle's luminance and checks that
// SHADED is brighter where faces turn toward the light than where they turn away.
bool lit_vs_away(const ImageRGBA8& shaded, const ImageRGBA8& facing, Rgb background,
                 const LitAwayOptions& options, LitAwayResult* out, std::string* error);

struct WithinResult {
  uint64_t pixels = 0;
  uint64_t within = 0;    // pixels whose R, G, B and A all differ by at most the tolerance
  double fraction = 0.0;  // within / pixels
  int max_diff = 0;       // the largest difference of any channel of any pixel, 0..255
};

// Compares `test` with `reference` channel by channel (RGBA: alpha is part of what GL returns).
// If `diff` is non-null it receives a visualisation four panels wide (see kDiffPanels).
bool within_tolerance(const ImageRGBA8& reference, const ImageRGBA8& test, int max_channel_diff,
                      WithinResult* out, ImageRGBA8* diff, std::string* error);

// The panels of within_tolerance's difference image, left to right.
inline constexpr const char* kDiffPanels =
    "reference (opaque) | test (opaque) | |reference - test| of RGB x16 | mask: red = outside "
    "the tolerance, blue = differs within it, grey = identical (the reference, dimmed)";

// PSNR over the RGB channels in dB (peak 255); +infinity for identical images.
bool psnr(const ImageRGBA8& a, const ImageRGBA8& b, double* out, std::string* error);

// Fraction of pixels whose RGB differs from the top-left pixel by more than `tolerance`.
double fraction_differing_from_corner(const ImageRGBA8& image, int tolerance);

}  // namespace glpt::imgcompare
