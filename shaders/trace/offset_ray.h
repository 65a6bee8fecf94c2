// Small geometric helpers of the trace pass: safe normalisation, GL's power, and ray origins
// that never hit the surface they leave.
#ifndef GLPT_SHADERS_TRACE_OFFSET_RAY_H
#define GLPT_SHADERS_TRACE_OFFSET_RAY_H

vec3 normalize_or(vec3 v, vec3 fallback) {
  float len2 = dot(v, v);
  return len2 > 1.0e-30 && !isinf(len2) ? v * inversesqrt(len2) : fallback;
}

// GL's (x)^e with 0^0 = 1 (GLSL's pow leaves 0^0 undefined, GL lighting needs 1).
float power_gl(float x, float e) { return e == 0.0 ? 1.0 : pow(max(x, 0.0), e); }

// Moves a ray origin off the surface along `n` by a few float ulps of the position (Waechter &
// Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6):
// scale independent, so it works for scenes of any size without a tuned epsilon. Coordinates
// near 0, whose ulps vanish, move by a fixed step instead; the paper's step (1/65536 below 1/32)
// assumes a scene of about unit size, so below 1 both scale with the point's largest coordinate
// (its distance from the eye, to a factor of at most sqrt 3): a scene of 1e-6 units, every
// coordinate under 1/32, would otherwise have its rays start 1.5e-5 off, 15 times its own size,
// past every occluder (no shadows, no occlusion: tests/extremes).
vec3 offset_ray_origin(vec3 p, vec3 n) {
  float magnitude = clamp(max(max(abs(p.x), abs(p.y)), abs(p.z)), 1.0e-30, 1.0);
  float origin_threshold = magnitude * (1.0 / 32.0);
  float float_scale = magnitude * (1.0 / 65536.0);
  const float kIntScale = 256.0;
  ivec3 offset_ulps = ivec3(kIntScale * n);
  vec3 p_ulps = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0 ? -offset_ulps.x : offset_ulps.x)),
                     intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0 ? -offset_ulps.y : offset_ulps.y)),
                     intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0 ? -offset_ulps.z : offset_ulps.z)));
  return vec3(abs(p.x) < origin_threshold ? p.x + float_scale * n.x : p_ulps.x,
              abs(p.y) < origin_threshold ? p.y + float_scale * n.y : p_ulps.y,
              abs(p.z) < origin_threshold ? p.z + float_scale * n.z : p_ulps.z);
}

#endif  // GLPT_SHADERS_TRACE_OFFSET_RAY_H
