#include "flip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace glpt::diff {
namespace {

// The constants of LDR-FLIP as the HPG 2020 paper gives them.
// Contrast sensitivity functions of the achromatic, red-green and blue-yellow channels, as sums
// of Gaussians a * sqrt(pi / b) * exp(-pi^2 x^2 / b) in visual degrees x (paper, section 4.1).
struct SumOfGaussians {
  double a1, b1, a2, b2;
};
constexpr std::array<SumOfGaussians, 3> kChannelCsf = {{
    {1.0, 0.0047, 0.0, 1e-5},   // achromatic (Yy)
    {1.0, 0.0053, 0.0, 1e-5},   // red-green (Cx)
    {34.1, 0.04, 13.5, 0.025},  // blue-yellow (Cz)
}};
constexpr double kColorExponent = 0.7;    // q_c: compresses the HyAB distance
constexpr double kColorCutoff = 0.4;      // p_c: fraction of the largest error ...
constexpr double kColorCutoffMap = 0.95;  // p_t: ... that is mapped to this value
constexpr double kFeatureWidth = 0.082;   // w: edge/point feature width in degrees
constexpr double kFeatureExponent = 0.5;  // q_f

// sRGB (IEC 61966-2-1) primaries with the D65 white: linear RGB to CIE XYZ and back.
constexpr double kRgbToXyz[3][3] = {{0.4123908, 0.3575843, 0.1804808},
                                    {0.2126390, 0.7151687, 0.0721923},
                                    {0.0193308, 0.1191948, 0.9505322}};
constexpr double kXyzToRgb[3][3] = {{3.2409699, -1.5373832, -0.4986108},
                                    {-0.9692436, 1.8759675, 0.0415551},
                                    {0.0556301, -0.2039770, 1.0569715}};
// The reference white: XYZ of linear RGB (1, 1, 1).
constexpr double kWhite[3] = {kRgbToXyz[0][0] + kRgbToXyz[0][1] + kRgbToXyz[0][2],
                              kRgbToXyz[1][0] + kRgbToXyz[1][1] + kRgbToXyz[1][2],
                              kRgbToXyz[2][0] + kRgbToXyz[2][1] + kRgbToXyz[2][2]};

using Vec3 = std::array<float, 3>;

Vec3 multiply(const double (&m)[3][3], const Vec3& v) {
  Vec3 r{};
  for (int i = 0; i < 3; ++i) {
    r[i] = static_cast<float>(m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2]);
  }
  return r;
}

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// YyCxCz: the linearized CIELAB opponent space FLIP filters in (the cube root of L*a*b* left
// out so that filtering stays linear in light).
Vec3 xyz_to_ycxcz(const Vec3& xyz) {
  const double x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
  return {static_cast<float>(116.0 * y - 16.0), static_cast<float>(500.0 * (x - y)),
          static_cast<float>(200.0 * (y - z))};
}

Vec3 ycxcz_to_xyz(const Vec3& c) {
  const double y = (c[0] + 16.0) / 116.0;
  const double x = y + c[1] / 500.0;
  const double z = y - c[2] / 200.0;
  return {static_cast<float>(x * kWhite[0]), static_cast<float>(y * kWhite[1]),
          static_cast<float>(z * kWhite[2])};
}

