// Random numbers of the trace pass. Each sample of each pixel draws its numbers from a Sampler:
// its first dimensions from a scrambled Sobol sequence that runs on from frame to frame (the
// pixel's samples are then stratified over time: an accumulated or temporally filtered pixel
// converges faster than with independent numbers), the rest from a PCG stream seeded from the
// pixel, the frame's seed and the sample index. Both are reproducible from the frame's index.
// Needs `blue_noise_mask` (GLPT_PT_BINDING_BLUE_NOISE) and `frame` (GLPT_OPTION_BLUE_NOISE).
#ifndef GLPT_SHADERS_TRACE_RNG_H
#define GLPT_SHADERS_TRACE_RNG_H

#include "sobol.h"

uint sample_seed(uint pixel_index, uint frame_seed, uint sample_index) {
  return pcg_hash(pixel_index ^ pcg_hash(frame_seed + sample_index * 0x9E3779B9u));
}

// ---- the sampler ---------------------------------------------------------------------------

// Dimension pairs drawn from the Sobol sequence; later ones (deep bounces) from the stream.
const uint kSobolDimensionPairs = 8u;

struct Sampler {
  ivec2 pixel;      // where the blue-noise masks offset this pixel's points (GLPT_BLUE_NOISE=1)
  uint pixel_seed;  // otherwise (the default): what scrambles this pixel's points
  uint index;       // the pixel's sample number, counted on over frames
  uint dimension;   // the next dimension pair
  uint stream;      // PCG state of the dimensions past the Sobol pairs
};

Sampler make_sampler(ivec2 pixel, uint pixel_index, uint sample_number, uint frame_seed,
                     uint sample_index) {
  Sampler s;
  s.pixel = pixel;
  s.pixel_seed = pcg_hash(pixel_index ^ 0x5bd1e995u);
  s.index = sample_number;
  s.dimension = 0u;
  s.stream = sample_seed(pixel_index, frame_seed, sample_index);
  return s;
}

// The blue-noise offset of `pixel` (each coordinate's rank in its mask, centred in its 1/4096).
vec2 blue_noise_offset(ivec2 pixel) {
  uint word = blue_noise_mask[(pixel.y & (GLPT_BLUE_NOISE_SIZE - 1)) * GLPT_BLUE_NOISE_SIZE +
                              (pixel.x & (GLPT_BLUE_NOISE_SIZE - 1))];
  return (vec2(float(word & 0xffffu), float(word >> 16u)) + 0.5) * (1.0 / 4096.0);
}

float stream_random(inout Sampler s) {
  s.stream = pcg_hash(s.stream);
  return float(s.stream >> 8) * (1.0 / 16777216.0);
}

vec2 next_random2(inout Sampler s) {
  if (s.dimension < kSobolDimensionPairs) {
    uint pair = s.dimension++;
    // By default each pixel's pairs are scrambled by seeds of its own: pixels independent.
    if ((frame.options.x & GLPT_OPTION_BLUE_NOISE) == 0u)
      return scrambled_sobol2(s.index, pcg_hash(s.pixel_seed + pair * 0x9E3779B9u));
    // GLPT_BLUE_NOISE=1: every pixel takes the same point of the pair's sequence, shifted (mod
    // 1) by its blue-noise offset: over frames a pixel's points stay stratified (a shifted
    // stratified set is one), and within a frame neighbouring pixels' points are spread apart,
    // so the denoiser's spatial filter averages stratified samples. Each pair reads the masks
    // at another place, so a pixel's offsets of different pairs are unrelated.
    vec2 point = scrambled_sobol2(s.index, pcg_hash(0x5bd1e995u + pair * 0x9E3779B9u));
    return fract(point + blue_noise_offset(s.pixel + ivec2(23, 41) * int(pair)));
  }
  float u = stream_random(s);
  return vec2(u, stream_random(s));
}

// One number: the first of a pair (a 1-D decision is stratified over the frames as well).
float next_random(inout Sampler s) {
  return next_random2(s).x;
}

#endif  // GLPT_SHADERS_TRACE_RNG_H
