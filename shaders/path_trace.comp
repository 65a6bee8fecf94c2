#version 460
// Trace pass of path-traced mode (docs/light-transport.md). Primary visibility comes from the
// G-buffer (gbuffer_layout.h), which the raster pipelines drew with GL's coverage, depth test,
// culling, clip planes and textures. For each pixel it covers, `frame.sampling.y` paths:
//   at every vertex, next-event estimation of one of the surface's GL lights (chosen in
//   proportion to its estimated contribution; sphere and distant lights with multiple importance
//   sampling against the BSDF), then a bounce sampled from the diffuse or the GGX lobe, with
//   Russian roulette after the first; emission where bounces hit it; GL's ambient light at the
//   primary vertex, occluded by one ray-traced ambient-occlusion ray.
// The result is written as linear HDR radiance into the channels (shared_types.h: direct
// diffuse, indirect diffuse, specular; the diffuse ones divided by the albedo), this frame's
// samples averaged. composite.comp turns them into the GL colour buffer.
// With GLPT_OPTION_GL_PARITY the primary vertex is lit by GL's own lighting equation instead
// (GL 1.5 2.14.1, per pixel, no rays). Everything is in GL eye space.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_query : require
#extension GL_EXT_shader_image_load_formatted : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_EXT_nonuniform_qualifier : require

#include "gbuffer_layout.h"
#include "shared_types.h"

layout(local_size_x = GLPT_TILE_SIZE, local_size_y = GLPT_TILE_SIZE,
       local_size_x_id = GLPT_SPEC_TILE_WIDTH, local_size_y_id = GLPT_SPEC_TILE_HEIGHT) in;

