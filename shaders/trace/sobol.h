// Scrambled Sobol points (Burley 2020, "Practical Hash-based Owen Scrambling"): the numbers the
// trace pass's samples draw their first dimensions from (rng.h). Pure functions shared by GLSL
// and C++ (glsl_cpp.h): tests/light_transport checks that any aligned run of 2^k points is
// stratified in every elementary interval of area 2^-k, and that separate seeds are independent.
#ifndef GLPT_SHADERS_TRACE_SOBOL_H
#define GLPT_SHADERS_TRACE_SOBOL_H

#include "glsl_cpp.h"

#ifdef __cplusplus
#include <glm/integer.hpp>
namespace glpt::rt::gpu {
using namespace glm;
#endif

// PCG hash (Jarzynski & Olano 2020): cheap, and good enough to both seed and step a generator.
GLPT_FN uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// A random permutation of 32-bit words in which each bit depends only on the bits below it
// (Laine and Karras 2011, with Vegdahl's constants). On a bit-reversed word it is a nested
// uniform (Owen) scramble, which keeps a sequence's stratification and randomises it.
GLPT_FN uint laine_karras_permutation(uint x, uint seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

GLPT_FN uint owen_scramble(uint x, uint seed) {
  return bitfieldReverse(laine_karras_permutation(bitfieldReverse(x), seed));
}

// The Sobol sequence's second dimension before its bit reversal (sobol_second_dimension).
GLPT_FN uint sobol_second_dimension_reversed(uint index) {
  uint y = index;
  y ^= (y >> 1u) & 0x55555555u;
  y ^= (y >> 2u) & 0x33333333u;
  y ^= (y >> 4u) & 0x0F0F0F0Fu;
  y ^= (y >> 8u) & 0x00FF00FFu;
  y ^= (y >> 16u) & 0x0000FFFFu;
  return y;
}

// The second dimension of the Sobol sequence (the first is the bit-reversed index). Its
// direction numbers (the primitive polynomial x + 1) are the rows of Pascal's triangle mod 2,
// and C(j, i) is odd exactly where i's bits are a subset of j's (Lucas): output bit 31 - i is
// the XOR of the index bits j that contain i, a superset transform in five shift steps, the
// same for every index (no loop over its bits, which a shuffled index has 32 of).
GLPT_FN uint sobol_second_dimension(uint index) {
  return bitfieldReverse(sobol_second_dimension_reversed(index));
}

// Point `index` of a 2-D Sobol sequence, its order shuffled and its values scrambled by `seed`
// (Burley's shuffled scrambled Sobol: an aligned run of 2^k indices stays a stratified set, and
// the points of different seeds are independent of one another).
GLPT_FN vec2 scrambled_sobol2(uint index, uint seed) {
  index = owen_scramble(index, seed);
  // owen_scramble(bitfieldReverse(index)) and owen_scramble(sobol_second_dimension(index)),
  // with the reversals that cancel left out.
  uint x = bitfieldReverse(laine_karras_permutation(index, pcg_hash(seed)));
  uint y = bitfieldReverse(
      laine_karras_permutation(sobol_second_dimension_reversed(index), pcg_hash(seed + 1u)));
  // 24 bits: exactly representable, in [0,1)
  return vec2(float(x >> 8u), float(y >> 8u)) * (1.0f / 16777216.0f);
}

#ifdef __cplusplus
}  // namespace glpt::rt::gpu
#endif

#endif  // GLPT_SHADERS_TRACE_SOBOL_H
