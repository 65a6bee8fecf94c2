#version 460
// SVGF, step 1 (Schied et al. 2017, section 4.1): temporal accumulation per channel. Each pixel
// the tracer shaded is reprojected into the previous frame through its record state's previous
// transforms (GpuStateHistory: the draw's identity, so a still world under a moving camera keeps
// its history); the four bilinear taps there are kept only where they show the same object (id),
// a normal within ~25 degrees and a point within two pixels of the surface's plane (else a 3x3
// box around the reprojected point, as the paper's fallback; else no history). Colour and the
// first two luminance moments are exponential averages (alpha, or 1/length while the history is
// short). Against stale light (a light switched, a moving shadow or highlight), the history is
// clamped to a fast average of the raw colour (alpha 0.5) plus or minus a few standard deviations
// of its noise, and a clamped history is shortened so the next frames weigh new samples more
// (docs/denoiser.md, "No stale light"). Variance: from the moments, or estimated spatially where
// the history is under four frames long.
//
// A deformed surface (GpuStateHistory.info.z: a refit BLAS whose previous positions the instance
// table carries) is reprojected through its triangle's previous vertices: a short ray query along
// the normal finds the pixel's triangle and barycentrics, and the point moves by the triangle's
// deformation before the state's transforms apply.
//
// Writes work slot 0 (colour + variance: the a-trous filter's input), this frame's fast
// average and moments (the colour history is the first a-trous iteration's result, or written
// here when there is no iteration), guide, and where the pixel's point was in the previous frame
// (the motion buffer, for the temporal anti-aliasing pass).
// A channel the frame cannot have (filtered_channels) is neither read nor written (the next
// frame is told, GLPT_DN_PREVIOUS_NO_SPECULAR); a pixel the tracer did not shade writes nothing
// (its guide keeps an earlier frame's stamp, which no reader takes for this frame's). Everything
// written is in buffers reached by device address (shared_types.h): lavapipe stores an image
// texel lane by lane through a function call, a buffer texel with one scatter.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_image_load_formatted : require

#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_EXT_ray_query : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require

#include "svgf/svgf_common.h"

layout(set = 0, binding = GLPT_DN_BINDING_SCENE) uniform accelerationStructureEXT scene;
layout(std430, set = 0, binding = GLPT_DN_BINDING_INSTANCES) readonly buffer InstanceTable {
  GpuInstance instances[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer PositionArray {
  GpuPosition positions[];
};

// The point `eye` of a surface (shading normal `normal`) where it was last frame, in this frame's
// eye space, when its triangle deformed since: moved by the difference of the triangle's
// previous and present vertices at the point's barycentrics. `eye` itself where no triangle lies
// at the point (within a pixel footprint) or it did not deform.
vec3 before_deformation(vec3 eye, vec3 normal) {
  float reach = 4.0 * pixel_footprint(eye);
  rayQueryEXT query;
  // The segment holds the surface itself and rarely anything else: the first triangle found
  // will do (checked by its distance below), every one taken as opaque.
  rayQueryInitializeEXT(query, scene, gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT,
                        GLPT_MASK_VISIBLE, eye + reach * normal, 0.0, -normal, 2.0 * reach);
  while (rayQueryProceedEXT(query)) {
  }
  if (rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionTriangleEXT)
    return eye;
  if (abs(rayQueryGetIntersectionTEXT(query, true) - reach) > 0.25 * reach) return eye;
  GpuInstance instance = instances[rayQueryGetIntersectionInstanceCustomIndexEXT(query, true)];
  if (all(equal(instance.tables.zw, uvec2(0u)))) return eye;
  uint first = 3u * uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, true));
  vec2 b = rayQueryGetIntersectionBarycentricsEXT(query, true);
  vec3 w = vec3(1.0 - b.x - b.y, b.x, b.y);
  PositionArray now = PositionArray(instance.addresses.xy);
  PositionArray before = PositionArray(instance.tables.zw);
  vec3 moved = vec3(0.0);
  for (uint k = 0u; k < 3u; ++k)
    moved += w[k] * (before.positions[first + k].position.xyz -
                     now.positions[first + k].position.xyz);
  vec3 result = eye + mat3(rayQueryGetIntersectionObjectToWorldEXT(query, true)) * moved;
  return any(isnan(result)) || any(isinf(result)) ? eye : result;
}

