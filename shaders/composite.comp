#version 460
// Composite pass of path-traced mode: the radiance channels of the trace pass (and of the
// denoiser, when it ran) become GL's colour buffer. Per pixel this frame covered:
//   colour = fog(albedo * (direct + indirect) + specular reflectance * specular + emission)
// (the channels hold light per unit of reflectance, trace/gbuffer_material.h) with the
// reflectances and emission from the G-buffer and GL's fog of the pixel's draw; unlit pixels
// show the G-buffer's colour (times their ambient visibility under GLPT_UNLIT=ao). The colours
// of all frames accumulated so far are averaged; samples that did not cover the pixel (its edge,
// under sub-pixel jitter) show what the colour buffer holds there (the clears and raster draws
// of this frame), which is how partially covered edge pixels blend. The result is clamped to
// [0, 1] and written into the colour buffer(s) the pixel's draw writes.
//
// When the denoiser ran (DenoiseUniforms image.z GLPT_DN_ACTIVE), the pixel shows the average of
// the frames composited from its channels since the accumulation's second frame (where it
// filtered the pixel; the raw colour where it did not), mixed with the average of the raw
// samples by params.w (how far accumulation has come towards GLPT_DENOISE_UNTIL samples, from
// which on the raw average alone is shown). Averaging the denoised frames of a still scene
// anti-aliases them as the raw average is (each frame's G-buffer is jittered) instead of showing
// the last frame's jittered edges, and averages the denoiser's own residual noise; when anything
// changes, the accumulation and this average start again. (The first frame of an accumulation
// stores nothing for the average: a moving scene, every frame of which is a first, pays nothing
// for it.) The raw average always sums the raw samples: it converges to the unbiased image,
// whatever the denoiser did on the way.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_image_load_formatted : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require

#include "gbuffer_layout.h"
#include "shared_types.h"
#include "trace/gbuffer_material.h"

layout(local_size_x = GLPT_TILE_SIZE, local_size_y = GLPT_TILE_SIZE,
       local_size_x_id = GLPT_SPEC_TILE_WIDTH, local_size_y_id = GLPT_SPEC_TILE_HEIGHT) in;

layout(std140, set = 0, binding = GLPT_CO_BINDING_FRAME) uniform FrameBlock {
  FrameUniforms frame;
};
layout(std430, set = 0, binding = GLPT_CO_BINDING_STATES) readonly buffer StateTable {
  GpuTraceState states[];
};
// Per pixel, layer 0 rgb: sum of the covered samples' colour, a: sum of their alpha; layer 1
// x: how many samples were covered, y: how many samples there were, z and w: the same counts from
// the accumulation's second frame on; layer 2 (frames the denoiser ran, from the second on): as
// layer 0 with each frame's denoised colour for its samples. In a buffer reached by device
// address (FrameUniforms::buffers.xy, pixel_buffers.h): not a storage image, which lavapipe
// stores lane by lane through a function call, nor a buffer binding, which is limited to
// maxStorageBufferRange (lavapipe: 128 MiB, 2.8 million pixels).
layout(set = 0, binding = GLPT_CO_BINDING_GBUFFER + GLPT_GBUFFER_POSITION, rgba32f)
    uniform readonly image2D gbuffer_position;
layout(set = 0, binding = GLPT_CO_BINDING_GBUFFER + GLPT_GBUFFER_SURFACE, rgba32ui)
    uniform readonly uimage2D gbuffer_surface;
layout(set = 0, binding = GLPT_CO_BINDING_GBUFFER + GLPT_GBUFFER_MATERIAL0, rgba32ui)
    uniform readonly uimage2D gbuffer_material0;
layout(set = 0, binding = GLPT_CO_BINDING_GBUFFER + GLPT_GBUFFER_MATERIAL1, rgba32ui)
    uniform readonly uimage2D gbuffer_material1;
