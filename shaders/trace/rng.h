// Random numbers of the trace pass. Each sample of each pixel gets its own stream, seeded from the
// pixel, the frame's seed and the sample index, so accumulated frames and shards see new,
// reproducible samples.
#ifndef GLPT_SHADERS_TRACE_RNG_H
#define GLPT_SHADERS_TRACE_RNG_H

// PCG hash (Jarzynski & Olano 2020): cheap, and good enough to both seed and step the generator.
uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

float next_random(inout uint rng) {
  rng = pcg_hash(rng);
  return float(rng >> 8) * (1.0 / 16777216.0);  // 24 bits: exactly representable, in [0,1)
}

vec2 next_random2(inout uint rng) {
  float u = next_random(rng);
  return vec2(u, next_random(rng));
}

uint sample_seed(uint pixel_index, uint frame_seed, uint sample_index) {
  return pcg_hash(pixel_index ^ pcg_hash(frame_seed + sample_index * 0x9E3779B9u));
}

#endif  // GLPT_SHADERS_TRACE_RNG_H
