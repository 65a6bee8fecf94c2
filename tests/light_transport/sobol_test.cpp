// The trace pass's scrambled Sobol points (shaders/trace/sobol.h), compiled as C++ from the
// header the shader includes. A pixel's samples are consecutive points of one sequence over
// frames (trace/rng.h): what accumulation and the denoiser's history gain from that rests on
// these properties.
#include "trace/sobol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

using glpt::rt::gpu::scrambled_sobol2;
using glpt::rt::gpu::sobol_second_dimension;

// Sobol's second dimension in index order: the direction numbers v_0 = 1/2, v_i = v_(i-1) ^
// (v_(i-1) >> 1) XORed by the index's bits (the Gray-code order of other generators lists the
// same points differently). The shader's five-step form must equal this definition.
TEST(Sobol, SecondDimensionIsSobols) {
  const double expected[] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (unsigned i = 0; i < 8; ++i)
    EXPECT_EQ(sobol_second_dimension(i) * 0x1p-32, expected[i]) << "index " << i;
  auto by_definition = [](unsigned index) {
    unsigned x = 0;
    for (unsigned v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
      if ((index & 1u) != 0) x ^= v;
    return x;
  };
  for (unsigned i = 0; i < 100000; ++i) {
    const unsigned index = i < 50000 ? i : glpt::rt::gpu::pcg_hash(i);
    ASSERT_EQ(sobol_second_dimension(index), by_definition(index)) << "index " << index;
  }
}

// Any aligned run of 2^k indices (a pixel's frames 0..15, 16..31, ...) puts exactly one point
// in each cell of every 2^a x 2^b grid with a + b = k, for any seed: the (0, 2)-sequence
// property, kept by the shuffle and the scramble. Random numbers fail this almost always.
TEST(Sobol, AlignedRunsAreStratifiedInEveryElementaryInterval) {
  for (unsigned seed : {0u, 1u, 0x9E3779B9u, 123456789u, 0xdeadbeefu})
    for (unsigned k = 1; k <= 8; ++k)
      for (unsigned run : {0u, 1u, 7u}) {
        const unsigned n = 1u << k;
        for (unsigned a = 0; a <= k; ++a) {
          const unsigned b = k - a;
          std::set<unsigned> cells;
          for (unsigned i = run * n; i < (run + 1) * n; ++i) {
            const glm::vec2 p = scrambled_sobol2(i, seed);
            ASSERT_GE(p.x, 0.0f);
            ASSERT_LT(p.x, 1.0f);
            ASSERT_GE(p.y, 0.0f);
            ASSERT_LT(p.y, 1.0f);
            const unsigned cx = static_cast<unsigned>(std::floor(p.x * float(1u << a)));
            const unsigned cy = static_cast<unsigned>(std::floor(p.y * float(1u << b)));
            cells.insert(cx << b | cy);
          }
          EXPECT_EQ(cells.size(), n)
              << "seed " << seed << ", 2^" << a << " x 2^" << b << " grid, run " << run;
        }
      }
}

// Seeds are a pixel's dimension pairs and the pixels themselves: across seeds the points are
// uniform, and two seeds' points for the same index are uncorrelated (a path's light sample
// must not depend on its AO direction).
TEST(Sobol, SeparateSeedsAreUniformAndIndependent) {
  constexpr int kSeeds = 20000;
  for (unsigned index : {0u, 5u, 1000u}) {
    double mean = 0, second = 0, cross = 0;
    for (int s = 0; s < kSeeds; ++s) {
      const glm::vec2 p = scrambled_sobol2(index, glpt::rt::gpu::pcg_hash(unsigned(s)));
      const glm::vec2 q = scrambled_sobol2(index, glpt::rt::gpu::pcg_hash(unsigned(s) + 77u));
      mean += p.x + p.y;
      second += p.x * p.x + p.y * p.y;
      cross += (p.x - 0.5) * (q.x - 0.5) + (p.y - 0.5) * (q.y - 0.5);
    }
    mean /= 2 * kSeeds;
    second /= 2 * kSeeds;
    cross /= 2 * kSeeds;
    // Uniform: mean 1/2, second moment 1/3, each within about 4 standard errors.
    EXPECT_NEAR(mean, 0.5, 4 * std::sqrt(1.0 / 12 / (2 * kSeeds))) << "index " << index;
    EXPECT_NEAR(second, 1.0 / 3, 4 * std::sqrt(4.0 / 45 / (2 * kSeeds))) << "index " << index;
    EXPECT_NEAR(cross, 0.0, 4 * (1.0 / 12) / std::sqrt(2.0 * kSeeds)) << "index " << index;
  }
}

}  // namespace
