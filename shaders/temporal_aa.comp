#version 460
// Temporal anti-aliasing: the last stage of the SVGF pipeline (Schied et al. 2017, figure 2),
// after the composite pass, before raster draws over it (blended geometry, HUD). While the
// denoiser runs, every frame's G-buffer is drawn at a new sub-pixel jitter (a Halton sequence),
// so one frame shows each edge at one place in its pixels; this pass blends each pixel's colour
// with its own history, reprojected to where the pixel's point was last frame, and the average
// over frames covers the pixel's area: edges come out anti-aliased, as the reference (whose
// samples are jittered over the pixel) is. Only pixels near an edge of geometry, texture or
// shadow are blended (see main); the others show the denoiser's frame.
//
// Karis, "High Quality Temporal Supersampling" (SIGGRAPH 2014 course): an exponential average
// (GLPT_TAA_ALPHA, or 1/length while the history is short), the history clipped in YCoCg to a
// box around this frame's 3x3 neighbourhood (Salvi's variance clipping, GDC 2016: mean plus or
// minus GLPT_TAA_GAMMA standard deviations), so that what the neighbourhood no longer shows (a
// disocclusion, a light switched, a moving shadow) leaves no trail. The position in the previous
// frame is the denoiser's (its motion buffer: the draw's previous transforms, or a deformed
// triangle's previous vertices); pixels it did not filter (the background, unlit surfaces) read
// their history where they are.
//
// Two dispatches (push constant): GLPT_TAA_RESOLVE writes the blend into this frame's history
// (the colour buffer's neighbourhoods must stay this frame's while it runs), GLPT_TAA_WRITE_BACK
// copies it into the colour buffer.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_image_load_formatted : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require

#include "shared_types.h"

layout(local_size_x = GLPT_TILE_SIZE, local_size_y = GLPT_TILE_SIZE,
       local_size_x_id = GLPT_SPEC_TILE_WIDTH, local_size_y_id = GLPT_SPEC_TILE_HEIGHT) in;

layout(std140, set = 0, binding = GLPT_TAA_BINDING_UNIFORMS) uniform TaaBlock {
  TemporalAaUniforms taa;
};
// BGRA8: no format qualifier (the view's format converts).
layout(set = 0, binding = GLPT_TAA_BINDING_COLOUR) uniform image2D colour_buffer;
// The denoiser's motion (TemporalAaUniforms::buffers.xy) and the histories (rgb colour and
// length), a texel per pixel (shared_types.h, pixel_buffers.h).
#include "pixel_buffers.h"
layout(set = 0, binding = GLPT_TAA_BINDING_SURFACE, rgba32ui)
    uniform readonly uimage2D gbuffer_surface;
#define GLPT_TILE_LIST_BINDING GLPT_TAA_BINDING_TILES
#include "svgf/tile_list.h"
// The denoiser's motion texel of pixel p (inside the image).
uvec4 load_motion(ivec2 p) {
  return PixelUintTexels(taa.buffers.xy).texels[layer_texel(taa.image.xy, 0u, p)];
}
vec4 load_history(ivec2 p) { return load_texel(taa.buffers.zw, taa.image.xy, 0u, p); }
vec4 load_previous_history(ivec2 p) { return load_texel(taa.histories.xy, taa.image.xy, 0u, p); }
void store_history(ivec2 p, vec4 value) { store_texel(taa.buffers.zw, taa.image.xy, 0u, p, value); }

layout(push_constant) uniform Dispatch {
  uint mode;  // GLPT_TAA_RESOLVE or GLPT_TAA_WRITE_BACK
};

bool inside(ivec2 q) {
  return q.x >= 0 && q.y >= 0 && q.x < int(taa.image.x) && q.y < int(taa.image.y);
}

vec3 to_ycocg(vec3 c) {
  return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b,
              -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}
vec3 from_ycocg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// `h` moved towards the box's centre until it lies within the box (clipping, not clamping each
// component: the colour keeps its hue where it is pulled in).
vec3 clip_to_box(vec3 h, vec3 centre, vec3 extent) {
  vec3 offset = h - centre;
  vec3 units = abs(offset) / max(extent, vec3(1e-4));
  float largest = max(units.x, max(units.y, units.z));
  return largest > 1.0 ? centre + offset / largest : h;
}

