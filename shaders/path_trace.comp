#version 460
// Trace pass of path-traced mode. Primary visibility comes from the G-buffer (gbuffer_layout.h),
// which the raster pipelines drew with GL's coverage, depth test, culling and matrices. For each
// pixel it covers, `frame.sampling.y` samples of
//   G-buffer surface -> GL direct lighting (one shadow ray per light of the pixel's own state)
//   + ambient (occluded by the next bounce ray) + emission -> `frame.sampling.z` cosine-sampled
//   diffuse bounces, shaded the same way (with the lights of the state the hit geometry was
//   drawn with)
// are added to the accumulation buffer, and the average over every accumulated frame is written
// into the colour buffer(s) the pixel's draw writes. Pixels no sample covered keep what the
// clears and raster draws left; pixels covered by some samples blend with it (anti-aliasing).
// Unlit surfaces show their G-buffer colour, the exact colour raster mode draws.
// Everything is in GL eye space. Colours are GL-linear, clamped when written.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_query : require
#extension GL_EXT_shader_image_load_formatted : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "gbuffer_layout.h"
#include "shared_types.h"

layout(local_size_x = GLPT_TILE_SIZE, local_size_y = GLPT_TILE_SIZE) in;

layout(set = 0, binding = GLPT_PT_BINDING_SCENE) uniform accelerationStructureEXT scene;
layout(std430, set = 0, binding = GLPT_PT_BINDING_INSTANCES) readonly buffer InstanceTable {
  GpuInstance instances[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_LIGHTS) readonly buffer LightTable {
  GpuLight lights[];
};
layout(std430, set = 0, binding = GLPT_PT_BINDING_STATES) readonly buffer StateTable {
  GpuTraceState states[];
};
// Per pixel two vec4: [2i] rgb: sum of the covered samples' radiance, a: sum of their alpha;
// [2i + 1] x: how many samples were covered.
layout(std430, set = 0, binding = GLPT_PT_BINDING_ACCUMULATION) buffer Accumulation {
  vec4 accumulation[];
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
// The colour buffers are BGRA8: no format qualifier (the view's format converts).
layout(set = 0, binding = GLPT_PT_BINDING_FRONT) uniform image2D front_buffer;
layout(set = 0, binding = GLPT_PT_BINDING_BACK) uniform image2D back_buffer;

layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer PositionArray {
  GpuPosition positions[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer VertexArray {
  ShadingVertex vertices[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer MaterialArray {
  GpuMaterial materials[];
};

const float kPi = 3.14159265358979;
// Bounce and directional-light shadow rays have no natural end.
const float kUnboundedRay = 1.0e30;

// ---- random numbers ---------------------------------------------------------------------------

// PCG hash (Jarzynski & Olano 2020): cheap, and good enough to both seed and step the generator.
uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

float next_random(inout uint rng) {
  rng = pcg_hash(rng);
  return float(rng >> 8) * (1.0 / 16777216.0);  // 24 bits: exactly representable, in [0,1)
}

vec2 next_random2(inout uint rng) {
  float u = next_random(rng);
  return vec2(u, next_random(rng));
}

// ---- geometry helpers -------------------------------------------------------------------------

// Orthonormal basis around a unit vector (Duff et al. 2017, branchless).
void make_basis(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

vec3 sample_cosine_hemisphere(vec3 n, vec2 u) {
  float r = sqrt(u.x);
  float phi = 2.0 * kPi * u.y;
  vec3 t, b;
  make_basis(n, t, b);
  return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u.x)) * n);
}

// Uniform direction inside the cone of half-angle acos(cos_max) around `axis` (soft shadows).
vec3 sample_cone(vec3 axis, float cos_max, vec2 u) {
  if (cos_max >= 1.0) return axis;
  float cos_theta = mix(1.0, cos_max, u.x);
  float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
  float phi = 2.0 * kPi * u.y;
  vec3 t, b;
  make_basis(axis, t, b);
  return normalize(sin_theta * cos(phi) * t + sin_theta * sin(phi) * b + cos_theta * axis);
}

// Moves a ray origin off the surface along `n` by a few float ulps of the position (Waechter &
// Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6):
// scale independent, so it works for scenes of any size without a tuned epsilon.
vec3 offset_ray_origin(vec3 p, vec3 n) {
  const float kOriginThreshold = 1.0 / 32.0;
  const float kFloatScale = 1.0 / 65536.0;
  const float kIntScale = 256.0;
  ivec3 offset_ulps = ivec3(kIntScale * n);
  vec3 p_ulps = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0 ? -offset_ulps.x : offset_ulps.x)),
                     intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0 ? -offset_ulps.y : offset_ulps.y)),
                     intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0 ? -offset_ulps.z : offset_ulps.z)));
  return vec3(abs(p.x) < kOriginThreshold ? p.x + kFloatScale * n.x : p_ulps.x,
              abs(p.y) < kOriginThreshold ? p.y + kFloatScale * n.y : p_ulps.y,
              abs(p.z) < kOriginThreshold ? p.z + kFloatScale * n.z : p_ulps.z);
}

