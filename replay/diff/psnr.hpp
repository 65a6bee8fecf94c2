// Peak signal-to-noise ratio and relative mean squared error of two 8-bit images, for reports
// next to FLIP.
#pragma once

#include "flip.hpp"

namespace glpt::diff {

// PSNR in dB over the R, G and B channels (alpha ignored): 10 log10(255^2 / MSE), the mean
// squared error taken over all 3 * width * height channel values. Identical images give
// +infinity. The views must have the same size (checked by the caller; see compute_flip).
double psnr_rgb8(const Rgb8View& a, const Rgb8View& b);

// relMSE of `test` against `reference` (Rousselle et al. 2011): the mean over R, G and B values
// in [0, 1] of (test - reference)^2 / (reference^2 + 0.01), so an error weighs by how bright the
// reference is there (0.01 keeps black pixels finite). Same-size views, as psnr_rgb8.
double relmse_rgb8(const Rgb8View& test, const Rgb8View& reference);

}  // namespace glpt::diff
