#version 460
// SVGF, step 2 (Schied et al. 2017, section 4.2): one iteration of the edge-avoiding a-trous
// wavelet filter, dispatched `iterations` times with steps 1, 2, 4, ... Per channel, each tap q of
// the kernel (the paper's 5x5 B3 spline, a 3x3 one, or by default four taps of the 3x3: see
// below) spaced `step` pixels apart weighs
//   h(q) * w_depth * w_normal * w_luminance
//   w_depth     = exp(-|n_p . (x_q - x_p)| / (sigma_depth * pixel size * |p - q|))
//   w_normal    = max(0, n_p . n_q) ^ sigma_normal
//   w_luminance = exp(-|l_p - l_q| / (sigma_luminance * sqrt(g3x3(variance_p)) + eps))
// The paper's depth term divides the depth difference by the screen-space depth gradient; the
// distance to p's tangent plane over the pixel's footprint is the same test in eye space, without
// a gradient buffer. Unlike the paper, taps of another object (history id) are never used: with
// a short history the luminance term stops little, and coplanar neighbours passed the rest. Variance is filtered with the squared weights (it feeds the next
// iteration's luminance term). The first iteration's output is the next frame's colour history.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_image_load_formatted : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require

#include "svgf/svgf_common.h"

layout(push_constant) uniform Iteration {
  uint step;         // tap spacing in pixels
  uint input_slot;   // work slots (shared_types.h, DenoiseUniforms::buffers)
  uint output_slot;  // the first iteration's result is the colour history
  uint also_output;  // a work slot written as well (the first iteration when it is the last), or
                     // GLPT_DN_SLOT_NONE
} iteration;

// One a-trous tap per channel, weighed as above. The weights are computed as one exp2 per
// channel of the summed log2 terms (w_depth * w_normal * w_luminance = 2^(sum)): two
// transcendentals fewer per tap than exp, pow and exp (on lavapipe each is a vector polynomial,
// about a third of an iteration's time).
DenoiseGuide centre;
vec3 x_p, n_p;
float depth_scale;  // log2(e) / (sigma_depth * pixel footprint * step)
vec4 centre_values[3];
float luminance_p[3], luminance_scale[3];  // log2(e) / (sigma_luminance * deviation), per channel
vec3 sums[3];
float variance_sums[3], weight_sums[3];

void add_channel(uint c, vec4 value, float h, float log_geometry) {
  float w = h * exp2(log_geometry - abs(luminance(value.rgb) - luminance_p[c]) * luminance_scale[c]);
  sums[c] += w * value.rgb;
  variance_sums[c] += w * w * value.a;
  weight_sums[c] += w;
}

// The kernel's weight at offset d (in taps) along one axis: the B3 spline (0.375, 0.25, 0.0625),
// or (0.5, 0.25) for the 3x3 kernel, which is also the variance prefilter's Gaussian.
float kernel_weight(int d, bool three_by_three) {
  return three_by_three ? (d == 0 ? 0.5 : 0.25) : (d == 0 ? 0.375 : abs(d) == 1 ? 0.25 : 0.0625);
}

void add_tap(ivec2 pixel, ivec2 offset, float h, uint channels) {
  ivec2 q = pixel + offset * int(iteration.step);
  if (!inside(q)) return;
  DenoiseGuide g = load_guide(q);
  // Another object's light is no estimate of this one's, however close its plane (gears side by
  // side, a character against a wall at the same depth).
  // (0, no surface, is never the centre's id; a guide of an earlier frame has another stamp)
  if (g.meta.x != centre.meta.x || (g.meta.y >> 8) != dn.slots.z) return;
  float facing = dot(n_p, guide_normal(g));
  if (!(facing > 0.0)) return;  // w_normal = 0
  float log_geometry = -abs(dot(n_p, g.eye.xyz - x_p)) * depth_scale / length(vec2(offset)) +
                       dn.sigmas.y * log2(facing);
  if (!(log_geometry > -126.0)) return;  // a weight below the smallest normal float
  add_channel(0u, load_work(iteration.input_slot, 0u, q), h, log_geometry);
  add_channel(1u, load_work(iteration.input_slot, 1u, q), h, log_geometry);
  if (channels > 2u) add_channel(2u, load_work(iteration.input_slot, 2u, q), h, log_geometry);
}