vec3 normalize_or(vec3 v, vec3 fallback) {
  float len2 = dot(v, v);
  return len2 > 1.0e-30 ? v * inversesqrt(len2) : fallback;
}

// GL's (x)^e with 0^0 = 1 (GLSL's pow leaves 0^0 undefined, GL lighting needs 1).
float power_gl(float x, float e) { return e == 0.0 ? 1.0 : pow(max(x, 0.0), e); }

// ---- ray queries ------------------------------------------------------------------------------
// One call site each for closest-hit and shadow queries: lavapipe inlines the whole BVH traversal
// at every call site, so fewer sites mean faster pipeline compiles and smaller code.

struct Hit {
  float t;
  int instance;
  int primitive;
  vec2 barycentrics;
  mat4x3 object_to_eye;
  mat4x3 eye_to_object;
};

bool trace_closest(vec3 origin, vec3 direction, float t_max, out Hit hit) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, scene, gl_RayFlagsOpaqueEXT, GLPT_MASK_VISIBLE, origin, 0.0,
                        direction, t_max);
  while (rayQueryProceedEXT(query)) {
    // Everything is opaque: there are no candidates to confirm.
  }
  if (rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionTriangleEXT)
    return false;
  hit.t = rayQueryGetIntersectionTEXT(query, true);
  hit.instance = rayQueryGetIntersectionInstanceCustomIndexEXT(query, true);
  hit.primitive = rayQueryGetIntersectionPrimitiveIndexEXT(query, true);
  hit.barycentrics = rayQueryGetIntersectionBarycentricsEXT(query, true);
  hit.object_to_eye = rayQueryGetIntersectionObjectToWorldEXT(query, true);
  hit.eye_to_object = rayQueryGetIntersectionWorldToObjectEXT(query, true);
  return true;
}

bool occluded(vec3 origin, vec3 direction, float t_max, uint cull_mask) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, scene, gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT,
                        cull_mask, origin, 0.0, direction, t_max);
  while (rayQueryProceedEXT(query)) {
  }
  return rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionNoneEXT;
}

// ---- surfaces ---------------------------------------------------------------------------------

struct Surface {
  vec3 position;         // eye space, on the triangle
  vec3 shadow_position;  // where secondary rays start (terminator-corrected, offset)
  vec3 normal;           // shading normal (GL one-sided lighting: as given; two-sided lighting:
                         // flipped for back faces)
  vec3 offset_normal;    // unit geometric normal on the side secondary rays leave from
  vec3 ambient;
  vec3 diffuse;
  vec3 specular;
  vec3 emission;
  float shininess;
  uint state;  // record state: lights, ambient, viewer
};

