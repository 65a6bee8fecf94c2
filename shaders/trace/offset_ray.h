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

// The same for a point computed from terms of up to `term_magnitude` (eye-space units): a
// position is no more precise than the products summed to make it, so a surface 1e5 units from
// its object's origin under a modelview that brings it near the eye is 1/128 coarse in eye space
// too, and the BLAS (object coordinates) intersects rays at that precision. Its origin moves at
// least kTermUlps float steps of that magnitude along `n`. Measured on the corner 1e5 from the
// origin (tests/reference_tracer CornerFarFromTheOrigin, worst block of 48 in SE; tests/extremes
// PathTracedScene1e5FromTheOrigin..., mean difference to the scene at the origin in levels):
// 0 steps -9.4 levels (acne); 1: +3.2 SE, 0.28; 2: +2.7 SE, 0.48; 4: -3.2 SE, 0.85; 8: -6.1 SE
// (fails), 1.32; 16: -12.7 SE; 64: light leaks, 294 SE. 2 leaves a margin on both sides (the
// G-buffer keeps the magnitude as a power of two rounded up: 2 to 4 steps there).
vec3 offset_ray_origin(vec3 p, vec3 n, float term_magnitude) {
  const float kTermUlps = 2.0;
  vec3 by_position = offset_ray_origin(p, n);
  vec3 by_terms = p + n * (min(term_magnitude, 1.0e37) * (kTermUlps / 8388608.0));
  return mix(min(by_position, by_terms), max(by_position, by_terms), greaterThanEqual(n, vec3(0.0)));
}

// The eye-space term magnitude of `object_to_eye * (p, 1)` (see above).
float term_magnitude(mat4x3 object_to_eye, vec3 p) {
  vec3 terms = abs(object_to_eye[0]) * abs(p.x) + abs(object_to_eye[1]) * abs(p.y) +
               abs(object_to_eye[2]) * abs(p.z) + abs(object_to_eye[3]);
  return max(max(terms.x, terms.y), terms.z);
}

#endif  // GLPT_SHADERS_TRACE_OFFSET_RAY_H