#include "pixel_buffers.h"
layout(std140, set = 0, binding = GLPT_CO_BINDING_DENOISE) uniform DenoiseBlock {
  DenoiseUniforms dn;
};
// The colour buffers are BGRA8: no format qualifier (the view's format converts).
layout(set = 0, binding = GLPT_CO_BINDING_FRONT) uniform image2D front_buffer;
layout(set = 0, binding = GLPT_CO_BINDING_BACK) uniform image2D back_buffer;

// GL's fog (GL 1.5 3.10) on a lit pixel's radiance; unlit pixels come fogged from the G-buffer.
vec3 apply_fog(uint state, float fog_coordinate, vec3 radiance) {
  uint mode = states[state].info.y;
  if (mode == 0u) return radiance;
  vec4 p = states[state].fog_params;
  float z = fog_coordinate;
  float f = mode == 1u ? (p.z - z) * p.w : mode == 2u ? exp(-p.x * z) : exp(-(p.x * z) * (p.x * z));
  return mix(states[state].fog_color.rgb, radiance, clamp(f, 0.0, 1.0));
}

// This frame's colour of a pixel the G-buffer covers (rgb) and its alpha, from the radiance of
// the channels `light` (GLPT_CHANNEL_* order).
vec4 composite(ivec2 pixel, uvec4 surface, vec3 light[GLPT_CHANNELS]) {
  uvec4 m0 = imageLoad(gbuffer_material0, pixel);
  if ((surface.w & GLPT_GBUFFER_LIT) == 0u) {
    vec4 color = unpackUnorm4x8(m0.x);
    if ((frame.options.x & GLPT_OPTION_UNLIT_AO) != 0u)
      color.rgb *= light[GLPT_CHANNEL_INDIRECT_DIFFUSE].r;
    return color;
  }
  GBufferMaterial m = gbuffer_material(surface, m0, imageLoad(gbuffer_material1, pixel));
  vec3 diffuse_light = light[GLPT_CHANNEL_DIRECT_DIFFUSE] + light[GLPT_CHANNEL_INDIRECT_DIFFUSE];
  Bsdf bsdf = material_bsdf(m.diffuse.rgb, m.specular, m.shininess);
  vec3 radiance = diffuse_channel_factor(bsdf.diffuse, m.diffuse.rgb, m.ambient) * diffuse_light +
                  bsdf.specular * light[GLPT_CHANNEL_SPECULAR] + m.emission;
  float fog_coordinate = imageLoad(gbuffer_position, pixel).w;
  return vec4(apply_fog(surface.x - 1u, fog_coordinate, radiance), m.diffuse.a);
}

