// Random numbers of the trace pass. Each sample of each pixel draws its numbers from a Sampler:
// its first dimensions from a scrambled Sobol sequence that runs on from frame to frame (the
// pixel's samples are then stratified over time: an accumulated or temporally filtered pixel
// converges faster than with independent numbers), the rest from a PCG stream seeded from the
// pixel, the frame's seed and the sample index. Both are reproducible from the frame's index.
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
  uint index;      // the pixel's sample number, counted on over frames
  uint pixel;      // seeds the scrambles: fixed per pixel, so its points stay one sequence
  uint dimension;  // the next dimension pair
  uint stream;     // PCG state of the dimensions past the Sobol pairs
};

Sampler make_sampler(uint pixel_index, uint sample_number, uint frame_seed, uint sample_index) {
  Sampler s;
  s.index = sample_number;
  s.pixel = pcg_hash(pixel_index ^ 0x5bd1e995u);
  s.dimension = 0u;
  s.stream = sample_seed(pixel_index, frame_seed, sample_index);
  return s;
}

float stream_random(inout Sampler s) {
  s.stream = pcg_hash(s.stream);
  return float(s.stream >> 8) * (1.0 / 16777216.0);
}

vec2 next_random2(inout Sampler s) {
  if (s.dimension < kSobolDimensionPairs) {
    uint pair = s.dimension++;
    return scrambled_sobol2(s.index, pcg_hash(s.pixel + pair * 0x9E3779B9u));
  }
  float u = stream_random(s);
  return vec2(u, stream_random(s));
}

// One number: the first of a pair (a 1-D decision is stratified over the frames as well).
float next_random(inout Sampler s) {
  return next_random2(s).x;
}

#endif  // GLPT_SHADERS_TRACE_RNG_H