// A surface where a bounce ray hit the traced geometry (BLAS shading data, no textures).
Surface load_surface(Hit hit, vec3 ray_direction) {
  GpuInstance instance = instances[hit.instance];
  PositionArray position_array = PositionArray(instance.addresses.xy);
  VertexArray vertex_array = VertexArray(instance.addresses.zw);
  MaterialArray material_array = MaterialArray(instance.materials.xy);
  uint first = 3u * uint(hit.primitive);
  ShadingVertex v0 = vertex_array.vertices[first];
  ShadingVertex v1 = vertex_array.vertices[first + 1u];
  ShadingVertex v2 = vertex_array.vertices[first + 2u];
  vec3 w = vec3(1.0 - hit.barycentrics.x - hit.barycentrics.y, hit.barycentrics);

  vec3 p0 = position_array.positions[first].position.xyz;
  vec3 p1 = position_array.positions[first + 1u].position.xyz;
  vec3 p2 = position_array.positions[first + 2u].position.xyz;
  vec3 n0 = v0.normal.xyz, n1 = v1.normal.xyz, n2 = v2.normal.xyz;
  vec3 p_object = w.x * p0 + w.y * p1 + w.z * p2;

  // Normals go to eye space with the inverse-transpose of object->eye, as GL's normal matrix:
  // n * M == transpose(M) * n, and M = eye->object is the inverse.
  mat3 normal_matrix_t = mat3(hit.eye_to_object);
  vec3 geometric_object = cross(p1 - p0, p2 - p0);
  vec3 geometric = normalize_or(geometric_object * normal_matrix_t, vec3(0.0, 0.0, 1.0));
  vec3 shading_object = w.x * n0 + w.y * n1 + w.z * n2;
  Surface s;
  s.state = instance.materials.z;
  s.normal = normalize_or(shading_object * normal_matrix_t, geometric);
  bool from_front = dot(geometric, ray_direction) < 0.0;
  s.offset_normal = from_front ? geometric : -geometric;
  s.position = hit.object_to_eye * vec4(p_object, 1.0);

  // Shadow terminator fix (Hanika, "Hacking the shadow terminator", Ray Tracing Gems II ch. 4):
  // on coarse meshes with smooth normals (glutSolidSphere...), secondary rays from the flat
  // triangle would hit the neighbouring triangles near the terminator and show the facets as
  // shadow steps. Lift the origin onto the curved surface the vertex normals describe, on the
  // side the normals point to (only when the ray arrived from that side). The G-buffer pass
  // does the same for the surfaces the camera sees (raster_ff.frag).
  vec3 shading_side = dot(geometric_object, shading_object) >= 0.0 ? geometric : -geometric;
  vec3 p_shadow = p_object;
  if (dot(shading_side, s.offset_normal) > 0.0) {
    vec3 fallback = normalize_or(geometric_object, vec3(0.0, 0.0, 1.0));
    vec3 u0 = normalize_or(n0, fallback), u1 = normalize_or(n1, fallback);
    vec3 u2 = normalize_or(n2, fallback);
    vec3 lift = w.x * min(0.0, dot(p_object - p0, u0)) * u0 +
                w.y * min(0.0, dot(p_object - p1, u1)) * u1 +
                w.z * min(0.0, dot(p_object - p2, u2)) * u2;
    p_shadow = p_object - lift;
  }
  s.shadow_position = offset_ray_origin(hit.object_to_eye * vec4(p_shadow, 1.0), s.offset_normal);

  // Interpolated relative to vertex 0, so a constant colour comes out bit-exact.
  vec3 color = v0.color.rgb + w.y * (v1.color.rgb - v0.color.rgb) +
               w.z * (v2.color.rgb - v0.color.rgb);
  GpuMaterial m = material_array.materials[uint(v0.normal.w)];
  s.ambient = m.ambient.rgb;
  s.diffuse = m.diffuse.rgb;
  s.specular = m.specular.rgb;
  s.emission = m.emission.rgb;
  s.shininess = uintBitsToFloat(m.params.x);
  // GL_COLOR_MATERIAL: the current colour replaces the tracked material colour(s).
  switch (m.params.z) {
    case GLPT_COLOR_SOURCE_AMBIENT_AND_DIFFUSE: s.ambient = color; s.diffuse = color; break;
    case GLPT_COLOR_SOURCE_DIFFUSE: s.diffuse = color; break;
    case GLPT_COLOR_SOURCE_AMBIENT: s.ambient = color; break;
    case GLPT_COLOR_SOURCE_EMISSION: s.emission = color; break;
    case GLPT_COLOR_SOURCE_SPECULAR: s.specular = color; break;
    default: break;
  }
  if (m.params.y == 0u) {
    // Lighting off: for light arriving from elsewhere a plain diffuse reflector of its colour,
    // not an emitter.
    s.ambient = color;
    s.diffuse = color;
    s.specular = vec3(0.0);
    s.emission = vec3(0.0);
  }
  return s;
}

