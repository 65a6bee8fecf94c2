// Peak signal-to-noise ratio of two 8-bit images, for reports next to FLIP.
#pragma once

#include "flip.hpp"

namespace glpt::diff {

// PSNR in dB over the R, G and B channels (alpha ignored): 10 log10(255^2 / MSE), the mean
// squared error taken over all 3 * width * height channel values. Identical images give
// +infinity. The views must have the same size (checked by the caller; see compute_flip).
double psnr_rgb8(const Rgb8View& a, const Rgb8View& b);

}  // namespace glpt::diff
