#include "imgcompare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace glpt::imgcompare {
namespace {

bool same_size(const ImageRGBA8& a, const ImageRGBA8& b, std::string* error) {
  if (a.width == b.width && a.height == b.height &&
      a.pixels.size() == size_t{a.width} * a.height * 4 && b.pixels.size() == a.pixels.size()) {
    return true;
  }
  if (error) {
    *error = "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
             " vs " + std::to_string(b.width) + "x" + std::to_string(b.height);
  }
  return false;
}

}  // namespace

bool parse_rgb(const std::string& text, Rgb* out) {
  int values[3];
  size_t pos = 0;
  for (int i = 0; i < 3; ++i) {
    if (pos >= text.size()) return false;
    char* end = nullptr;
    const long v = std::strtol(text.c_str() + pos, &end, 10);
    const size_t used = static_cast<size_t>(end - (text.c_str() + pos));
    if (used == 0 || v < 0 || v > 255) return false;
    values[i] = static_cast<int>(v);
    pos += used;
    if (i < 2) {
      if (pos >= text.size() || text[pos] != ',') return false;
      ++pos;
    }
  }
  if (pos != text.size()) return false;
  *out = Rgb{static_cast<uint8_t>(values[0]), static_cast<uint8_t>(values[1]),
             static_cast<uint8_t>(values[2])};
  return true;
}

bool is_covered(const uint8_t* rgba, Rgb background, int tolerance) {
  return std::abs(rgba[0] - background.r) > tolerance ||
         std::abs(rgba[1] - background.g) > tolerance ||
         std::abs(rgba[2] - background.b) > tolerance;
}

double luminance(const uint8_t* rgba) {
  return (0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2]) / 255.0;
}

bool coverage(const ImageRGBA8& a, const ImageRGBA8& b, Rgb background, int tolerance,
              CoverageResult* out, ImageRGBA8* diff, std::string* error) {
  if (!same_size(a, b, error)) return false;
  CoverageResult r;
  if (diff) {
    diff->width = a.width;
    diff->height = a.height;
    diff->pixels.assign(a.pixels.size(), 0);
  }
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    const bool in_a = is_covered(&a.pixels[i], background, tolerance);
    const bool in_b = is_covered(&b.pixels[i], background, tolerance);
    uint8_t colour[3] = {0, 0, 0};
    if (in_a && in_b) {
      ++r.both;
      colour[0] = colour[1] = colour[2] = 255;
    } else if (in_a) {
      ++r.only_a;
      colour[0] = 255;
    } else if (in_b) {
      ++r.only_b;
      colour[1] = 255;
    } else {
      ++r.neither;
    }
    if (diff) {
      diff->pixels[i] = colour[0];
      diff->pixels[i + 1] = colour[1];
      diff->pixels[i + 2] = colour[2];
      diff->pixels[i + 3] = 255;
    }
  }
  const uint64_t uni = r.only_a + r.only_b + r.both;
  r.iou = uni == 0 ? 0.0 : static_cast<double>(r.both) / static_cast<double>(uni);
  *out = r;
  return true;
}

bool lit_vs_away(const ImageRGBA8& shaded, const ImageRGBA8& facing, Rgb background,
                 const LitAwayOptions& options, LitAwayResult* out, std::string* error) {
  if (!same_size(shaded, facing, error)) return false;
  LitAwayResult r;
  double sum_lit = 0.0, sum_away = 0.0;
  for (size_t i = 0; i < facing.pixels.size(); i += 4) {
    // Only pixels that are geometry in both images: a pixel that one renderer puts on an edge
    // and the other does not says nothing about shading.
    if (!is_covered(&facing.pixels[i], background, options.tolerance) ||
        !is_covered(&shaded.pixels[i], background, options.tolerance)) {
      continue;
    }
    ++r.covered;
    const double oracle = luminance(&facing.pixels[i]);
    if (oracle > options.lit_threshold) {
      ++r.lit;
      sum_lit += luminance(&shaded.pixels[i]);
    } else if (oracle < options.away_threshold) {
      ++r.away;
      sum_away += luminance(&shaded.pixels[i]);
    }
  }
  if (r.lit) r.mean_lit = sum_lit / static_cast<double>(r.lit);
  if (r.away) r.mean_away = sum_away / static_cast<double>(r.away);
  const double min_pixels = options.min_class_fraction * static_cast<double>(r.covered);
  if (r.covered == 0) {
    r.reason = "no pixel is covered in both images";
  } else if (static_cast<double>(r.lit) < min_pixels || r.lit == 0) {
    r.reason = "too few lit pixels in the facing oracle";
  } else if (static_cast<double>(r.away) < min_pixels || r.away == 0) {
    r.reason = "too few away pixels in the facing oracle";
  } else if (r.mean_lit - r.mean_away < options.min_margin) {
    r.reason = "mean(lit) - mean(away) is below the margin";
  } else if (r.mean_lit < options.min_ratio * r.mean_away) {
    r.reason = "mean(lit) / mean(away) is below the ratio";
  }
  r.pass = r.reason.empty();
  *out = r;
  return true;
}