// The direction from `p` towards the viewer of `state` (its projection's centre, or GL's
// infinite viewer for parallel projections).
vec3 towards_viewer(uint state, vec3 p) {
  vec4 viewer = states[state].viewer;
  return viewer.w != 0.0 ? normalize_or(viewer.xyz - p, vec3(0.0, 0.0, 1.0)) : viewer.xyz;
}

// The lit surface a G-buffer pixel shows; `alpha`: GL's fragment alpha there.
Surface load_gbuffer_surface(ivec2 pixel, uvec4 surface, out float alpha) {
  vec4 position = imageLoad(gbuffer_position, pixel);
  uvec4 m0 = imageLoad(gbuffer_material0, pixel);
  uvec4 m1 = imageLoad(gbuffer_material1, pixel);
  Surface s;
  s.state = surface.x - 1u;
  s.position = position.xyz;
  s.normal = gbuffer_unpack_normal(surface.y);
  vec3 geometric = gbuffer_unpack_normal(surface.z);
  // Secondary rays leave on the side of the geometric surface that faces the viewer. "The
  // viewer" is GL's: for a parallel projection (an identity projection, a flipped glOrtho) the
  // infinite viewer at +Z that GL lights with, so a face GL lights never shadows itself.
  s.offset_normal =
      dot(geometric, towards_viewer(s.state, s.position)) >= 0.0 ? geometric : -geometric;
  vec2 emission_b_lift_x = unpackHalf2x16(m1.z);
  vec3 lift = vec3(emission_b_lift_x.y, unpackHalf2x16(m1.w));
  // The terminator fix applies where the vertex normals point to the side rays leave from.
  vec3 base = dot(lift, s.offset_normal) > 0.0 ? s.position + lift : s.position;
  s.shadow_position = offset_ray_origin(base, s.offset_normal);
  vec4 diffuse = vec4(unpackHalf2x16(m0.x), unpackHalf2x16(m0.y));
  vec2 ambient_rg = unpackHalf2x16(m0.z), ambient_b_specular_r = unpackHalf2x16(m0.w);
  s.diffuse = diffuse.rgb;
  alpha = diffuse.a;
  s.ambient = vec3(ambient_rg, ambient_b_specular_r.x);
  s.specular = vec3(ambient_b_specular_r.y, unpackHalf2x16(m1.x));
  s.emission = vec3(unpackHalf2x16(m1.y), emission_b_lift_x.x);
  s.shininess = unpackHalf2x16(surface.w >> 16).x;
  return s;
}

// ---- GL lighting ------------------------------------------------------------------------------

