// What both SVGF passes (svgf_temporal.comp, svgf_atrous.comp) bind and share: the G-buffer, the
// raw channels, the guides and histories of this and the previous frame, and the work slots
// (shared_types.h, GLPT_DN_BINDING_*). Schied et al., "Spatiotemporal Variance-Guided Filtering",
// HPG 2017; docs/denoiser.md says what glpt does differently and why.
#ifndef GLPT_SHADERS_SVGF_COMMON_H
#define GLPT_SHADERS_SVGF_COMMON_H

#include "gbuffer_layout.h"
#include "shared_types.h"
#include "svgf/work_texels.h"

layout(local_size_x = GLPT_TILE_SIZE, local_size_y = GLPT_TILE_SIZE,
       local_size_x_id = GLPT_SPEC_TILE_WIDTH, local_size_y_id = GLPT_SPEC_TILE_HEIGHT) in;

layout(std140, set = 0, binding = GLPT_DN_BINDING_UNIFORMS) uniform DenoiseBlock {
  DenoiseUniforms dn;
};
layout(std430, set = 0, binding = GLPT_DN_BINDING_STATES) readonly buffer StateHistories {
  GpuStateHistory state_histories[];
};
layout(set = 0, binding = GLPT_DN_BINDING_POSITION, rgba32f) uniform readonly image2D gbuffer_position;
layout(set = 0, binding = GLPT_DN_BINDING_SURFACE, rgba32ui) uniform readonly uimage2D gbuffer_surface;
layout(set = 0, binding = GLPT_DN_BINDING_CHANNELS + 0, rgba32f) uniform readonly image2D raw_channel0;
layout(set = 0, binding = GLPT_DN_BINDING_CHANNELS + 1, rgba32f) uniform readonly image2D raw_channel1;
layout(set = 0, binding = GLPT_DN_BINDING_CHANNELS + 2, rgba32f) uniform readonly image2D raw_channel2;
layout(set = 0, binding = GLPT_DN_BINDING_GUIDE, rgba32f) uniform image2D guide_eye;
layout(set = 0, binding = GLPT_DN_BINDING_GUIDE_META, rgba32ui) uniform uimage2D guide_meta;
layout(set = 0, binding = GLPT_DN_BINDING_GUIDE_PREVIOUS, rgba32f)
    uniform readonly image2D previous_guide_eye;
layout(set = 0, binding = GLPT_DN_BINDING_GUIDE_META_PREVIOUS, rgba32ui)
    uniform readonly uimage2D previous_guide_meta;
layout(set = 0, binding = GLPT_DN_BINDING_HISTORY, rgba32ui) uniform uimage2DArray history;
layout(set = 0, binding = GLPT_DN_BINDING_HISTORY_PREVIOUS, rgba32ui)
    uniform readonly uimage2DArray previous_history;
layout(set = 0, binding = GLPT_DN_BINDING_MOMENTS, rgba32f)
    uniform writeonly image2DArray history_moments;
layout(set = 0, binding = GLPT_DN_BINDING_MOMENTS_PREVIOUS, rgba32f)
    uniform readonly image2DArray previous_history_moments;
layout(set = 0, binding = GLPT_DN_BINDING_WORK, rgba32ui) uniform uimage2DArray work;
layout(set = 0, binding = GLPT_DN_BINDING_MOTION, rgba32ui) uniform writeonly uimage2D motion;

#define GLPT_TILE_LIST_BINDING GLPT_DN_BINDING_TILES
#include "svgf/tile_list.h"

// The invocation's pixel in a dispatch over the listed tiles (one workgroup, a tile, per list
// entry: the passes' workgroups are GLPT_IMAGE_TILE_WIDTH x GLPT_IMAGE_TILE_HEIGHT).
ivec2 listed_tile_pixel() {
  uint tile = tile_words[tile_count(dn.image.xy) + gl_WorkGroupID.x];
  return tile_origin(tile, dn.image.xy) + ivec2(gl_LocalInvocationID.xy);
}