bool psnr(const ImageRGBA8& a, const ImageRGBA8& b, double* out, std::string* error) {
  if (!same_size(a, b, error)) return false;
  uint64_t sum_sq = 0, count = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) {
      const int d = a.pixels[i + c] - b.pixels[i + c];
      sum_sq += static_cast<uint64_t>(d * d);
    }
    count += 3;
  }
  if (sum_sq == 0) {
    *out = std::numeric_limits<double>::infinity();
    return true;
  }
  const double mse = static_cast<double>(sum_sq) / static_cast<double>(count);
  *out = 10.0 * std::log10(255.0 * 255.0 / mse);
  return true;
}

bool within_tolerance(const ImageRGBA8& reference, const ImageRGBA8& test, int max_channel_diff,
                      WithinResult* out, ImageRGBA8* diff, std::string* error) {
  if (!same_size(reference, test, error)) return false;
  const size_t w = reference.width, h = reference.height;
  WithinResult r;
  r.pixels = w * h;
  if (diff) {
    diff->width = static_cast<uint32_t>(4 * w);
    diff->height = static_cast<uint32_t>(h);
    diff->pixels.assign(16 * w * h, 255);
  }
  for (size_t y = 0; y < h; ++y) {
    for (size_t x = 0; x < w; ++x) {
      const uint8_t* a = &reference.pixels[(y * w + x) * 4];
      const uint8_t* b = &test.pixels[(y * w + x) * 4];
      int largest = 0;
      for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(a[c] - b[c]));
      r.max_diff = std::max(r.max_diff, largest);
      const bool within = largest <= max_channel_diff;
      if (within) ++r.within;
      if (!diff) continue;
      uint8_t* row = &diff->pixels[y * 16 * w];
      uint8_t* panel[4] = {row + x * 4, row + (w + x) * 4, row + (2 * w + x) * 4,
                           row + (3 * w + x) * 4};
      for (int c = 0; c < 3; ++c) {
        panel[0][c] = a[c];
        panel[1][c] = b[c];
        panel[2][c] = static_cast<uint8_t>(std::min(255, 16 * std::abs(a[c] - b[c])));
      }
      const uint8_t grey = static_cast<uint8_t>(luminance(a) * 255.0 / 3.0);
      const uint8_t mask[3][3] = {{255, 0, 0}, {0, 96, 255}, {grey, grey, grey}};
      const int kind = !within ? 0 : largest > 0 ? 1 : 2;
      for (int c = 0; c < 3; ++c) panel[3][c] = mask[kind][c];
    }
  }
  r.fraction = r.pixels == 0 ? 0.0 : static_cast<double>(r.within) / static_cast<double>(r.pixels);
  *out = r;
  return true;
}

double fraction_differing_from_corner(const ImageRGBA8& image, int tolerance) {
  if (image.pixels.size() < 4) return 0.0;
  const Rgb corner{image.pixels[0], image.pixels[1], image.pixels[2]};
  uint64_t differing = 0;
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    if (is_covered(&image.pixels[i], corner, tolerance)) ++differing;
  }
  return static_cast<double>(differing) / static_cast<double>(image.pixels.size() / 4);
}

}  // namespace glpt::imgcompare
