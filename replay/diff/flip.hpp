// LDR-FLIP: the perceptual difference between two 8-bit sRGB images, as a per-pixel error in
// [0, 1] and its mean.
//
// Implemented from the papers: P. Andersson, J. Nilsson, T. Akenine-Möller, M. Oskarsson,
// K. Åström, M. D. Fairchild, "FLIP: A Difference Evaluator for Alternating Images", HPG 2020,
// and the FLIP chapter of Ray Tracing Gems II (2021). docs/image-diff.md explains the steps and
// how the results were checked against NVlabs' reference implementation.
//
// Pure computation: no I/O, no global state, thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace glpt::diff {

// Pixels per degree of visual angle for an observer `distance_m` metres from a monitor
// `width_m` metres wide showing `width_px` pixels across.
double pixels_per_degree(double distance_m, double width_m, double width_px);

// The paper's default observer: 0.7 m from a 0.7 m wide monitor with 3840 pixels across,
// about 67.02 pixels per degree.
double default_pixels_per_degree();

// A read-only view of an 8-bit sRGB image, rows top first, `channels` bytes per pixel (3: RGB,
// 4: RGBA; alpha is ignored, as FLIP compares opaque colours), no row padding.
struct Rgb8View {
  uint32_t width = 0, height = 0;
  uint32_t channels = 3;
  const uint8_t* pixels = nullptr;  // width * height * channels bytes
};

struct FlipResult {
  uint32_t width = 0, height = 0;
  std::vector<float> error;  // width * height values in [0, 1], rows top first
  double mean = 0.0;
  double max = 0.0;
};

// Computes LDR-FLIP of `test` against `reference` for an observer at `pixels_per_degree`.
// Returns false and sets *error (if non-null) when the sizes differ, an image is empty or a
// view is malformed (channels not 3 or 4, null pixels), or pixels_per_degree is not a positive
// finite number; *out is then unspecified.
bool compute_flip(const Rgb8View& reference, const Rgb8View& test, double pixels_per_degree,
                  FlipResult* out, std::string* error);

// The fraction of `result`'s pixels whose FLIP value is strictly greater than `tolerance`.
double fraction_over(const FlipResult& result, double tolerance);

}  // namespace glpt::diff