void main() {
  // Dispatched over the tiles with a shaded pixel (the trace pass's list): the others would
  // only return (about 0.2 ms a dispatch over 320x240 when all do).
  ivec2 pixel = listed_tile_pixel();
  if (!inside(pixel)) return;
  centre = load_guide(pixel);
  if (!guide_shaded(centre)) return;  // not shaded by the tracer: nothing to filter
  x_p = centre.eye.xyz;
  n_p = guide_normal(centre);
  const float log2_e = 1.4426950408889634;
  depth_scale = log2_e / (dn.sigmas.x * pixel_footprint(x_p) * float(iteration.step) + 1e-20);
  uint channels = filtered_channels();  // a channel the frame cannot have is neither read nor written

  centre_values[0] = load_work(iteration.input_slot, 0u, pixel);
  centre_values[1] = load_work(iteration.input_slot, 1u, pixel);
  centre_values[2] = channels > 2u ? load_work(iteration.input_slot, 2u, pixel) : vec4(0.0);
  for (uint c = 0u; c < 3u; ++c) luminance_p[c] = luminance(centre_values[c].rgb);
  // The centre's variance through a 3x3 Gaussian (the paper's prefilter): one noisy variance
  // estimate must not stop the filter. Later iterations read variance the previous iteration
  // filtered already: they take it as it is (a third of their cost saved, no measured loss).
  vec3 variance = vec3(centre_values[0].a, centre_values[1].a, centre_values[2].a);
  if (iteration.step == 1u) {
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        ivec2 q = pixel + ivec2(dx, dy);
        // (a buffer has no border: q is tested before the load, not with it)
        if (!inside(q)) continue;
        if (!meta_shaded(load_guide_meta(q))) continue;
        float w = kernel_weight(dx, true) * kernel_weight(dy, true);
        sum += w * vec3(load_work_variance(iteration.input_slot, 0u, q),
                        load_work_variance(iteration.input_slot, 1u, q),
                        channels > 2u ? load_work_variance(iteration.input_slot, 2u, q) : 0.0);
        total += w;
      }
    variance = sum / max(total, 1e-6);
  }
  for (uint c = 0u; c < 3u; ++c)
    luminance_scale[c] = log2_e / (dn.sigmas.z * sqrt(max(variance[c], 0.0)) + 1e-10);

  // Each tap loop has a constant trip count so the compiler unrolls it.
  int kernel = int(dn.sigmas.w);
  bool three_by_three = kernel != 2;
  float h_centre = kernel_weight(0, three_by_three) * kernel_weight(0, three_by_three);
  for (uint c = 0u; c < 3u; ++c) {
    sums[c] = h_centre * centre_values[c].rgb;
    variance_sums[c] = h_centre * h_centre * centre_values[c].a;
    weight_sums[c] = h_centre;
  }
  if (kernel == 0 && iteration.step > 1u) {
    // The default kernel: the whole 3x3 at step 1 (the finest scale, where the raw noise is
    // independent per pixel: it leaves no pixel-checkerboard residue), then four taps of it with
    // its weights, a cross at steps 2, 8, 32, ... and a diagonal cross at 4, 16, ...: each
    // scale turned 45 degrees from the one before, at half the 3x3's taps. Measured as close
    // to the reference as the whole 3x3 at every step (docs/denoiser.md, "Cost"), closer with
    // the diagonal at the last step than with a cross there.
    if ((iteration.step & 0xAAAAAAAAu) != 0u) {
      const float h = kernel_weight(1, true) * kernel_weight(0, true);
      add_tap(pixel, ivec2(1, 0), h, channels);
      add_tap(pixel, ivec2(-1, 0), h, channels);
      add_tap(pixel, ivec2(0, 1), h, channels);
      add_tap(pixel, ivec2(0, -1), h, channels);
    } else {
      const float h = kernel_weight(1, true) * kernel_weight(1, true);
      add_tap(pixel, ivec2(1, 1), h, channels);
      add_tap(pixel, ivec2(-1, 1), h, channels);
      add_tap(pixel, ivec2(1, -1), h, channels);
      add_tap(pixel, ivec2(-1, -1), h, channels);
    }
  } else if (three_by_three) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (dx != 0 || dy != 0)
          add_tap(pixel, ivec2(dx, dy), kernel_weight(dx, true) * kernel_weight(dy, true), channels);
  } else {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx)
        if (dx != 0 || dy != 0)
          add_tap(pixel, ivec2(dx, dy), kernel_weight(dx, false) * kernel_weight(dy, false),
                  channels);
  }
  vec4 results[3];
  for (uint c = 0u; c < 3u; ++c) {
    float inverse_weight = 1.0 / weight_sums[c];  // >= the centre's kernel weight
    results[c] = vec4(sums[c] * inverse_weight, variance_sums[c] * inverse_weight * inverse_weight);
  }
  store_work(iteration.output_slot, pixel, results[0], results[1], results[2], channels);
  if (iteration.also_output != GLPT_DN_SLOT_NONE)
    store_work(iteration.also_output, pixel, results[0], results[1], results[2], channels);
}