DenoiseGuide load_guide(ivec2 p) {
  return DenoiseGuide(imageLoad(guide_eye, p), imageLoad(guide_meta, p));
}
DenoiseGuide load_previous_guide(ivec2 p) {
  return DenoiseGuide(imageLoad(previous_guide_eye, p), imageLoad(previous_guide_meta, p));
}
DenoiseGuide make_guide(vec3 eye, vec3 normal, uint id, uint history_length) {
  return DenoiseGuide(vec4(eye, normal.z), uvec4(max(id, 1u), history_length | (dn.slots.z << 8),
                                                 floatBitsToUint(normal.xy)));
}
// Whether this frame filters the pixel whose guide has `meta` (a surface's, and this frame's
// stamp: the passes skip tiles, whose guides stay as an earlier frame wrote them).
bool meta_shaded(uvec4 meta) { return meta.x != 0u && (meta.y >> 8) == dn.slots.z; }
bool guide_shaded(DenoiseGuide g) { return meta_shaded(g.meta); }
vec3 guide_normal(DenoiseGuide g) { return vec3(uintBitsToFloat(g.meta.zw), g.eye.w); }
void store_guide(ivec2 p, DenoiseGuide g) {
  imageStore(guide_eye, p, g.eye);
  imageStore(guide_meta, p, g.meta);
}
// The work slots keep two channels per texel in half floats (shared_types.h,
// GLPT_DN_BINDING_WORK): on lavapipe an image store is a scalar store per lane and component,
// the dearest operation of the a-trous iterations, and a load is a call; one texel for the two
// diffuse channels halves both. Half floats keep 11 bits: far below what 8-bit output shows.
// Channels 0 (xy) and 1 (zw) of pixel p in work slot `slot`, packed.
uvec4 load_work_pair(uint slot, ivec2 p) {
  return imageLoad(work, ivec3(p, slot * GLPT_DN_WORK_LAYERS));
}
vec4 load_work_specular(uint slot, ivec2 p) {
  return unpack_work(imageLoad(work, ivec3(p, slot * GLPT_DN_WORK_LAYERS + 1u)).xy);
}
// The `channels` (2 or 3) channels of pixel p into work slot `slot`.
void store_work(uint slot, ivec2 p, vec4 channel0, vec4 channel1, vec4 channel2, uint channels) {
  imageStore(work, ivec3(p, slot * GLPT_DN_WORK_LAYERS),
             uvec4(pack_work(channel0), pack_work(channel1)));
  if (channels > 2u)
    imageStore(work, ivec3(p, slot * GLPT_DN_WORK_LAYERS + 1u), uvec4(pack_work(channel2), 0u, 0u));
}

// Whether pixel q lies in the image.
bool inside(ivec2 q) {
  return q.x >= 0 && q.y >= 0 && q.x < int(dn.image.x) && q.y < int(dn.image.y);
}

// The channels the passes filter: direct and indirect diffuse, and specular where any surface
// reflects specularly (GLPT_DN_NO_SPECULAR; specular is the last channel).
//
// Both passes loop over channels (and taps) with constant trip counts, a channel the frame does
// not have skipped by a uniform test, so that every array is indexed by constants once the loops
// are unrolled: an array indexed by a value the compiler cannot resolve lives in memory, which
// lavapipe reads and writes one invocation at a time.
uint filtered_channels() { return (dn.image.z & GLPT_DN_NO_SPECULAR) != 0u ? 2u : 3u; }

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

vec3 raw_channel(ivec2 p, uint c) {
  return c == 0u   ? imageLoad(raw_channel0, p).rgb
         : c == 1u ? imageLoad(raw_channel1, p).rgb
                   : imageLoad(raw_channel2, p).rgb;
}

// The size of one pixel at eye-space position `eye`: what depth tolerances scale with.
float pixel_footprint(vec3 eye) {
  return max(dn.params.y, dn.params.x * abs(eye.z)) + 1e-6 * length(eye);
}

#endif  // GLPT_SHADERS_SVGF_COMMON_H