double lab_f(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

Vec3 xyz_to_lab(const Vec3& xyz) {
  const double fx = lab_f(xyz[0] / kWhite[0]);
  const double fy = lab_f(xyz[1] / kWhite[1]);
  const double fz = lab_f(xyz[2] / kWhite[2]);
  return {static_cast<float>(116.0 * fy - 16.0), static_cast<float>(500.0 * (fx - fy)),
          static_cast<float>(200.0 * (fy - fz))};
}

// The Hunt effect (colourfulness grows with luminance): chroma scaled by L*/100.
Vec3 hunt_adjust(const Vec3& lab) {
  return {lab[0], 0.01f * lab[0] * lab[1], 0.01f * lab[0] * lab[2]};
}

// HyAB: city-block distance in lightness plus Euclidean distance in the chroma plane.
double hyab(const Vec3& p, const Vec3& q) {
  const double da = p[1] - q[1], db = p[2] - q[2];
  return std::abs(double{p[0]} - q[0]) + std::sqrt(da * da + db * db);
}

Vec3 linear_rgb_to_hunt_lab(const Vec3& rgb) {
  return hunt_adjust(xyz_to_lab(multiply(kRgbToXyz, rgb)));
}

// The largest colour error FLIP expects: between pure green and pure blue, compressed by q_c.
double max_color_error() {
  return std::pow(hyab(linear_rgb_to_hunt_lab({0, 1, 0}), linear_rgb_to_hunt_lab({0, 0, 1})),
                  kColorExponent);
}

// One float per pixel, rows top first.
struct Plane {
  int width = 0, height = 0;
  std::vector<float> v;
  Plane(int w, int h) : width(w), height(h), v(static_cast<size_t>(w) * h, 0.0f) {}
  float& at(int x, int y) { return v[static_cast<size_t>(y) * width + x]; }
  float at(int x, int y) const { return v[static_cast<size_t>(y) * width + x]; }
};

// A 1-D filter of odd length, centred.
using Taps = std::vector<float>;

// Convolves along rows (horizontal == true) or columns. Outside the image the edge pixel is
// repeated, so a uniform image stays uniform up to its border and no dark or bright frame is
// invented there.
Plane convolve(const Plane& src, const Taps& taps, bool horizontal) {
  Plane dst(src.width, src.height);
  const int radius = static_cast<int>(taps.size() / 2);
  for (int y = 0; y < src.height; ++y) {
    for (int x = 0; x < src.width; ++x) {
      float sum = 0.0f;
      for (int k = -radius; k <= radius; ++k) {
        const float w = taps[k + radius];
        sum += horizontal ? w * src.at(std::clamp(x + k, 0, src.width - 1), y)
                          : w * src.at(x, std::clamp(y + k, 0, src.height - 1));
      }
      dst.at(x, y) = sum;
    }
  }
  return dst;
}

Plane separable(const Plane& src, const Taps& along_x, const Taps& along_y) {
  return convolve(convolve(src, along_x, true), along_y, false);
}

// The spatial (contrast sensitivity) filter of one channel: the 2-D kernel is the channel's
// sum of Gaussians evaluated at the distance r from the centre, which is a sum of separable
// Gaussians, one 1-D filter per term: sqrt(a sqrt(pi/b)) exp(-pi^2 x^2 / b) in x times the same
// in y gives a sqrt(pi/b) exp(-pi^2 r^2 / b). The kernel is normalized to sum to 1 (the sum of
// a separable term is the square of its 1-D sum).
std::vector<Taps> csf_filter_terms(const SumOfGaussians& csf, int radius, double ppd) {
  const double pi = std::numbers::pi;
  std::vector<std::pair<double, double>> terms = {{csf.a1, csf.b1}};
  if (csf.a2 != 0.0) terms.emplace_back(csf.a2, csf.b2);
  std::vector<std::vector<double>> taps;
  double kernel_sum = 0.0;
  for (const auto& [a, b] : terms) {
    std::vector<double>& t = taps.emplace_back();
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
      const double x = i / ppd;  // degrees
      t.push_back(std::sqrt(a * std::sqrt(pi / b)) * std::exp(-pi * pi * x * x / b));
      sum += t.back();
    }
    kernel_sum += sum * sum;
  }
  const double scale = 1.0 / std::sqrt(kernel_sum);
  std::vector<Taps> result;
  for (const std::vector<double>& t : taps) {
    Taps& r = result.emplace_back();
    for (double w : t) r.push_back(static_cast<float>(w * scale));
  }
  return result;
}

// Scales the positive taps to sum to 1 and the negative ones to sum to -1 (paper, section 4.2:
// the edge and point detectors respond to contrast, not to the mean level).
Taps normalize_signed(const std::vector<double>& t) {
  double positive = 0.0, negative = 0.0;
  for (double w : t) (w > 0.0 ? positive : negative) += w;
  Taps r;
  for (double w : t) r.push_back(static_cast<float>(w > 0.0 ? w / positive : w / -negative));
  return r;
}