// Whether the denoiser filtered a pixel in this workgroup's tile or the 8 around it (the
// workgroups are its tiles, GLPT_IMAGE_TILE_WIDTH x GLPT_IMAGE_TILE_HEIGHT): else no pixel of
// the tile has the denoiser's motion in its 3x3, and only G-buffer surfaces (jittered) can show
// an edge that moves with the jitter.
bool near_filtered_tile() {
  ivec2 tiles = ivec2(tiles_across(taa.image.xy), tiles_down(taa.image.xy));
  ivec2 tile = ivec2(gl_WorkGroupID.xy);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 t = tile + ivec2(dx, dy);
      if (t.x >= 0 && t.y >= 0 && t.x < tiles.x && t.y < tiles.y &&
          tile_words[uint(t.y * tiles.x + t.x)] != 0u)
        return true;
    }
  return false;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (!inside(pixel)) return;
  if (mode == GLPT_TAA_WRITE_BACK) {
    // Only pixels the resolve blended (a positive length): an image store is the dearest
    // operation on lavapipe, and most pixels show this frame unchanged.
    vec4 h = load_history(pixel);
    if (h.a > 0.0)
      imageStore(colour_buffer, pixel, vec4(h.rgb, imageLoad(colour_buffer, pixel).a));
    return;
  }
  vec3 current_rgb = imageLoad(colour_buffer, pixel).rgb;
  // The history length stored: negative where the pixel shows this frame unchanged (the write
  // back skips it). A pixel that takes this frame keeps it as a history as long as the
  // denoiser's (255 where the denoiser did not filter it).
  float denoiser_length = 255.0;
  if ((taa.image.z & GLPT_TAA_HISTORY_VALID) == 0u) {
    store_history(pixel, vec4(current_rgb, -1.0));
    return;
  }
  // While a still image accumulates, the composite's average is the image: kept as the history
  // (with the denoiser's length at the pixel), nothing written back.
  if ((taa.image.z & GLPT_TAA_TAKE_CURRENT) != 0u) {
    uvec4 m = load_motion(pixel);
    if ((m.z >> 8) == taa.image.w) denoiser_length = float(m.z & 0xFFu);
    store_history(pixel, vec4(current_rgb, -max(denoiser_length, 1.0)));
    return;
  }
  // Far from what the denoiser filtered, a pixel no traced draw covers (the background, raster
  // draws: neither is jittered) shows this frame as it is.
  bool near = near_filtered_tile();
  if (!near && imageLoad(gbuffer_surface, pixel).x == 0u) {
    store_history(pixel, vec4(current_rgb, -255.0));
    return;
  }
  // Where the pixel's area was: the denoiser's reprojection of the nearest surface in the 3x3
  // pixels around (Karis 2014). A jittered edge pixel shows one surface in one frame and the
  // one behind in the next; its history, which covers both, follows the one in front, as the
  // background around an object does. Pixels the denoiser did not filter this frame (its
  // stamp), the background and unlit surfaces, carry no motion: where no pixel around has any,
  // the history is read here.
  vec2 offset = vec2(0.0);
  float nearest = 1.0 / 0.0, farthest = 0.0;
  int around = 0, with_motion = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = pixel + ivec2(dx, dy);
      if (!near || !inside(q)) continue;
      ++around;
      uvec4 m = load_motion(q);
      if ((m.z >> 8) != taa.image.w) continue;
      ++with_motion;
      if (dx == 0 && dy == 0) denoiser_length = float(m.z & 0xFFu);
      float depth = uintBitsToFloat(m.w);
      farthest = max(farthest, depth);
      if (depth < nearest) {
        nearest = depth;
        offset = uintBitsToFloat(m.xy) - vec2(q);
      }
    }
  // This frame's 3x3 neighbourhood: its mean and deviation (image edges: the pixels inside).
  vec3 current = to_ycocg(current_rgb);
  vec3 m1 = vec3(0.0), m2 = vec3(0.0);
  float count = 0.0, darkest = 1.0, brightest = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = pixel + ivec2(dx, dy);
      if (!inside(q)) continue;
      vec3 c = (dx == 0 && dy == 0) ? current : to_ycocg(imageLoad(colour_buffer, q).rgb);
      m1 += c;
      m2 += c * c;
      count += 1.0;
      darkest = min(darkest, c.x);
      brightest = max(brightest, c.x);
    }
  m1 /= count;
  // Jitter changes what a pixel shows only where its area holds an edge: of geometry (a step in
  // depth, or the edge of what the denoiser filtered: the background, an unlit surface) or of
  // texture and shadow (a luminance range over the 3x3 pixels of more than a fifth of their
  // mean). Elsewhere the denoiser's history integrates already, and averaging again only delays
  // changing light: the pixel shows this frame (measured on the denoiser tests: a light switched
  // on back in 4 frames instead of 6, the moving box 0.0062 against 0.0085; the still scene
  // 0.00136 against 0.00120).
  bool edge = (with_motion > 0 && with_motion < around) || farthest > 1.1 * nearest;
  bool detail = brightest - darkest > 0.2 * m1.x + 0.01;
  vec2 position = vec2(pixel) + offset;
  if (!(edge || detail) || !(denoiser_length > 1.0) || any(isnan(position)) ||
      any(isinf(position)) || any(lessThanEqual(position, vec2(-1.0))) ||
      any(greaterThanEqual(position, vec2(taa.image.xy)))) {
    store_history(pixel, vec4(current_rgb, -max(denoiser_length, 1.0)));
    return;
  }
  // Catmull-Rom over the 4x4 texels around (a bilinear read, repeated every frame of a motion,
  // blurs the history by half a pixel each time).
  ivec2 base = ivec2(floor(position));
  vec2 f = position - vec2(base);
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 wx[4] = vec2[4](w0, w1, w2, w3);
  vec4 sum = vec4(0.0);
  float weight_sum = 0.0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      ivec2 q = base + ivec2(i - 1, j - 1);
      float w = wx[i].x * wx[j].y;
      if (w == 0.0 || !inside(q)) continue;
      vec4 h = load_previous_history(q);
      h.a = abs(h.a);
      sum += w * h;
      weight_sum += w;
    }
  vec4 h = weight_sum > 0.1 ? sum / weight_sum : vec4(0.0);
  vec3 previous = to_ycocg(max(h.rgb, vec3(0.0)));
  if (!(h.a >= 1.0) || any(isnan(previous)) || any(isinf(previous))) {
    store_history(pixel, vec4(current_rgb, -1.0));
    return;
  }
  vec3 deviation = sqrt(max(m2 / count - m1 * m1, vec3(0.0)));
  vec3 kept = clip_to_box(previous, m1, taa.params.y * deviation);
  float history_length = min(min(h.a + 1.0, 255.0), max(denoiser_length, 1.0));
  vec3 result = mix(kept, current, max(taa.params.x, 1.0 / history_length));
  store_history(pixel, vec4(clamp(from_ycocg(result), 0.0, 1.0), history_length));
}