// Whether the tracer shaded the pixel with samples the denoiser should filter.
bool shaded(ivec2 q, out uvec4 surface) {
  surface = imageLoad(gbuffer_surface, q);
  if (surface.x == 0u || !(raw_channel_texel(0u, q).a > 0.0)) return false;
  return (surface.w & GLPT_GBUFFER_LIT) != 0u || (dn.image.z & GLPT_DN_UNLIT_AO) != 0u;
}

// Whether the previous frame's pixel q shows the point `previous_eye` (the current pixel's
// surface point in the previous eye space) of object `id` with normal `previous_normal`.
// `tap_length` is that pixel's history length (read with the guide, not again).
bool tap_matches(ivec2 q, uint id, vec3 previous_eye, vec3 previous_normal, float tolerance,
                 out uint tap_length) {
  tap_length = 0u;
  if (!inside(q)) return false;
  DenoiseGuide g = load_previous_guide(q);
  tap_length = g.meta.y & 0xFFu;
  // (id 0, no surface, is never a pixel's; a guide of an earlier frame has another stamp)
  if (g.meta.x != id || (g.meta.y >> 8) != dn.slots.w) return false;
  if (dot(previous_normal, guide_normal(g)) < 0.9) return false;
  return abs(dot(previous_normal, g.eye.xyz - previous_eye)) <= tolerance;
}

// Adds the previous frame's history at q (of length tap_length) with weight w.
void add_history(ivec2 q, float w, uint tap_length, inout vec3 colour[3], inout vec3 fast[3],
                 inout vec2 moments[3], inout float history_length, inout float weight_sum) {
  weight_sum += w;
  history_length += w * float(tap_length);
  // The moments of two channels a texel (shared_types.h).
  vec4 first_two = load_previous_moments(0u, q);
  colour[0] += w * load_work(dn.slots.y, 0u, q).rgb;
  colour[1] += w * load_work(dn.slots.y, 1u, q).rgb;
  fast[0] += w * load_previous_fast(0u, q);
  fast[1] += w * load_previous_fast(1u, q);
  moments[0] += w * first_two.xy;
  moments[1] += w * first_two.zw;
  if (filtered_channels() > 2u) {
    colour[2] += w * load_work(dn.slots.y, 2u, q).rgb;
    fast[2] += w * load_previous_fast(2u, q);
    moments[2] += w * load_previous_moments(1u, q).xy;
  }
}