struct FeatureFilters {
  Taps gaussian, first_derivative, second_derivative;
};

// Gaussian with standard deviation 0.5 * w (in pixels) and its first and second derivatives,
// cut off at 3 standard deviations.
FeatureFilters feature_filters(double ppd) {
  const double sigma = 0.5 * kFeatureWidth * ppd;
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> g, dg, ddg;
  double g_sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    const double gi = std::exp(-double(i) * i / (2.0 * sigma * sigma));
    g.push_back(gi);
    g_sum += gi;
    dg.push_back(-i * gi);                                        // d/dx, up to a positive factor
    ddg.push_back((double(i) * i / (sigma * sigma) - 1.0) * gi);  // d2/dx2, likewise
  }
  FeatureFilters f;
  for (double w : g) f.gaussian.push_back(static_cast<float>(w / g_sum));
  f.first_derivative = normalize_signed(dg);
  f.second_derivative = normalize_signed(ddg);
  return f;
}

// The colour pipeline's input: the image in YyCxCz, one plane per channel; and the feature
// pipeline's: luminance Y / Y_white in [0, 1].
struct Opponent {
  std::array<Plane, 3> channel;
  Plane luminance;
};

Opponent to_opponent(const Rgb8View& img) {
  std::array<float, 256> linear{};
  for (int i = 0; i < 256; ++i) linear[i] = static_cast<float>(srgb_to_linear(i / 255.0));
  const int w = static_cast<int>(img.width), h = static_cast<int>(img.height);
  Opponent o{{Plane(w, h), Plane(w, h), Plane(w, h)}, Plane(w, h)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = img.pixels + (static_cast<size_t>(y) * w + x) * img.channels;
      const Vec3 c = xyz_to_ycxcz(multiply(kRgbToXyz, {linear[p[0]], linear[p[1]], linear[p[2]]}));
      for (int k = 0; k < 3; ++k) o.channel[k].at(x, y) = c[k];
      o.luminance.at(x, y) = (c[0] + 16.0f) / 116.0f;
    }
  }
  return o;
}

// The image as the eye resolves it at this distance: each opponent channel filtered by its
// CSF, then brought back to linear RGB, clamped to the displayable range, and into Hunt-adjusted
// CIELAB, where colour distances are measured.
std::vector<Vec3> perceived_colors(const Opponent& o, double ppd) {
  double b_max = 0.0;
  for (const SumOfGaussians& c : kChannelCsf) b_max = std::max({b_max, c.b1, c.a2 != 0 ? c.b2 : 0});
  const double pi = std::numbers::pi;
  // 3 standard deviations of the widest Gaussian (its variance is b / (2 pi^2) degrees^2).
  const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(b_max / (2.0 * pi * pi)) * ppd));
  const int w = o.luminance.width, h = o.luminance.height;
  std::array<Plane, 3> filtered{Plane(w, h), Plane(w, h), Plane(w, h)};
  for (int k = 0; k < 3; ++k) {
    for (const Taps& t : csf_filter_terms(kChannelCsf[k], radius, ppd)) {
      const Plane term = separable(o.channel[k], t, t);
      for (size_t i = 0; i < term.v.size(); ++i) filtered[k].v[i] += term.v[i];
    }
  }
  std::vector<Vec3> lab(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < lab.size(); ++i) {
    Vec3 rgb =
        multiply(kXyzToRgb, ycxcz_to_xyz({filtered[0].v[i], filtered[1].v[i], filtered[2].v[i]}));
    for (float& c : rgb) c = std::clamp(c, 0.0f, 1.0f);
    lab[i] = linear_rgb_to_hunt_lab(rgb);
  }
  return lab;
}

// Edge (gradient) and point (second derivative) strengths of the luminance.
struct Features {
  std::vector<float> edge, point;
};