layout(set = 0, binding = GLPT_PT_BINDING_SCENE) uniform accelerationStructureEXT scene;
layout(std430, set = 0, binding = GLPT_PT_BINDING_INSTANCES) readonly buffer InstanceTable {
  GpuInstance instances[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_LIGHTS) readonly buffer LightTable {
  GpuLight lights[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_EMITTERS) readonly buffer EmitterTable {
  GpuEmitter emitters[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_BLUE_NOISE) readonly buffer BlueNoise {
  uint blue_noise_mask[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_CLIP_PLANES) readonly buffer ClipPlaneTable {
  GpuClipPlanes clip_planes[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_STATES) readonly buffer StateTable {
  GpuTraceState states[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_COUNTERS) buffer Counters {
  GpuCounters counters;
};
layout(std140, set = 0, binding = GLPT_PT_BINDING_FRAME) uniform FrameBlock {
  FrameUniforms frame;
};
layout(set = 0, binding = GLPT_PT_BINDING_GBUFFER + GLPT_GBUFFER_POSITION, rgba32f)
    uniform readonly image2D gbuffer_position;
layout(set = 0, binding = GLPT_PT_BINDING_GBUFFER + GLPT_GBUFFER_SURFACE, rgba32ui)
    uniform readonly uimage2D gbuffer_surface;
layout(set = 0, binding = GLPT_PT_BINDING_GBUFFER + GLPT_GBUFFER_MATERIAL0, rgba32ui)
    uniform readonly uimage2D gbuffer_material0;
layout(set = 0, binding = GLPT_PT_BINDING_GBUFFER + GLPT_GBUFFER_MATERIAL1, rgba32ui)
    uniform readonly uimage2D gbuffer_material1;
#include "pixel_buffers.h"
// This frame's channel c at pixel p (inside the image).
vec4 load_channel(uint c, ivec2 p) { return load_channel(frame.buffers.zw, frame.image.xy, c, p); }
void store_channel(uint c, ivec2 p, vec4 value) {
  store_texel(frame.buffers.zw, frame.image.xy, c, p, value);
}
#define GLPT_TILE_LIST_BINDING GLPT_PT_BINDING_DENOISE_TILES
#include "svgf/tile_list.h"
layout(push_constant) uniform TracePassBlock {
  uint trace_pass;  // GLPT_TRACE_PASS_*
} push;
layout(set = 0, binding = GLPT_PT_BINDING_TEXTURES) uniform sampler2D textures[GLPT_TRACE_TEXTURES];
layout(set = 0, binding = GLPT_PT_BINDING_TEXTURES_1D)
    uniform sampler1D textures_1d[GLPT_TRACE_TEXTURES_OTHER];
layout(set = 0, binding = GLPT_PT_BINDING_TEXTURES_3D)
    uniform sampler3D textures_3d[GLPT_TRACE_TEXTURES_OTHER];
layout(set = 0, binding = GLPT_PT_BINDING_TEXTURES_CUBE)
    uniform samplerCube textures_cube[GLPT_TRACE_TEXTURES_OTHER];

layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer PositionArray {
  GpuPosition positions[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer VertexArray {
  ShadingVertex vertices[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer MaterialArray {
  GpuMaterial materials[];
};

#include "trace/rng.h"
#include "trace/offset_ray.h"
#include "trace/texture.h"
#include "trace/queries.h"
#include "trace/surface.h"
#include "trace/lights.h"
#include "trace/emitters.h"

uint g_rays = 0u;

bool has_option(uint option) { return (frame.options.x & option) != 0u; }

// What one path contributes to the three channels, per unit of the primary vertex's reflectance
// (trace_path; lighting_gl: radiance), and GL's ambient term at the primary vertex apart: that
// is radiance as it is, with a reflectance of its own (GL's ambient colour).
struct Channels {
  vec3 direct;
  vec3 indirect;
  vec3 specular;
  vec3 ambient;
};

// Adds `value` to the channel of the primary vertex's lobe: diffuse light found directly goes to
// `direct`, everything found beyond the first bounce to `indirect`; the specular lobe has one.
void add_to_channel(inout Channels c, uint lobe, bool direct, vec3 value) {
  if (lobe == GLPT_LOBE_SPECULAR)
    c.specular += value;
  else if (direct)
    c.direct += value;
  else
    c.indirect += value;
}

// ---- GL's lighting equation (GL-parity mode) ---------------------------------------------------

// GL 1.5 2.14.1 at the primary vertex, per pixel: ambient, diffuse and specular of every light,
// unoccluded, with GL's viewer (local or infinite), spot cones on every light and GL's
// unnormalised Blinn-Phong specular.
Channels lighting_gl(Surface s) {
  Channels c;
  c.direct = vec3(0.0);
  c.indirect = vec3(0.0);
  c.specular = vec3(0.0);
  vec3 ambient_light = states[s.state].global_ambient.rgb;
  bool local_viewer = (states[s.state].info.w & GLPT_STATE_LOCAL_VIEWER) != 0u;
  vec3 to_viewer = local_viewer ? normalize_or(-s.position, vec3(0.0, 0.0, 1.0)) : vec3(0.0, 0.0, 1.0);
  uint count = min(states[s.state].info.x, uint(GLPT_MAX_STATE_LIGHTS));
  for (uint i = 0u; i < count; ++i) {
    GpuLight light = lights[states[s.state].lights[i >> 2u][i & 3u]];
    vec3 to_light;
    float d = 0.0;
    if (light.position.w != 0.0) {
      vec3 offset = light.position.xyz / light.position.w - s.position;
      d = length(offset);
      to_light = normalize_or(offset, vec3(0.0, 0.0, 1.0));
    } else {
      to_light = light.position.xyz;
    }
    float attenuation = attenuation_gl(light, to_light, d, true);
    ambient_light += attenuation * light.ambient.rgb;
    float n_dot_l = dot(s.normal, to_light);
    if (n_dot_l <= 0.0) continue;
    c.direct += attenuation * n_dot_l * s.diffuse_gl * light.diffuse.rgb;
    vec3 h = normalize_or(to_light + to_viewer, s.normal);
    c.specular += attenuation * power_gl(dot(s.normal, h), s.shininess) * s.specular_gl *
                  light.specular.rgb;
  }
  c.ambient = s.ambient * ambient_light;
  return c;
}

// ---- light transport ---------------------------------------------------------------------------

// One ray that may be blocked, with what it brings where it is not: a next-event sample of a
// light (its radiance through each lobe, weighted) or the ambient-occlusion ray. A vertex
// collects its rays first and traces them in one loop: lavapipe inlines the BVH traversal at
// every query call site, and one site per kind of query keeps the pipeline small enough to
// compile in reasonable time.
struct OcclusionRay {
  vec3 direction;
  float t_max;
  uint cull_mask;
  bool ambient;     // the AO ray: blocked by an occluder within its own size (t_max unbounded)
  vec3 diffuse;     // what the ray brings through the diffuse lobe (already divided by its pdf)
  vec3 specular;
};

// Every light of the state (GLPT_LIGHT_CHOICE_ALL), an emitter, the AO ray.
const uint kMaxOcclusionRays = GLPT_MAX_STATE_LIGHTS + 2u;

// Ambient occlusion (seed 001's obscurance, with a ray instead of the depth buffer): a
// cosine-distributed ray from `s`, blocked by an occluder within the fixed radius frame.params.x
// or, when that is 0, within the occluder's own size: a box occludes the floor it stands on
// within about a box's width, whatever else is in the scene. `brings`: the ambient term.
bool ambient_ray(Surface s, inout Sampler rng, vec3 brings, out OcclusionRay ray) {
  ray.direction = sample_cosine_hemisphere(s.normal, next_random2(rng));
  ray.t_max = frame.params.x > 0.0 ? frame.params.x : kUnboundedRay;
  ray.cull_mask = GLPT_MASK_VISIBLE;
  ray.ambient = true;
  ray.diffuse = brings;
  ray.specular = vec3(0.0);
  return dot(ray.direction, s.offset_normal) > 0.0;  // else into the surface itself: occluded
}

// Next-event estimation at `s` (view direction v in `basis`'s local frame) for light i of
// `choice`: the direction and what it brings through each lobe, MIS-weighted against BSDF
// sampling when a bounce ray will also be traced from `s` (`mis`). False: nothing to bring.
bool light_ray(Surface s, Bsdf bsdf, Basis basis, vec3 v, LightChoice choice, uint i, bool mis,
               inout Sampler rng, out OcclusionRay ray) {
  ray.ambient = false;
  ray.diffuse = vec3(0.0);
  ray.specular = vec3(0.0);
  LightView view = choice.views[i];
  float probability = choice.probability[i];
  vec2 u = next_random2(rng);
  if (probability <= 0.0) return false;
  bool area = view.one_minus_cos > 0.0;
  ray.direction = area ? sample_cone(view.direction, view.one_minus_cos, u) : view.direction;
  ray.t_max = view.distance - view.sphere_radius;
  ray.cull_mask = lights[choice.indices[i]].params.x;
  // A direction below the flat triangle but above the smooth surface (near the terminator of a
  // coarse mesh) is lit: its shadow ray leaves from the lifted origin (surface.h).
  vec3 l = to_local(basis, ray.direction);
  if (l.z <= 0.0) return false;
  vec3 f_diffuse = bsdf_lobe_cos(bsdf, GLPT_LOBE_DIFFUSE, v, l);
  vec3 f_specular = bsdf_lobe_cos(bsdf, GLPT_LOBE_SPECULAR, v, l);
  if (max3(f_diffuse + f_specular) <= 0.0) return false;
  if (!area) {
    // A delta light: GL's colour is irradiance / pi at normal incidence.
    ray.diffuse = kPi * f_diffuse * view.diffuse / probability;
    ray.specular = kPi * f_specular * view.specular / probability;
    return true;
  }
  float pdf = probability * cone_pdf(view.one_minus_cos);
  float w_diffuse = 1.0, w_specular = 1.0;
  if (mis) {
    w_diffuse = power_heuristic(pdf, lobe_probability(bsdf, GLPT_LOBE_DIFFUSE) *
                                         lobe_pdf(bsdf, GLPT_LOBE_DIFFUSE, v, l));
    w_specular = power_heuristic(pdf, lobe_probability(bsdf, GLPT_LOBE_SPECULAR) *
                                          lobe_pdf(bsdf, GLPT_LOBE_SPECULAR, v, l));
  }
  ray.diffuse = w_diffuse * f_diffuse * view.diffuse / pdf;
  ray.specular = w_specular * f_specular * view.specular / pdf;
  return true;
}

// Next-event estimation of one emissive triangle (emitters.h) at `s`, MIS-weighted against BSDF
// sampling when a bounce ray will also be traced (`mis`). False: nothing to bring.
bool emitter_ray(Surface s, Bsdf bsdf, Basis basis, vec3 v, bool mis, inout Sampler rng,
                 out OcclusionRay ray) {
  ray.ambient = false;
  ray.diffuse = vec3(0.0);
  ray.specular = vec3(0.0);
  ray.cull_mask = GLPT_MASK_VISIBLE;
  float u_choice = next_random(rng);
  EmitterSample e;
  bool found = sample_emitter(s.position, u_choice, next_random2(rng), e);
  ray.direction = e.direction;
  // Stop short of the emitter itself: only what lies between blocks it.
  ray.t_max = e.distance * (1.0 - 1.0e-3);
  if (!found || max3(e.radiance) <= 0.0) return false;
  vec3 l = to_local(basis, ray.direction);
  if (l.z <= 0.0 || dot(ray.direction, s.offset_normal) <= 0.0) return false;
  vec3 f_diffuse = bsdf_lobe_cos(bsdf, GLPT_LOBE_DIFFUSE, v, l);
  vec3 f_specular = bsdf_lobe_cos(bsdf, GLPT_LOBE_SPECULAR, v, l);
  float w_diffuse = 1.0, w_specular = 1.0;
  if (mis) {
    w_diffuse = power_heuristic(e.pdf, lobe_probability(bsdf, GLPT_LOBE_DIFFUSE) *
                                           lobe_pdf(bsdf, GLPT_LOBE_DIFFUSE, v, l));
    w_specular = power_heuristic(e.pdf, lobe_probability(bsdf, GLPT_LOBE_SPECULAR) *
                                            lobe_pdf(bsdf, GLPT_LOBE_SPECULAR, v, l));
  }
  ray.diffuse = w_diffuse * f_diffuse * e.radiance / e.pdf;
  ray.specular = w_specular * f_specular * e.radiance / e.pdf;
  return true;
}

// Whether `ray` from `s` is blocked (the one occlusion query site of the pass).
bool blocked(Surface s, OcclusionRay ray) {
  ++g_rays;
  float t;
  int instance;
  bool hit = query_occlusion(s.shadow_position, ray.direction, ray.t_max, ray.cull_mask,
                             !ray.ambient || frame.params.x > 0.0,
                             ray.ambient ? kLookingRayFlags : kLightRayFlags, t, instance);
  if (!hit || !ray.ambient || frame.params.x > 0.0) return hit;
  return t < uintBitsToFloat(instances[instance].materials.w);
}

// The primary vertex's lobes with unit reflectance: the channels then hold light per unit of
// reflectance whatever the texel's albedo (gbuffer_material.h), and the composite pass multiplies
// the reflectance back. A bounce still picks the specular lobe about as often as the material's
// own reflectances say (the probability is the unit lobes' ratio, so MIS and the bounce weights
// follow), within [0.05, 0.95] so that neither channel goes unsampled where one reflectance is
// ~0 (black lettering), and half the time where both are. `specular_material`: the draw's
// material reflects specularly somewhere (the texel may not). `specular_scale` turns the
// specular lobe's results into light per unit of reflectance.
Bsdf unit_reflectance_bsdf(Bsdf material, bool specular_material, out float specular_scale) {
  Bsdf unit = material;
  unit.diffuse = vec3(1.0);
  unit.specular = vec3(0.0);
  specular_scale = 0.0;
  if (max3(material.specular) > 0.0 || specular_material) {
    float d = luminance(material.diffuse), s = luminance(material.specular);
    float p = d + s > 1.0e-4 ? clamp(s / (d + s), 0.05, 0.95) : 0.5;
    unit.specular = vec3(p / (1.0 - p));
    specular_scale = (1.0 - p) / p;
  }
  return unit;
}

// The light of the path starting at the G-buffer surface `first` towards the viewer, by
// channel, per unit of the primary vertex's reflectance. An unlit `first` (GLPT_UNLIT=ao) traces
// its ambient-occlusion ray only: ambient.r is its visibility.
Channels trace_path(Surface first, inout Sampler rng) {
  Channels c;
  c.direct = vec3(0.0);
  c.indirect = vec3(0.0);
  c.specular = vec3(0.0);
  c.ambient = vec3(0.0);
  float specular_scale = 1.0;
  Surface s = first;
  vec3 to_viewer = towards_viewer(s.state, s.position);
  vec3 throughput = vec3(1.0);
  uint first_lobe = GLPT_LOBE_DIFFUSE;
  // The ray cone's width grows with the distance travelled (texture levels at bounce hits).
  vec4 viewer = states[s.state].viewer;
  float path_length = viewer.w != 0.0 ? length(s.position - viewer.xyz) : 0.0;
  uint bounces = first.lit ? frame.sampling.z : 0u;
  // The MIS weight of emission a bounce ray hits against the emitter sampling of the vertex it
  // left (1 where that could not have found it).
  float emission_weight = 1.0;
  for (uint depth = 0u;; ++depth) {
    Basis basis = make_basis(s.normal);
    vec3 v = to_local(basis, to_viewer);
    // Unlit surfaces hit by bounces: a diffuse reflector of their colour, or (GLPT_UNLIT=emit)
    // an emitter of it that reflects nothing more.
    bool emitter_only = !s.lit && has_option(GLPT_OPTION_UNLIT_EMIT);
    if (depth > 0u) {
      vec3 emitted = emitter_only ? s.diffuse_gl : s.emission;
      add_to_channel(c, first_lobe, false, throughput * emitted * emission_weight);
      if (emitter_only) break;
    }
    Bsdf bsdf = material_bsdf(s.diffuse_gl, s.specular_gl, s.shininess);
    if (depth == 0u && first.lit)
      bsdf = unit_reflectance_bsdf(
          bsdf, (states[s.state].info.w & GLPT_STATE_SPECULAR_MATERIAL) != 0u, specular_scale);
    // Seen from below its shading normal (a normal facing away from the viewer, or leaning
    // away near a silhouette) a surface has no specular reflection: the lobe needs v.z > 0.
    if (v.z <= 1.0e-4) bsdf.specular = vec3(0.0);
    LightChoice choice = choose_lights(s.state, s.position, s.normal);
    bool bounce = depth < bounces;

    // The vertex's occlusion rays: its light samples, and at the primary vertex the AO ray.
    OcclusionRay rays[kMaxOcclusionRays];
    uint ray_count = 0u;
    if (depth == 0u) {
      // GL's ambient light, seen at the primary vertex only: it stands for the light of the
      // world around the scene, which bounces do not trace (docs/light-transport.md).
      vec3 ambient = first.lit ? s.ambient * choice.ambient : vec3(1.0);
      if (!has_option(GLPT_OPTION_AO))
        c.ambient += ambient;
      else if (max3(ambient) > 0.0 && ambient_ray(s, rng, ambient, rays[ray_count]))
        ++ray_count;
    }
    if (choice.count > 0u && first.lit) {
      bool all = frame.options.y == GLPT_LIGHT_CHOICE_ALL;
      uint begin = all ? 0u : pick_light(choice, next_random(rng));
      uint end = all ? choice.count : min(begin + 1u, choice.count);
      for (uint i = begin; i < end; ++i)
        if (light_ray(s, bsdf, basis, v, choice, i, bounce, rng, rays[ray_count])) ++ray_count;
    }
    if (emitter_count() > 0u && first.lit &&
        emitter_ray(s, bsdf, basis, v, bounce, rng, rays[ray_count]))
      ++ray_count;
    for (uint r = 0u; r < ray_count; ++r) {
      OcclusionRay ray = rays[r];
      if ((!ray.ambient && !has_option(GLPT_OPTION_SHADOWS)) || !blocked(s, ray)) {
        if (ray.ambient) {
          c.ambient += ray.diffuse;
        } else {
          add_to_channel(c, depth == 0u ? GLPT_LOBE_DIFFUSE : first_lobe, depth == 0u,
                         throughput * ray.diffuse);
          add_to_channel(c, depth == 0u ? GLPT_LOBE_SPECULAR : first_lobe, depth == 0u,
                         throughput * ray.specular);
        }
      }
    }
    if (!bounce) break;

    // The bounce: one lobe chosen in proportion to its reflectance, then sampled.
    float p_specular = specular_lobe_probability(bsdf);
    if (max3(bsdf.diffuse) <= 0.0 && p_specular <= 0.0) break;
    uint lobe = next_random(rng) < p_specular ? GLPT_LOBE_SPECULAR : GLPT_LOBE_DIFFUSE;
    float p_lobe = lobe == GLPT_LOBE_SPECULAR ? p_specular : 1.0 - p_specular;
    vec3 l = sample_lobe(bsdf, lobe, v, next_random2(rng));
    float pdf = p_lobe * lobe_pdf(bsdf, lobe, v, l);
    if (l.z <= 0.0 || pdf <= 0.0) break;
    vec3 direction = normalize(to_world(basis, l));
    if (dot(direction, s.offset_normal) <= 0.0) break;  // below the geometric surface
    vec3 weight = bsdf_lobe_cos(bsdf, lobe, v, l) / pdf;
    if (depth == 0u) first_lobe = lobe;

    // The world first; a ray that misses it sees the sky where the frame has one, looked up
    // from the eye in the ray's direction (the sky is drawn around the camera, so its radiance
    // depends on the direction alone), else GLPT_ENVIRONMENT. One query site for both (lavapipe
    // inlines the traversal at each).
    Hit hit;
    bool found = false, at_sky = false;
    for (uint look = 0u; look < 2u && !found; ++look) {
      at_sky = look == 1u;
      if (at_sky && !has_option(GLPT_OPTION_SKY)) break;
      ++g_rays;
      found = trace_closest(at_sky ? vec3(0.0) : s.shadow_position, direction, kUnboundedRay,
                            at_sky ? GLPT_MASK_SKY : GLPT_MASK_VISIBLE, hit);
    }
    bool sky_hit = found && at_sky;
    if (sky_hit) found = false;
    float t_hit = found ? hit.t : kUnboundedRay;
    // The ray passing through one of the surface's area lights: the other technique of MIS.
    for (uint i = 0u; i < choice.count; ++i) {
      LightView view = choice.views[i];
      GpuLight light = lights[choice.indices[i]];
      float t_light = light_hit_distance(view, s.shadow_position, direction, light_centre(light));
      if (t_light >= t_hit) continue;
      float light_pdf = light_direction_pdf(choice, i, direction);
      if (light_pdf <= 0.0) continue;
      vec3 radiance = lobe == GLPT_LOBE_SPECULAR ? view.specular : view.diffuse;
      add_to_channel(c, first_lobe, depth == 0u,
                     throughput * weight * radiance * power_heuristic(pdf, light_pdf));
    }
    emission_weight = 1.0;
    if (found && first.lit) {
      float emitter_pdf =
          emitter_direction_pdf(instances[hit.instance], hit.primitive, direction, hit.t);
      if (emitter_pdf > 0.0) emission_weight = power_heuristic(pdf, emitter_pdf);
    }
    throughput *= weight;
    if (!found && !sky_hit) {
      if (has_option(GLPT_OPTION_ENVIRONMENT))
        add_to_channel(c, first_lobe, false, throughput * frame.environment.rgb);
      break;
    }
    // Russian roulette after the first bounce: paths that carry little go on rarely, with
    // their weight raised to keep the estimate unbiased.
    if (found && depth >= 1u) {
      float keep = clamp(max3(throughput), 0.05, 0.95);
      if (next_random(rng) >= keep) break;
      throughput /= keep;
    }
    path_length += hit.t;
    s = load_surface(hit, direction, path_length * frame.params.w);
    if (sky_hit) {
      // The sky's radiance is the colour GL draws it with (unlit, textured). The sky is the world
      // around the scene GL's ambient term stands for, and that term is the diffuse reflection
      // at the primary vertex (docs/light-transport.md): there the sky is not counted again.
      // Reflections see it, and so do later vertices, where ambient is never added.
      if (depth > 0u || lobe == GLPT_LOBE_SPECULAR)
        add_to_channel(c, first_lobe, false, throughput * s.diffuse_gl);
      break;
    }
    to_viewer = -direction;
  }
  c.specular *= specular_scale;
  return c;
}

bool finite(vec3 v) { return !any(isnan(v)) && !any(isinf(v)); }

// ---- GLPT_SCALE below 1: a coarse grid traced, the other pixels filled -----------------------

// The cells of the coarse grid across the window.
ivec2 grid_cells() { return ivec2(ceil(vec2(frame.image.xy) * frame.trace_grid.xy)); }

// The pixel the grid pass traces for `cell` this frame: the cell covers [cell, cell + 1) / scale
// of the window; trace_grid.zw moves the pixel within it from frame to frame, so accumulation and
// the denoiser's history see every pixel traced in turn.
ivec2 grid_pixel(ivec2 cell) {
  ivec2 p = ivec2(floor((vec2(cell) + frame.trace_grid.zw) / frame.trace_grid.xy));
  return min(p, ivec2(frame.image.xy) - 1);
}

// Fill pass: true when `pixel` needs no tracing of its own - the grid pass traced it, or it takes
// this frame's radiance from traced pixels of the 3x3 cells around it that lie on the same
// surface (the same record state and lighting, normals within 25 degrees, on the pixel's tangent
// plane), weighted by a tent one cell wide (bilinear interpolation between the traced pixels
// around it: exact for radiance that varies linearly; joint bilateral upsampling with the
// full-resolution G-buffer as guide). The channels hold radiance with the albedo divided out,
// so texture detail is not blurred. A pixel no neighbour matches (a thin object, a silhouette)
// is traced.
bool filled_from_grid(ivec2 pixel, uvec4 surface) {
  ivec2 home = ivec2(floor((vec2(pixel) + 0.5) * frame.trace_grid.xy));
  ivec2 cells = grid_cells();
  bool fill = surface.x != 0u && frame.sampling.y > 0u &&
              !(((surface.w & GLPT_GBUFFER_LIT) != 0u) && has_option(GLPT_OPTION_GL_PARITY)) &&
              ((surface.w & GLPT_GBUFFER_LIT) != 0u || has_option(GLPT_OPTION_UNLIT_AO));
  vec3 position = vec3(0.0), normal = vec3(0.0);
  float footprint = 0.0;
  if (fill) {
    position = imageLoad(gbuffer_position, pixel).xyz;
    normal = gbuffer_unpack_normal(surface.y);
    footprint = frame.params.w * max(abs(position.z), 1e-20);
  }
  vec3 direct = vec3(0.0), indirect = vec3(0.0), specular = vec3(0.0);
  float total = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 cell = home + ivec2(dx, dy);
      if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, cells))) continue;
      ivec2 traced = grid_pixel(cell);
      if (traced == pixel) return true;
      if (!fill) continue;
      uvec4 other = imageLoad(gbuffer_surface, traced);
      if (other.x != surface.x || ((other.w ^ surface.w) & GLPT_GBUFFER_LIT) != 0u) continue;
      float alike = dot(normal, gbuffer_unpack_normal(other.y));
      if (alike < 0.9) continue;
      vec3 offset = imageLoad(gbuffer_position, traced).xyz - position;
      if (abs(dot(normal, offset)) > 0.1 * length(offset) + 2.0 * footprint) continue;
      vec4 d = load_channel(GLPT_CHANNEL_DIRECT_DIFFUSE, traced);
      if (d.a <= 0.0) continue;
      vec2 distance = abs(vec2(traced - pixel)) * frame.trace_grid.xy;
      float w = max(1.0 - distance.x, 0.0) * max(1.0 - distance.y, 0.0);
      if (w <= 0.0) continue;
      direct += w * d.rgb;
      indirect += w * load_channel(GLPT_CHANNEL_INDIRECT_DIFFUSE, traced).rgb;
      specular += w * load_channel(GLPT_CHANNEL_SPECULAR, traced).rgb;
      total += w;
    }
  }
  if (total <= 0.0) return false;
  store_channel(GLPT_CHANNEL_DIRECT_DIFFUSE, pixel, vec4(direct / total, float(frame.sampling.y)));
  store_channel(GLPT_CHANNEL_INDIRECT_DIFFUSE, pixel, vec4(indirect / total, 0.0));
  store_channel(GLPT_CHANNEL_SPECULAR, pixel, vec4(specular / total, 0.0));
  return true;
}

// Puts the denoiser's tile of `pixel` on its list (GLPT_DN_BINDING_TILES) where `filtered`, the
// pixel being one the denoiser filters: one atomic per subgroup where its pixels share a tile
// (the workgroup's 8-wide rows lie in one tile), else one per pixel.
void list_denoise_tile(ivec2 pixel, bool filtered) {
  uint tile = tile_of(pixel, frame.image.xy);
  uint first = subgroupMin(filtered ? tile : 0xFFFFFFFFu);
  if (first == 0xFFFFFFFFu) return;
  bool shared_tile = subgroupAll(!filtered || tile == first);
  if (shared_tile ? subgroupElect() : filtered) {
    uint listed = shared_tile ? first : tile;
    if (atomicExchange(tile_words[listed], 1u) == 0u)
      tile_words[tile_count(frame.image.xy) + atomicAdd(tiles_dispatch[0], 1u)] = listed;
  }
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uint dropped = 0u;
  bool mine;
  bool in_image = pixel.x < int(frame.image.x) && pixel.y < int(frame.image.y);
  uvec4 surface = uvec4(0u);
  if (push.trace_pass == GLPT_TRACE_PASS_GRID) {
    mine = all(lessThan(pixel, grid_cells()));
    pixel = grid_pixel(pixel);
  } else {
    mine = in_image;
    if (in_image) surface = imageLoad(gbuffer_surface, pixel);
  }
  if (mine && push.trace_pass == GLPT_TRACE_PASS_FILL) mine = !filled_from_grid(pixel, surface);
  // What the denoiser filters (svgf_temporal.comp, shaded()): a covered pixel with a traced
  // sample, lit or with AO under GLPT_UNLIT=ao.
  bool filtered = false;
  if (mine) {
    uint pixel_index = uint(pixel.y) * frame.image.x + uint(pixel.x);
    if (push.trace_pass == GLPT_TRACE_PASS_GRID) surface = imageLoad(gbuffer_surface, pixel);
    uint samples = frame.sampling.y;
    Channels sum;
    sum.direct = vec3(0.0);
    sum.indirect = vec3(0.0);
    sum.specular = vec3(0.0);
    float traced = 0.0;
    bool lit = (surface.w & GLPT_GBUFFER_LIT) != 0u;
    // Lighting off: the colour raster mode draws (composite.comp), no rays, unless the unlit
    // policy darkens it by ambient occlusion. GL's equation has no randomness: one evaluation
    // stands for every sample.
    bool parity = lit && has_option(GLPT_OPTION_GL_PARITY);
    bool trace = lit || has_option(GLPT_OPTION_UNLIT_AO);
    if (surface.x != 0u && samples > 0u && trace) {
      Surface s = load_gbuffer_surface(pixel, surface);
      s.lit = lit;
      // What the composite pass multiplies the channels by (gbuffer_material.h): the diffuse
      // albedo (1 for unlit pixels, whose AO visibility is the indirect channel) and the
      // specular reflectance.
      Bsdf material = material_bsdf(s.diffuse_gl, s.specular_gl, s.shininess);
      vec3 albedo = lit ? material.diffuse : vec3(1.0);
      vec3 raw = lit ? raw_diffuse(material.diffuse, s.diffuse_gl, s.ambient) : vec3(1.0);
      // One call site of trace_path (everything in it is inlined where it is called).
      for (uint k = 0u; k < (parity ? 1u : samples); ++k) {
        Channels c;
        if (parity) {
          c = lighting_gl(s);
        } else {
          Sampler rng = make_sampler(pixel, pixel_index, frame.options.w + k, frame.image.w,
                                     frame.sampling.x + k);
          c = trace_path(s, rng);
        }
        // A non-finite sample (a degenerate transform or triangle) would poison the pixel for
        // the rest of the accumulation: it is dropped and counted, not shown as black.
        if (!finite(c.direct) || !finite(c.indirect) || !finite(c.specular) ||
            !finite(c.ambient)) {
          ++dropped;
          continue;
        }
        if (parity) {
          // Radiance: divided by the reflectances the composite multiplies by (GL's specular
          // reflectance is never ~0 where its specular colour is not: the ratio is bounded).
          sum.direct += mix(per_unit_reflectance(c.direct, albedo), c.direct, raw);
          sum.indirect += mix(per_unit_reflectance(c.ambient, albedo), c.ambient, raw);
          sum.specular += mix(vec3(0.0), c.specular / max(material.specular, vec3(1.0e-30)),
                              greaterThan(material.specular, vec3(0.0)));
        } else {
          sum.direct += mix(c.direct, albedo * c.direct, raw);
          sum.indirect += mix(c.indirect + per_unit_reflectance(c.ambient, albedo),
                              albedo * c.indirect + c.ambient, raw);
          sum.specular += c.specular;
        }
        traced += 1.0;
      }
    } else if (surface.x != 0u && samples > 0u) {
      traced = float(samples);
    }
    float scale = traced > 0.0 ? 1.0 / traced : 0.0;
    if (traced > 0.0 && parity) traced = float(samples);
    store_channel(GLPT_CHANNEL_DIRECT_DIFFUSE, pixel, vec4(sum.direct * scale, traced));
    store_channel(GLPT_CHANNEL_INDIRECT_DIFFUSE, pixel, vec4(sum.indirect * scale, 0.0));
    store_channel(GLPT_CHANNEL_SPECULAR, pixel, vec4(sum.specular * scale, 0.0));
    filtered = surface.x != 0u && trace && traced > 0.0;
  } else if (in_image && push.trace_pass == GLPT_TRACE_PASS_FILL) {
    // Traced by the grid pass or filled from it.
    filtered = surface.x != 0u &&
               ((surface.w & GLPT_GBUFFER_LIT) != 0u || has_option(GLPT_OPTION_UNLIT_AO)) &&
               load_channel(GLPT_CHANNEL_DIRECT_DIFFUSE, pixel).a > 0.0;
  }
  // The grid pass leaves the list to the fill pass, which sees every pixel.
  if (has_option(GLPT_OPTION_DENOISE_TILES) && push.trace_pass != GLPT_TRACE_PASS_GRID)
    list_denoise_tile(pixel, filtered);
  // Count rays with one atomic per subgroup rather than per invocation.
  uint subgroup_rays = subgroupAdd(g_rays);
  uint subgroup_dropped = subgroupAdd(dropped);
  if (subgroupElect()) {
    atomicAdd(counters.rays.x, subgroup_rays);
    if (subgroup_dropped != 0u) atomicAdd(counters.rays.y, subgroup_dropped);
  }
}