void main() {
  // Dispatched over the tiles the trace pass listed (those with a pixel to filter): the guides
  // of the others keep an earlier frame's stamp, which no pass takes for this frame's.
  ivec2 pixel = listed_tile_pixel();
  uvec4 surface;
  if (!inside(pixel) || !shaded(pixel, surface)) return;
  vec3 eye = imageLoad(gbuffer_position, pixel).xyz;
  vec3 normal = gbuffer_unpack_normal(surface.y);
  uint channels = filtered_channels();
  // Neighbouring pixels mostly show the same record state: where a whole subgroup does, its
  // history is read once at a uniform index (lavapipe loads a per-invocation index one
  // invocation at a time, 40 words each).
  uint state_index = surface.x - 1u;
  GpuStateHistory sh;
  if (subgroupAllEqual(state_index))
    sh = state_histories[subgroupBroadcastFirst(state_index)];
  else
    sh = state_histories[state_index];
  uint id = sh.info.x;

  // ---- reprojection into the previous frame
  vec3 previous_colour[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
  vec3 previous_fast[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
  vec2 previous_moments[3] = vec2[3](vec2(0.0), vec2(0.0), vec2(0.0));
  float previous_length = 0.0, weight_sum = 0.0;
  // Where the pixel's point was (for the anti-aliasing pass): here, until reprojected.
  vec2 previous_position = vec2(pixel);
  if ((dn.image.z & GLPT_DN_HISTORY_VALID) != 0u && sh.info.y != 0u && id > 1u) {
    // A deformed surface's point moves back by its triangle's deformation first: its draw's
    // transform alone finds a wrong history there, or none. (Trying the transform first and the
    // triangle only where it found none measured worse than either alone: a patchwork of both.)
    vec3 point = sh.info.z != 0u ? before_deformation(eye, normal) : eye;
    vec4 previous_eye = sh.to_previous_eye * vec4(point, 1.0);
    vec4 clip = sh.previous_projection * previous_eye;
    // Normals go through the inverse transpose (a motion may scale).
    vec3 previous_normal = normalize(transpose(inverse(mat3(sh.to_previous_eye))) * normal);
    if (clip.w > 0.0 && !any(isnan(previous_normal))) {
      previous_eye.xyz /= previous_eye.w;
      vec2 window = (clip.xy / clip.w * 0.5 + 0.5) * sh.viewport.zw + sh.viewport.xy;
      // Pixel centres are at +0.5. This frame's sub-pixel jitter is no motion: the G-buffer was
      // drawn shifted by it (raster_ff.vert), so the pixel's point lies `jitter` before its
      // centre, and the history of a still point is read at this very pixel. (Subtracting it,
      // as before, read 2 x jitter away: still scene under accumulation, 16 frames, relMSE
      // 0.00136 -> 0.00121.)
      vec2 position = window - 0.5 + dn.jitter.xy;
      previous_position = position;
      ivec2 base = ivec2(floor(position));
      vec2 f = position - vec2(base);
      float tolerance = 2.0 * pixel_footprint(previous_eye.xyz);
      float weights[4] = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y,
                                  f.x * f.y);
      for (int t = 0; t < 4; ++t) {
        ivec2 q = base + ivec2(t & 1, t >> 1);
        uint tap_length;
        if (weights[t] > 0.0 &&
            tap_matches(q, id, previous_eye.xyz, previous_normal, tolerance, tap_length))
          add_history(q, weights[t], tap_length, previous_colour, previous_fast, previous_moments,
                      previous_length, weight_sum);
      }
      if (weight_sum == 0.0) {
        ivec2 centre = ivec2(floor(position + 0.5));
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = centre + ivec2(dx, dy);
            uint tap_length;
            if (tap_matches(q, id, previous_eye.xyz, previous_normal, tolerance, tap_length))
              add_history(q, 1.0, tap_length, previous_colour, previous_fast, previous_moments,
                          previous_length, weight_sum);
          }
      }
    }
  }
  bool has_history = weight_sum > 1e-4;
  float history_length = 1.0;
  if (has_history) {
    float inverse_weight = 1.0 / weight_sum;
    history_length = min(floor(previous_length * inverse_weight + 0.5) + 1.0, 255.0);
    for (uint c = 0u; c < 3u; ++c) {
      previous_colour[c] *= inverse_weight;
      previous_fast[c] *= inverse_weight;
      previous_moments[c] *= inverse_weight;
    }
  }

  // ---- accumulation per channel
  float fast_alpha = dn.temporal.z;
  // The standard deviation of an exponential average of alpha a over noise of deviation s is
  // s * sqrt(a / (2 - a)).
  float fast_spread = sqrt(fast_alpha / (2.0 - fast_alpha));
  bool clamped_any = false;
  // The noise the clamp allows for: the spread of this frame's raw luminance over the 3x3
  // pixels around (a temporal estimate would count the very step the clamp is to find).
  float noise_sigma[3] = float[3](0.0, 0.0, 0.0);
  if (has_history && dn.temporal.w > 0.0) {
    vec2 sums[3] = vec2[3](vec2(0.0), vec2(0.0), vec2(0.0));
    float count = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        ivec2 q = pixel + ivec2(dx, dy);
        if (!inside(q)) continue;
        // Any traced sample counts (no G-buffer read: this runs for every pixel every frame).
        vec4 direct = raw_channel_texel(0u, q);
        if (!(direct.a > 0.0)) continue;
        count += 1.0;
        float l0 = luminance(direct.rgb), l1 = luminance(raw_channel(q, 1u)),
              l2 = channels > 2u ? luminance(raw_channel(q, 2u)) : 0.0;
        sums[0] += vec2(l0, l0 * l0);
        sums[1] += vec2(l1, l1 * l1);
        sums[2] += vec2(l2, l2 * l2);
      }
    for (uint c = 0u; c < 3u; ++c) {
      vec2 m = sums[c] / max(count, 1.0);
      noise_sigma[c] = sqrt(max(m.y - m.x * m.x, 0.0));
    }
  }
  float variances[3] = float[3](0.0, 0.0, 0.0);
  vec3 colours[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
  vec3 fasts[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
  vec2 all_moments[3] = vec2[3](vec2(0.0), vec2(0.0), vec2(0.0));
  // A specular channel the previous frame did not filter has no history stored: it was black
  // there (and the fast-history clamp brings it up as for a light switched on).
  if (channels > 2u && (dn.image.z & GLPT_DN_PREVIOUS_NO_SPECULAR) != 0u) {
    previous_colour[2] = vec3(0.0);
    previous_fast[2] = vec3(0.0);
    previous_moments[2] = vec2(0.0);
  }
  for (uint c = 0u; c < 3u; ++c) {
    if (c >= channels) break;
    vec3 raw = raw_channel(pixel, c);
    float l = luminance(raw);
    vec3 colour = raw, fast = raw;
    vec2 moments = vec2(l, l * l);
    if (has_history) {
      vec3 slow = previous_colour[c];
      vec2 slow_moments = previous_moments[c];
      fast = mix(previous_fast[c], raw, fast_alpha);
      float alpha = max(dn.temporal.x, 1.0 / history_length);
      float moments_alpha = max(dn.temporal.y, 1.0 / history_length);
      bool clamped = false;
      if (dn.temporal.w > 0.0) {
        // In luminance (what the moments measure): the history moves towards the fast average
        // until its luminance is within the window.
        // The 3x3 estimate is 0 where this frame's nine samples agree, as a sparse signal's
        // (rare indirect hits) often do, and then any noise of the fast average read as a step.
        // There the spread of the history's own samples (its moments, before this frame) stands
        // in; it does not hold this frame's step.
        vec2 pm = previous_moments[c];
        float sigma = noise_sigma[c] > 0.0 ? noise_sigma[c] : sqrt(max(pm.y - pm.x * pm.x, 0.0));
        float fast_l = luminance(fast), slow_l = luminance(slow);
        float width = dn.temporal.w * sigma * fast_spread + 0.02 * max(fast_l, 0.0);
        if (abs(slow_l - fast_l) > width) {
          float t = 1.0 - width / abs(slow_l - fast_l);  // in (0, 1]
          vec3 kept = mix(slow, fast, t);
          // Stale light: the history jumps to the fast average's range and counts as short;
          // its moments move with it, keeping their variance.
          float variance = max(slow_moments.y - slow_moments.x * slow_moments.x, 0.0);
          float m1 = luminance(kept);
          float short_alpha = 1.0 / dn.params.z;
          colour = mix(kept, raw, max(alpha, short_alpha));
          moments = mix(vec2(m1, variance + m1 * m1), vec2(l, l * l),
                        max(moments_alpha, short_alpha));
          clamped = true;
        }
      }
      if (!clamped) {
        colour = mix(slow, raw, alpha);
        moments = mix(slow_moments, vec2(l, l * l), moments_alpha);
      }
      clamped_any = clamped_any || clamped;
    }
    // Nothing non-finite is kept (the tracer drops such samples; this guards the history).
    if (any(isnan(colour)) || any(isinf(colour)) || any(isnan(moments)) || any(isinf(moments))) {
      colour = vec3(0.0);
      moments = vec2(0.0);
    }
    colours[c] = colour;
    variances[c] = max(moments.y - moments.x * moments.x, 0.0);
    fasts[c] = fast;
    all_moments[c] = moments;
  }
  store_fast(0u, pixel, fasts[0]);
  store_fast(1u, pixel, fasts[1]);
  store_moments(0u, pixel, vec4(all_moments[0], all_moments[1]));
  if (channels > 2u) {
    store_fast(2u, pixel, fasts[2]);
    store_moments(1u, pixel, vec4(all_moments[2], 0.0, 0.0));
  }
  // A clamp shortens the history for the next frames' weights but keeps the moments' variance
  // (moved with the colour above): the spatial estimate is for histories that are short.
  bool short_history = history_length < 4.0;
  if (clamped_any) history_length = min(history_length, dn.params.z);

  // ---- variance: spatial where the history is short (the paper's 7x7 bilateral estimate; 5x5
  // here, weighted by normal and plane distance)
  if (short_history) {
    vec2 sums[3] = vec2[3](vec2(0.0), vec2(0.0), vec2(0.0));
    float total = 0.0;
    float tolerance = 2.0 * pixel_footprint(eye);
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        ivec2 q = pixel + ivec2(dx, dy);
        if (!inside(q)) continue;
        uvec4 s;
        if (!shaded(q, s)) continue;
        vec3 qe = imageLoad(gbuffer_position, q).xyz;
        float distance = abs(dot(normal, qe - eye));
        float w = exp(-distance / (tolerance * max(length(vec2(dx, dy)), 1.0))) *
                  pow(max(dot(normal, gbuffer_unpack_normal(s.y)), 0.0), 32.0);
        if (!(w > 0.0)) continue;
        total += w;
        for (uint c = 0u; c < 3u; ++c) {
          if (c >= channels) break;
          float l = luminance(raw_channel(q, c));
          sums[c] += w * vec2(l, l * l);
        }
      }
    if (total > 0.0)
      for (uint c = 0u; c < 3u; ++c) {
        vec2 m = sums[c] / total;
        variances[c] = max(m.y - m.x * m.x, 0.0);
      }
  }
  // The moments (or the spatial estimate) give the variance of one sample; the colour handed on
  // is an average of several, whose variance is smaller: that of a plain average of n samples
  // while 1/n is above alpha, then an exponential average's, a / (2 - a) of one sample's. The
  // a-trous filter then stops at luminance steps larger than the integrated colour's noise,
  // not a single sample's (GLPT_DENOISE_MEAN_VARIANCE; the 2017 paper takes one sample's).
  if ((dn.image.z & GLPT_DN_MEAN_VARIANCE) != 0u) {
    float a = dn.temporal.x;
    float integrated = 1.0 / history_length >= a ? 1.0 / history_length : a / (2.0 - a);
    for (uint c = 0u; c < 3u; ++c) variances[c] *= integrated;
  }
  store_work(0u, pixel, vec4(colours[0], variances[0]), vec4(colours[1], variances[1]),
             vec4(colours[2], variances[2]), channels);
  // Without a-trous iterations the integrated colour is the history.
  if (dn.image.w == 0u)
    store_work(dn.slots.x, pixel, vec4(colours[0], variances[0]),
               vec4(colours[1], variances[1]), vec4(colours[2], variances[2]), channels);
  store_guide(pixel, make_guide(eye, normal, id, uint(history_length)));
  if ((dn.image.z & GLPT_DN_MOTION) != 0u)
    store_motion(pixel, uvec4(floatBitsToUint(previous_position),
                              (dn.slots.z << 8) | uint(history_length), floatBitsToUint(-eye.z)));
}