// Sum over the lights of the surface's state of GL's diffuse + specular terms, each visible only
// if its shadow ray is unoccluded. `ambient_light` returns the state's global ambient + the
// lights' ambient terms (attenuated and spot-weighted as GL does), to be multiplied by the
// material ambient and an occlusion factor.
vec3 direct_light(Surface s, vec3 to_viewer, inout uint rng, inout uint rays,
                  out vec3 ambient_light) {
  vec3 radiance = vec3(0.0);
  ambient_light = states[s.state].global_ambient.rgb;
  uint light_count = states[s.state].info.x;
  for (uint i = 0u; i < light_count; ++i) {
    GpuLight light = lights[states[s.state].lights[i >> 2u][i & 3u]];
    vec3 to_light;
    float light_distance;
    float attenuation = 1.0;
    if (light.position.w != 0.0) {
      vec3 offset = light.position.xyz / light.position.w - s.position;
      light_distance = max(length(offset), 1.0e-20);
      to_light = offset / light_distance;
      attenuation = 1.0 / max(light.attenuation.x + light.attenuation.y * light_distance +
                                  light.attenuation.z * light_distance * light_distance,
                              1.0e-20);
    } else {
      to_light = light.position.xyz;
      light_distance = kUnboundedRay;
    }
    if (light.spot.w > -1.5) {
      float spot_cos = dot(-to_light, light.spot.xyz);
      attenuation *= spot_cos >= light.spot.w ? power_gl(spot_cos, light.attenuation.w) : 0.0;
    }
    ambient_light += attenuation * light.ambient.rgb;

    float n_dot_l = dot(s.normal, to_light);
    if (n_dot_l <= 0.0 || attenuation <= 0.0) continue;
    vec3 shadow_direction = sample_cone(to_light, frame.params.y, next_random2(rng));
    ++rays;
    if (occluded(s.shadow_position, shadow_direction, light_distance, light.params.x)) continue;
    vec3 half_vector = normalize(to_light + to_viewer);
    float specular = power_gl(dot(s.normal, half_vector), s.shininess);
    radiance += attenuation * (s.diffuse * light.diffuse.rgb * n_dot_l +
                               s.specular * light.specular.rgb * specular);
  }
  return radiance;
}

// ---- paths ------------------------------------------------------------------------------------

// The radiance leaving the G-buffer surface `first` towards the viewer.
vec3 trace_path(Surface first, inout uint rng, inout uint rays) {
  Surface s = first;
  vec3 to_viewer = towards_viewer(s.state, s.position);
  vec3 radiance = vec3(0.0);
  vec3 throughput = vec3(1.0);
  // Ambient term of the previous path vertex, added once the next ray shows it is not occluded.
  vec3 pending_ambient = vec3(0.0);
  uint bounces = frame.sampling.z;
  for (uint depth = 0u;; ++depth) {
    vec3 ambient_light;
    vec3 direct = direct_light(s, to_viewer, rng, rays, ambient_light);
    radiance += throughput * (s.emission + direct);
    pending_ambient = throughput * s.ambient * ambient_light;
    throughput *= s.diffuse;
    if (depth >= bounces || max(throughput.r, max(throughput.g, throughput.b)) <= 0.0) {
      radiance += pending_ambient;  // no further ray: nothing to occlude the ambient with
      break;
    }

    // Cosine-weighted diffuse bounce around the shading normal turned to the side rays leave
    // from; mirrored back if it would leave through the geometric surface. With a Lambertian
    // BRDF (albedo / pi) and cosine sampling the estimator is simply albedo * incoming radiance,
    // which `throughput` carries.
    vec3 bounce_normal = dot(s.normal, s.offset_normal) >= 0.0 ? s.normal : -s.normal;
    vec3 direction = sample_cosine_hemisphere(bounce_normal, next_random2(rng));
    float below = dot(direction, s.offset_normal);
    if (below <= 0.0) direction = normalize(direction - 2.0 * below * s.offset_normal);
    Hit hit;
    bool found = trace_closest(s.shadow_position, direction, kUnboundedRay, hit);
    ++rays;
    // Ambient occlusion: the previous vertex's ambient counts if this bounce ray got farther
    // than the AO radius (or left the scene).
    if (!found || hit.t > frame.params.x) radiance += pending_ambient;
    if (!found) break;  // a bounce that leaves the scene adds nothing
    s = load_surface(hit, direction);
    to_viewer = -direction;
  }
  return radiance;
}

