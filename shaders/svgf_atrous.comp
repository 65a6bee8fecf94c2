#version 460
// SVGF, step 2 (Schied et al. 2017, section 4.2): one iteration of the edge-avoiding a-trous
// wavelet filter, dispatched `iterations` times with steps 1, 2, 4, ... Per channel, each tap q of
// a B3-spline kernel (5x5; 3x3 with a kernel radius of 1) spaced `step` pixels apart weighs
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

#include "svgf/svgf_common.h"

layout(push_constant) uniform Iteration {
  uint step;      // tap spacing in pixels
  uint input_slot;
  uint output_slot;
  uint feedback;  // 1: also write the result as this frame's colour history
} iteration;

bool inside(ivec2 q) {
  return q.x >= 0 && q.y >= 0 && q.x < int(dn.image.x) && q.y < int(dn.image.y);
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (!inside(pixel)) return;
  DenoiseGuide centre = load_guide(pixel);
  if (centre.eye.w == 0.0) return;  // not shaded by the tracer: nothing to filter
  vec3 x_p = centre.eye.xyz;
  vec3 n_p = gbuffer_unpack_normal(centre.meta.z);
  float footprint = pixel_footprint(x_p);
  int radius = int(dn.sigmas.w);
  float kernel[3] = radius == 1 ? float[3](0.5, 0.25, 0.0) : float[3](0.375, 0.25, 0.0625);
  int step = int(iteration.step);
  uint channels = filtered_channels();  // a channel the frame cannot have is neither read nor written

  vec4 centre_values[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  float luminance_p[3] = float[3](0.0, 0.0, 0.0), sigma_l[3] = float[3](1.0, 1.0, 1.0);
  for (uint c = 0u; c < channels; ++c) {
    centre_values[c] = load_work(iteration.input_slot, pixel, c);
    luminance_p[c] = luminance(centre_values[c].rgb);
  }
  // The centre's variance through a 3x3 Gaussian (the paper's prefilter): one noisy variance
  // estimate must not stop the filter. Later iterations read variance the previous iteration
  // filtered already: they take it as it is (a third of their cost saved, no measured loss).
  if (iteration.step > 1u) {
    for (uint c = 0u; c < channels; ++c)
      sigma_l[c] = dn.sigmas.z * sqrt(max(centre_values[c].a, 0.0)) + 1e-10;
  } else {
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        ivec2 q = pixel + ivec2(dx, dy);
        if (!inside(q) || imageLoad(guide_eye, q).w == 0.0) continue;
        float w = (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25);
        sum += w * vec3(load_work(iteration.input_slot, q, 0u).a,
                        load_work(iteration.input_slot, q, 1u).a,
                        channels > 2u ? load_work(iteration.input_slot, q, 2u).a : 0.0);
        total += w;
      }
    vec3 variance = sum / max(total, 1e-6);
    for (uint c = 0u; c < channels; ++c)
      sigma_l[c] = dn.sigmas.z * sqrt(max(variance[c], 0.0)) + 1e-10;
  }

  vec3 sums[3];
  float variance_sums[3], weight_sums[3];
  for (uint c = 0u; c < channels; ++c) {
    float h = kernel[0] * kernel[0];
    sums[c] = h * centre_values[c].rgb;
    variance_sums[c] = h * h * centre_values[c].a;
    weight_sums[c] = h;
  }
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      if (dx == 0 && dy == 0) continue;
      ivec2 q = pixel + ivec2(dx, dy) * step;
      if (!inside(q)) continue;
      DenoiseGuide g = load_guide(q);
      // Another object's light is no estimate of this one's, however close its plane (gears side
      // by side, a character against a wall at the same depth).
      if (g.eye.w == 0.0 || g.meta.x != centre.meta.x) continue;
      float geometry = exp(-abs(dot(n_p, g.eye.xyz - x_p)) /
                           (dn.sigmas.x * footprint * float(step) * length(vec2(dx, dy)) + 1e-20)) *
                       pow(max(dot(n_p, gbuffer_unpack_normal(g.meta.z)), 0.0), dn.sigmas.y);
      if (!(geometry > 0.0)) continue;
      float h = kernel[abs(dx)] * kernel[abs(dy)] * geometry;
      for (uint c = 0u; c < channels; ++c) {
        vec4 value = load_work(iteration.input_slot, q, c);
        float w = h * exp(-abs(luminance(value.rgb) - luminance_p[c]) / sigma_l[c]);
        sums[c] += w * value.rgb;
        variance_sums[c] += w * w * value.a;
        weight_sums[c] += w;
      }
    }
  for (uint c = 0u; c < channels; ++c) {
    float inverse_weight = 1.0 / weight_sums[c];  // >= the centre's kernel weight
    vec4 result = vec4(sums[c] * inverse_weight,
                       variance_sums[c] * inverse_weight * inverse_weight);
    store_work(iteration.output_slot, pixel, c, result);
    if (iteration.feedback != 0u) {
      vec4 colour = imageLoad(history, ivec3(pixel, c));
      imageStore(history, ivec3(pixel, c), vec4(result.rgb, colour.a));
    }
  }
}
