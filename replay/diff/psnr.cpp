#include "psnr.hpp"

#include <cmath>
#include <limits>

namespace glpt::diff {

double psnr_rgb8(const Rgb8View& a, const Rgb8View& b) {
  const size_t pixels = static_cast<size_t>(a.width) * a.height;
  // Exact integer sum: 255^2 * 3 per pixel fits 64 bits for any image that fits in memory.
  uint64_t squared_error = 0;
  for (size_t i = 0; i < pixels; ++i) {
    for (int c = 0; c < 3; ++c) {
      const int d = int{a.pixels[i * a.channels + c]} - int{b.pixels[i * b.channels + c]};
      squared_error += static_cast<uint64_t>(d * d);
    }
  }
  if (squared_error == 0) return std::numeric_limits<double>::infinity();
  const double mse = static_cast<double>(squared_error) / (3.0 * static_cast<double>(pixels));
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

double relmse_rgb8(const Rgb8View& test, const Rgb8View& reference) {
  const size_t pixels = static_cast<size_t>(test.width) * test.height;
  if (pixels == 0) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < pixels; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double t = test.pixels[i * test.channels + c] / 255.0;
      const double r = reference.pixels[i * reference.channels + c] / 255.0;
      sum += (t - r) * (t - r) / (r * r + 0.01);
    }
  }
  return sum / (3.0 * static_cast<double>(pixels));
}

}  // namespace glpt::diff