// Writes the pixel's average over all accumulated samples into the colour buffers `targets`:
// `sum` holds the covered samples (`covered` of the `total`); the others show what the colour
// buffer holds. With denoised_weight < 1 the average is mixed by it with the average of the
// denoised frames: `denoised_sum` of their covered samples, `denoised_counts` x of y samples.
void write_average(ivec2 pixel, uint targets, vec4 sum, float covered, float total,
                   vec4 denoised_sum, vec2 denoised_counts, float denoised_weight) {
  for (uint t = 0u; t < 2u; ++t) {
    if ((targets & (1u << t)) == 0u) continue;
    vec4 background = t == 0u ? imageLoad(front_buffer, pixel) : imageLoad(back_buffer, pixel);
    vec4 color = clamp((sum + (total - covered) * background) / total, 0.0, 1.0);
    if (denoised_weight < 1.0 && denoised_counts.y > 0.0) {
      vec4 denoised_color =
          (denoised_sum + (denoised_counts.y - denoised_counts.x) * background) / denoised_counts.y;
      color = mix(clamp(denoised_color, 0.0, 1.0), color, denoised_weight);
    }
    if (t == 0u)
      imageStore(front_buffer, pixel, color);
    else
      imageStore(back_buffer, pixel, color);
  }
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(frame.image.x) || pixel.y >= int(frame.image.y)) return;
  uvec4 surface = imageLoad(gbuffer_surface, pixel);
  // Samples of this frame: covered ones the trace pass kept (it drops non-finite ones, which then
  // count nowhere), uncovered ones all of the frame's.
  vec4 direct = load_channel(frame.buffers.zw, frame.image.xy, GLPT_CHANNEL_DIRECT_DIFFUSE, pixel);
  float traced = direct.a;
  bool covered = surface.x != 0u && traced > 0.0;
  uint samples = frame.sampling.y;
  vec3 raw[GLPT_CHANNELS] = vec3[GLPT_CHANNELS](
      direct.rgb,
      load_channel(frame.buffers.zw, frame.image.xy, GLPT_CHANNEL_INDIRECT_DIFFUSE, pixel).rgb,
      load_channel(frame.buffers.zw, frame.image.xy, GLPT_CHANNEL_SPECULAR, pixel).rgb);
  vec4 sum = covered ? composite(pixel, surface, raw) * traced : vec4(0.0);
  // The denoiser filtered what it calls shaded (svgf_temporal.comp): covered pixels, lit ones or
  // any under GLPT_UNLIT=ao; its result is in the slot of its last iteration.
  bool denoising = (dn.image.z & GLPT_DN_ACTIVE) != 0u;
  vec4 denoised_sum = sum;
  float denoised_weight = denoising ? clamp(dn.params.w, 0.0, 1.0) : 1.0;
  bool lit = (surface.w & GLPT_GBUFFER_LIT) != 0u;
  if (denoising && covered && (lit || (dn.image.z & GLPT_DN_UNLIT_AO) != 0u)) {
    uint slot = dn.image.w == 0u ? 0u : 1u + (dn.image.w - 1u) % 2u;
    // The work slots (shared_types.h, DenoiseUniforms::buffers.xy): a layer per channel. A channel
    // the denoiser did not filter (GLPT_DN_NO_SPECULAR) is not there: taken raw.
    uint layer = slot * GLPT_DN_WORK_LAYERS;
    vec3 specular = raw[GLPT_CHANNEL_SPECULAR];
    if ((dn.image.z & GLPT_DN_NO_SPECULAR) == 0u)
      specular = load_texel(dn.buffers.xy, dn.image.xy, layer + 2u, pixel).rgb;
    vec3 light[GLPT_CHANNELS] = vec3[GLPT_CHANNELS](
        load_texel(dn.buffers.xy, dn.image.xy, layer, pixel).rgb,
        load_texel(dn.buffers.xy, dn.image.xy, layer + 1u, pixel).rgb, specular);
    denoised_sum = composite(pixel, surface, light) * traced;
  }
  float count = covered ? traced : 0.0;
  float total = surface.x != 0u ? traced : float(samples);
  vec2 denoised_counts = vec2(count, total);
  vec2 later_counts = vec2(0.0);  // of frames after the first (layer 1 zw)
  if (frame.sampling.x != 0u) {
    sum += load_texel(frame.buffers.xy, frame.image.xy, 0u, pixel);
    vec4 counts = load_texel(frame.buffers.xy, frame.image.xy, 1u, pixel);
    count += counts.x;
    total += counts.y;
    // The denoiser runs from an accumulation's first frame until it stops for good (at
    // GLPT_DENOISE_UNTIL samples): while it runs, layer 2 holds the frames' from the second on
    // where any of them covered the pixel.
    if (denoising && counts.z > 0.0)
      denoised_sum += load_texel(frame.buffers.xy, frame.image.xy, 2u, pixel);
    denoised_counts += counts.zw;
    later_counts = denoised_counts;
  }
  if (samples > 0u) {
    store_texel(frame.buffers.xy, frame.image.xy, 0u, pixel, sum);
    store_texel(frame.buffers.xy, frame.image.xy, 1u, pixel, vec4(count, total, later_counts));
    if (denoising && denoised_weight < 1.0 && later_counts.x > 0.0)
      store_texel(frame.buffers.xy, frame.image.xy, 2u, pixel, denoised_sum);
  }
  if (count > 0.0 && total > 0.0) {
    uint targets = surface.x != 0u ? states[surface.x - 1u].info.z : frame.image.z;
    write_average(pixel, targets, sum, count, total, denoised_sum, denoised_counts,
                  denoised_weight);
  }
}