// GL's fog (GL 1.5 3.10) on a lit pixel's radiance; unlit pixels come fogged from the G-buffer.
vec3 apply_fog(uint state, float fog_coordinate, vec3 radiance) {
  uint mode = states[state].info.y;
  if (mode == 0u) return radiance;
  vec4 p = states[state].fog_params;
  float z = fog_coordinate;
  float f = mode == 1u ? (p.z - z) * p.w : mode == 2u ? exp(-p.x * z) : exp(-(p.x * z) * (p.x * z));
  return mix(states[state].fog_color.rgb, radiance, clamp(f, 0.0, 1.0));
}

// Writes the pixel's average over all accumulated samples into the colour buffers `targets`:
// `sum` holds the covered samples (`covered` of them); the others show what the colour buffer
// holds (the clears and raster draws of this frame).
void write_average(ivec2 pixel, uint targets, vec4 sum, float covered) {
  float total = float(frame.sampling.w);
  for (uint t = 0u; t < 2u; ++t) {
    if ((targets & (1u << t)) == 0u) continue;
    vec4 background = t == 0u ? imageLoad(front_buffer, pixel) : imageLoad(back_buffer, pixel);
    vec4 color = clamp((sum + (total - covered) * background) / total, 0.0, 1.0);
    if (t == 0u)
      imageStore(front_buffer, pixel, color);
    else
      imageStore(back_buffer, pixel, color);
  }
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uint rays = 0u;
  if (pixel.x < int(frame.image.x) && pixel.y < int(frame.image.y)) {
    uint pixel_index = uint(pixel.y) * frame.image.x + uint(pixel.x);
    uvec4 surface = imageLoad(gbuffer_surface, pixel);
    bool covered = surface.x != 0u;
    uint samples = frame.sampling.y;
    vec4 sum = vec4(0.0);
    if (covered && samples > 0u) {
      if ((surface.w & GLPT_GBUFFER_LIT) == 0u) {
        // Lighting off: exactly the colour raster mode draws, no rays.
        sum = unpackUnorm4x8(imageLoad(gbuffer_material0, pixel).x) * float(samples);
      } else {
        float alpha;
        Surface s = load_gbuffer_surface(pixel, surface, alpha);
        float fog_coordinate = imageLoad(gbuffer_position, pixel).w;
        for (uint k = 0u; k < samples; ++k) {
          uint sample_index = frame.sampling.x + k;
          uint rng = pcg_hash(pixel_index ^ pcg_hash(frame.image.w + sample_index * 0x9E3779B9u));
          vec3 radiance = apply_fog(s.state, fog_coordinate, trace_path(s, rng, rays));
          // One NaN (a degenerate transform or triangle) would poison the pixel for the rest of
          // the accumulation: drop such a sample's radiance instead.
          if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(0.0);
          sum += vec4(radiance, alpha);
        }
      }
    }
    float count = covered ? float(samples) : 0.0;
    if (frame.sampling.x != 0u) {
      sum += accumulation[2u * pixel_index];
      count += accumulation[2u * pixel_index + 1u].x;
    }
    if (samples > 0u) {
      accumulation[2u * pixel_index] = sum;
      accumulation[2u * pixel_index + 1u] = vec4(count, 0.0, 0.0, 0.0);
    }
    if (count > 0.0) {
      uint targets = covered ? states[surface.x - 1u].info.z : frame.image.z;
      write_average(pixel, targets, sum, count);
    }
  }
  // Count rays with one atomic per subgroup rather than per invocation.
  uint subgroup_rays = subgroupAdd(rays);
  if (subgroupElect()) atomicAdd(counters.rays.x, subgroup_rays);
}
