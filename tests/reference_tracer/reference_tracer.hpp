// A CPU reference of glpt's path tracer, in double precision: the same estimator as
// shaders/path_trace.comp (docs/light-transport.md: GL lights as sphere, distant, point and spot
// lights with GL's attenuation; GL materials as a Lambertian lobe under a GGX lobe; next-event
// estimation of one light chosen in proportion to its contribution and of one emissive triangle
// chosen by power, MIS with the power heuristic; bounces with Russian roulette; GL's ambient at
// the primary vertex under one ambient-occlusion ray; the composite's clamp and 8-bit rounding),
// on its own geometry (triangles in a BVH built with the surface area heuristic), its own
// random numbers and its own camera rays. It converges to the value glpt's estimator converges
// to, and its per-sample distribution is the one glpt's 1-sample frames have, so the tests
// (reference_test.cpp, distribution_compare.hpp) can check glpt in distribution: means per
// block within the two estimators' standard errors, variances per block within a factor.
//
// Usage: build a Scene (reference_scene.hpp), then
//   Estimate e = render(scene, Options{.samples = 4096, .center_samples = 1024});
//   e.at(x, y).mean        // the pixel's expected colour (unclamped; clamp for the 8-bit value)
//   e.at(x, y).q_variance  // the variance of a 1-sample frame's 8-bit value there
// Double precision throughout, plus a relative epsilon of 1e-9 and the origin's own triangle
// excluded for secondary rays: scene scale and distance from the origin change nothing.
//
// Deliberately not reproduced: glpt's float rounding (what a test is there to find), its
// random numbers, and the shadow-terminator lift (scenes with flat normals have none).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "reference_scene.hpp"

namespace glpt::reference {

// Deliberate errors, so a test can show that its comparison rejects a wrong estimator.
enum class Fault {
  kNone,
  kWrongAttenuation,    // GL's quadratic attenuation applied to d instead of d^2
  kDroppedBounce,       // one bounce fewer than the settings ask for
  kUniformLightChoice,  // lights chosen uniformly: the same mean, a different variance
};

struct Options {
  int samples = 4096;         // per pixel over GLPT_REFERENCE's jitter positions (means)
  int center_samples = 1024;  // per pixel at its centre: a 1-sample frame's distribution
  uint64_t seed = 1;
  int threads = 2;
  // GLPT_REFERENCE=N renders in at most 64 G-buffer passes, pass p jittered by the Halton
  // (2, 3) point p (0 for p = 0); the reference spreads its samples over the same positions.
  int jitter_positions = 64;
  Fault fault = Fault::kNone;
};

// One pixel, colours in [0, 1] units (GL's), before the composite's clamp.
struct PixelEstimate {
  glm::dvec3 mean{0.0};      // of the composite colour over the pixel (jitter positions)
  glm::dvec3 variance{0.0};  // per sample, of the same
  // A 1-sample frame's 8-bit value round(255 clamp(x)) at the pixel's centre (no jitter, as
  // glpt's first pass): its mean, variance and fourth central moment (in 8-bit steps).
  glm::dvec3 q_mean{0.0};
  glm::dvec3 q_variance{0.0};
  glm::dvec3 q_m4{0.0};
};

struct Estimate {
  int size = 0;
  Options options;
  std::vector<PixelEstimate> pixels;  // rows from the bottom (GL's window coordinates)
  const PixelEstimate& at(int x, int y) const { return pixels[size_t(y) * size_t(size) + x]; }
};

Estimate render(const Scene& scene, const Options& options);

}  // namespace glpt::reference