Features features(const Plane& luminance, const FeatureFilters& f) {
  const Plane dx = separable(luminance, f.first_derivative, f.gaussian);
  const Plane dy = separable(luminance, f.gaussian, f.first_derivative);
  const Plane ddx = separable(luminance, f.second_derivative, f.gaussian);
  const Plane ddy = separable(luminance, f.gaussian, f.second_derivative);
  Features r;
  r.edge.resize(dx.v.size());
  r.point.resize(dx.v.size());
  for (size_t i = 0; i < dx.v.size(); ++i) {
    r.edge[i] = std::hypot(dx.v[i], dy.v[i]);
    r.point[i] = std::hypot(ddx.v[i], ddy.v[i]);
  }
  return r;
}

bool fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

double pixels_per_degree(double distance_m, double width_m, double width_px) {
  return distance_m * (width_px / width_m) * (std::numbers::pi / 180.0);
}

double default_pixels_per_degree() { return pixels_per_degree(0.7, 0.7, 3840.0); }

bool compute_flip(const Rgb8View& reference, const Rgb8View& test, double ppd, FlipResult* out,
                  std::string* error) {
  for (const Rgb8View* v : {&reference, &test}) {
    if (v->pixels == nullptr || (v->channels != 3 && v->channels != 4)) {
      return fail(error, "malformed image view (needs pixels and 3 or 4 channels)");
    }
    if (v->width == 0 || v->height == 0) return fail(error, "empty image");
  }
  if (reference.width != test.width || reference.height != test.height) {
    return fail(error, "sizes differ: " + std::to_string(reference.width) + "x" +
                           std::to_string(reference.height) + " and " + std::to_string(test.width) +
                           "x" + std::to_string(test.height));
  }
  if (!(ppd > 0.0) || !std::isfinite(ppd)) return fail(error, "pixels per degree must be > 0");

  const Opponent ref = to_opponent(reference), tst = to_opponent(test);

  // Colour pipeline (paper, section 4.1).
  const std::vector<Vec3> ref_lab = perceived_colors(ref, ppd);
  const std::vector<Vec3> tst_lab = perceived_colors(tst, ppd);
  const double c_max = max_color_error();
  const double cutoff = kColorCutoff * c_max;

  // Feature pipeline (paper, section 4.2).
  const FeatureFilters filters = feature_filters(ppd);
  const Features ref_features = features(ref.luminance, filters);
  const Features tst_features = features(tst.luminance, filters);

  out->width = reference.width;
  out->height = reference.height;
  out->error.resize(ref_lab.size());
  double sum = 0.0, max = 0.0;
  for (size_t i = 0; i < ref_lab.size(); ++i) {
    // Compressed colour distance, remapped so that errors up to p_c * c_max fill [0, p_t] and
    // the rest (p_t, 1]: small differences get most of the range.
    const double d = std::pow(hyab(ref_lab[i], tst_lab[i]), kColorExponent);
    const double color =
        d < cutoff ? d * kColorCutoffMap / cutoff
                   : kColorCutoffMap + (d - cutoff) / (c_max - cutoff) * (1.0 - kColorCutoffMap);
    const double edge = std::abs(double{ref_features.edge[i]} - tst_features.edge[i]);
    const double point = std::abs(double{ref_features.point[i]} - tst_features.point[i]);
    const double feature = std::pow(std::max(edge, point) / std::numbers::sqrt2, kFeatureExponent);
    // A feature difference raises the colour error towards 1 (the exponent shrinks towards 0).
    const double flip = std::pow(color, 1.0 - feature);
    out->error[i] = static_cast<float>(flip);
    sum += flip;
    max = std::max(max, flip);
  }
  out->mean = sum / static_cast<double>(ref_lab.size());
  out->max = max;
  return true;
}

double fraction_over(const FlipResult& result, double tolerance) {
  if (result.error.empty()) return 0.0;
  // Compared in float, the map's precision: a value stored as 0.05f is not "over 0.05".
  const float limit = static_cast<float>(tolerance);
  const auto over = std::count_if(result.error.begin(), result.error.end(),
                                  [limit](float e) { return e > limit; });
  return static_cast<double>(over) / static_cast<double>(result.error.size());
}

}  // namespace glpt::diff
