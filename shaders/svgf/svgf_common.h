// What both SVGF passes (svgf_temporal.comp, svgf_atrous.comp) bind and share: the G-buffer
// (shared_types.h, GLPT_DN_BINDING_*), and through device addresses the raw channels, the guides
// and histories of this and the previous frame and the work slots (shared_types.h,
// DenoiseUniforms). Schied et al., "Spatiotemporal Variance-Guided Filtering", HPG 2017;
// docs/denoiser.md says what glpt does differently and why.
#ifndef GLPT_SHADERS_SVGF_COMMON_H
#define GLPT_SHADERS_SVGF_COMMON_H

#include "gbuffer_layout.h"
#include "shared_types.h"

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
#include "pixel_buffers.h"
// The guides: a DenoiseGuide (two texels) per pixel (shared_types.h).
layout(buffer_reference, std430, buffer_reference_align = 16) buffer GuideArray {
  DenoiseGuide guides[];
};
#define GLPT_TILE_LIST_BINDING GLPT_DN_BINDING_TILES
#include "svgf/tile_list.h"

// The invocation's pixel in a dispatch over the listed tiles (one workgroup, a tile, per list
// entry: the passes' workgroups are GLPT_IMAGE_TILE_WIDTH x GLPT_IMAGE_TILE_HEIGHT).
ivec2 listed_tile_pixel() {
  uint tile = tile_words[tile_count(dn.image.xy) + gl_WorkGroupID.x];
  return tile_origin(tile, dn.image.xy) + ivec2(gl_LocalInvocationID.xy);
}

// Pixel p's index in a layer of the per-pixel buffers (p inside the image).
uint pixel_index(ivec2 p) { return layer_texel(dn.image.xy, 0u, p); }
DenoiseGuide load_guide(ivec2 p) { return GuideArray(dn.guides.xy).guides[pixel_index(p)]; }
uvec4 load_guide_meta(ivec2 p) { return GuideArray(dn.guides.xy).guides[pixel_index(p)].meta; }
DenoiseGuide load_previous_guide(ivec2 p) {
  return GuideArray(dn.guides.zw).guides[pixel_index(p)];
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
void store_guide(ivec2 p, DenoiseGuide g) { GuideArray(dn.guides.xy).guides[pixel_index(p)] = g; }
// Channel c's fast history (rgb) at p, this frame's (store) or the previous frame's (load).
vec3 load_previous_fast(uint c, ivec2 p) {
  return load_texel(dn.histories.zw, dn.image.xy, c, p).rgb;
}
void store_fast(uint c, ivec2 p, vec3 value) {
  store_texel(dn.histories.xy, dn.image.xy, c, p, vec4(value, 0.0));
}
// The moments' layer `layer` (0: channels 0 and 1, 1: channel 2) at p, this frame's (store) or
// the previous frame's (load).
vec4 load_previous_moments(uint layer, ivec2 p) {
  return load_texel(dn.moments.zw, dn.image.xy, layer, p);
}
void store_moments(uint layer, ivec2 p, vec4 value) {
  store_texel(dn.moments.xy, dn.image.xy, layer, p, value);
}
// Channel c (rgb radiance, luminance variance) of pixel p in work slot `slot`. In floats: on
// lavapipe a half-float pack or unpack costs more than the gather or scatter of the bytes it
// saves.
vec4 load_work(uint slot, uint c, ivec2 p) {
  return load_texel(dn.buffers.xy, dn.image.xy, slot * GLPT_DN_WORK_LAYERS + c, p);
}
// Its variance alone: a load of one component (a trailing swizzle of load_work does not shrink
// the gather of all four).
float load_work_variance(uint slot, uint c, ivec2 p) {
  uint texel = layer_texel(dn.image.xy, slot * GLPT_DN_WORK_LAYERS + c, p);
  return PixelTexels(dn.buffers.xy).texels[texel].a;
}
// The `channels` (2 or 3) channels of pixel p into work slot `slot`.
void store_work(uint slot, ivec2 p, vec4 channel0, vec4 channel1, vec4 channel2, uint channels) {
  store_texel(dn.buffers.xy, dn.image.xy, slot * GLPT_DN_WORK_LAYERS, p, channel0);
  store_texel(dn.buffers.xy, dn.image.xy, slot * GLPT_DN_WORK_LAYERS + 1u, p, channel1);
  if (channels > 2u)
    store_texel(dn.buffers.xy, dn.image.xy, slot * GLPT_DN_WORK_LAYERS + 2u, p, channel2);
}
void store_motion(ivec2 p, uvec4 value) {
  PixelUintTexels(dn.buffers.zw).texels[pixel_index(p)] = value;
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

// The trace pass's channel c at p (inside the image): rgb radiance, and in channel 0 the samples
// traced (0: none).
vec4 raw_channel_texel(uint c, ivec2 p) { return load_channel(dn.channels.xy, dn.image.xy, c, p); }
vec3 raw_channel(ivec2 p, uint c) { return raw_channel_texel(c, p).rgb; }

// The size of one pixel at eye-space position `eye`: what depth tolerances scale with.
float pixel_footprint(vec3 eye) {
  return max(dn.params.y, dn.params.x * abs(eye.z)) + 1e-6 * length(eye);
}

#endif  // GLPT_SHADERS_SVGF_COMMON_H
