// Compares glpt's 8-bit images with the CPU reference's estimate (reference_tracer.hpp) in
// distribution, per block of pixels and colour channel:
//   compare_means:     a GLPT_REFERENCE=N image against the reference's mean, within z standard
//                      errors of the difference of the two estimates plus half an 8-bit step;
//   compare_variances: the per-pixel variance over K 1-sample frames (GLPT_SPP=1, accumulation
//                      off) against the reference's variance of the same 8-bit value, within z
//                      standard errors of the difference (from the fourth moments) and a factor.
// Header-only; images are RGBA8 rows from the bottom (glReadPixels), size x size.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "reference_tracer.hpp"

namespace glpt::reference {

struct BlockResult {
  int x = 0, y = 0, channel = 0;      // the block's lower left pixel
  double measured = 0, expected = 0;  // glpt's and the reference's value (8-bit steps, or their
                                      // square for variances)
  double standard_error = 0;          // of measured - expected
  double tolerance = 0;
  bool pass = true;
  double deviation() const {
    return standard_error > 0 ? (measured - expected) / standard_error : 0;
  }
};

struct Comparison {
  std::string what;
  std::vector<BlockResult> blocks;
  int failures() const {
    return static_cast<int>(
        std::count_if(blocks.begin(), blocks.end(), [](const BlockResult& b) { return !b.pass; }));
  }
  // The block farthest from agreement, in standard errors of the difference.
  const BlockResult* worst() const {
    const BlockResult* w = nullptr;
    for (const BlockResult& b : blocks)
      if (w == nullptr || std::abs(b.deviation()) > std::abs(w->deviation())) w = &b;
    return w;
  }
  std::string summary() const {
    char text[256];
    const BlockResult* w = worst();
    std::snprintf(text, sizeof text,
                  "%s: %d of %zu blocks out; worst %+.2f SE at (%d,%d) ch %d: glpt %.3f, "
                  "reference %.3f, SE %.3f, tolerance %.3f",
                  what.c_str(), failures(), blocks.size(), w ? w->deviation() : 0.0, w ? w->x : 0,
                  w ? w->y : 0, w ? w->channel : 0, w ? w->measured : 0.0, w ? w->expected : 0.0,
                  w ? w->standard_error : 0.0, w ? w->tolerance : 0.0);
    return text;
  }
  std::string failed_blocks(size_t at_most = 8) const {
    std::string out;
    for (const BlockResult& b : blocks) {
      if (b.pass || at_most == 0) continue;
      --at_most;
      char text[200];
      std::snprintf(text, sizeof text,
                    "  block (%d,%d) ch %d: glpt %.3f, reference %.3f, SE %.3f (%+.1f), "
                    "tolerance %.3f\n",
                    b.x, b.y, b.channel, b.measured, b.expected, b.standard_error, b.deviation(),
                    b.tolerance);
      out += text;
    }
    return out;
  }
};

inline double channel_of(const std::vector<uint8_t>& rgba, int size, int x, int y, int c) {
  return rgba[(size_t(y) * size_t(size) + size_t(x)) * 4 + size_t(c)];
}

// `image`: glpt's GLPT_REFERENCE=`glpt_samples` frame. Per block and channel, glpt's mean
// 8-bit value must lie within z standard errors of the reference's (both estimates' errors,
// from the reference's per-sample variance, which the stratified jitter of both only lowers)
// plus half a step: 8-bit rounding moves each pixel by at most half a step, and on smooth
// images the pixels of a block round the same way, so it does not average out.
inline Comparison compare_means(const std::vector<uint8_t>& image, int glpt_samples,
                                const Estimate& ref, int block, double z = 4.5) {
  Comparison out;
  out.what = "means";
  const int size = ref.size;
  for (int by = 0; by + block <= size; by += block)
    for (int bx = 0; bx + block <= size; bx += block)
      for (int c = 0; c < 3; ++c) {
        BlockResult r;
        r.x = bx;
        r.y = by;
        r.channel = c;
        double variance = 0;
        for (int y = by; y < by + block; ++y)
          for (int x = bx; x < bx + block; ++x) {
            const PixelEstimate& p = ref.at(x, y);
            r.measured += channel_of(image, size, x, y, c);
            r.expected += 255.0 * std::clamp(p.mean[c], 0.0, 1.0);
            variance += 255.0 * 255.0 * p.variance[c] *
                        (1.0 / glpt_samples + 1.0 / std::max(ref.options.samples, 1));
          }
        const double n = double(block) * block;
        r.measured /= n;
        r.expected /= n;
        r.standard_error = std::sqrt(variance) / n;
        r.tolerance = z * r.standard_error + 0.5;
        r.pass = std::abs(r.measured - r.expected) <= r.tolerance;
        out.blocks.push_back(r);
      }
  return out;
}

// `frames`: K >= 4 independent 1-sample frames of glpt (GLPT_SPP=1, GLPT_ACCUMULATE=0: every
// frame's G-buffer at the pixel centres, a new seed each). Per block and channel, the mean over
// its pixels of the per-pixel sample variance over the frames must lie within z standard errors
// (Var(s^2) = (mu4 - sigma^4 (K-3)/(K-1)) / K per pixel, from the reference's moments, and the
// same for the reference's own estimate) and a relative `factor` of the reference's variance
// (what the reference does not model: glpt's float rounding of the 8-bit conversion, of the
// sampling routines), plus a quarter step^2 / sqrt(pixels) for blocks without noise (there a
// few pixels rounding the other way in some frame are all the difference there can be).
inline Comparison compare_variances(const std::vector<std::vector<uint8_t>>& frames,
                                    const Estimate& ref, int block, double z = 4.5,
                                    double factor = 0.1) {
  Comparison out;
  out.what = "variances";
  const int size = ref.size;
  const double k = static_cast<double>(frames.size());
  const double m = ref.options.center_samples;
  for (int by = 0; by + block <= size; by += block)
    for (int bx = 0; bx + block <= size; bx += block)
      for (int c = 0; c < 3; ++c) {
        BlockResult r;
        r.x = bx;
        r.y = by;
        r.channel = c;
        double var_of_estimates = 0;
        for (int y = by; y < by + block; ++y)
          for (int x = bx; x < bx + block; ++x) {
            double s1 = 0, s2 = 0;
            for (const std::vector<uint8_t>& f : frames) {
              const double q = channel_of(f, size, x, y, c);
              s1 += q;
              s2 += q * q;
            }
            const double mean = s1 / k;
            r.measured += (s2 / k - mean * mean) * k / (k - 1.0);
            const PixelEstimate& p = ref.at(x, y);
            const double sigma2 = p.q_variance[c], mu4 = p.q_m4[c];
            r.expected += sigma2;
            var_of_estimates += std::max(0.0, (mu4 - sigma2 * sigma2 * (k - 3) / (k - 1)) / k) +
                                std::max(0.0, (mu4 - sigma2 * sigma2 * (m - 3) / (m - 1)) / m);
          }
        const double n = double(block) * block;
        r.measured /= n;
        r.expected /= n;
        r.standard_error = std::sqrt(var_of_estimates) / n;
        r.tolerance = z * r.standard_error + factor * r.expected + 0.25 / std::sqrt(n);
        r.pass = std::abs(r.measured - r.expected) <= r.tolerance;
        out.blocks.push_back(r);
      }
  return out;
}

}  // namespace glpt::reference
