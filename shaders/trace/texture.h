// Textures and the alpha test as rays see them (docs/light-transport.md, "Textures in the
// tracer"): a traced draw's texture units (1-D, 2-D, 3-D and cube maps) through their
// environments, at bounce hits with a mip level from ray cones (Akenine-Moeller et al., "Texture
// Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20), and GL's alpha
// test on every candidate hit of an alpha-tested draw, so cut-outs neither show nor cast shadows.
// Needs: `instances`, `textures`, the buffer reference types.
#ifndef GLPT_SHADERS_TRACE_TEXTURE_H
#define GLPT_SHADERS_TRACE_TEXTURE_H

// GL enums the texture environment and the alpha test use (gl.h values).
#define GLPT_GL_NEVER 0x0200u
#define GLPT_GL_LESS 0x0201u
#define GLPT_GL_EQUAL 0x0202u
#define GLPT_GL_LEQUAL 0x0203u
#define GLPT_GL_GREATER 0x0204u
#define GLPT_GL_NOTEQUAL 0x0205u
#define GLPT_GL_GEQUAL 0x0206u
#define GLPT_GL_REPLACE 0x1E01u
#define GLPT_GL_DECAL 0x2101u
#define GLPT_GL_ADD 0x0104u

// GL 1.5 table 3.21 for the modes rays honour; GL_BLEND and GL_COMBINE are taken as
// GL_MODULATE (documented approximation).
vec4 texture_environment(uint mode, vec4 color, vec4 texel) {
  if (mode == GLPT_GL_REPLACE) return texel;
  if (mode == GLPT_GL_DECAL) return vec4(mix(color.rgb, texel.rgb, texel.a), color.a);
  if (mode == GLPT_GL_ADD) return vec4(min(color.rgb + texel.rgb, 1.0), color.a * texel.a);
  return color * texel;
}

// GL's alpha test (GL 1.5 4.1.4).
bool alpha_test_passes(uint func, float alpha, float reference) {
  switch (func) {
    case GLPT_GL_NEVER: return false;
    case GLPT_GL_LESS: return alpha < reference;
    case GLPT_GL_EQUAL: return alpha == reference;
    case GLPT_GL_LEQUAL: return alpha <= reference;
    case GLPT_GL_GREATER: return alpha > reference;
    case GLPT_GL_NOTEQUAL: return alpha != reference;
    case GLPT_GL_GEQUAL: return alpha >= reference;
    default: return true;
  }
}

// The parts of a traced unit packed as GpuInstance.units holds it (shared_types.h).
uint unit_slot(uint unit) { return unit & 0xFFu; }  // + 1; 0: the unit is off for rays
uint unit_target(uint unit) { return (unit >> 8u) & 3u; }
uint unit_env_mode(uint unit) { return unit >> 16u; }

// (s, t, r) / q (a cube map's direction scales freely).
vec3 projected(vec4 texcoord) {
  return texcoord.w != 0.0 ? texcoord.xyz / texcoord.w : texcoord.xyz;
}

// The coordinates a lookup takes: projected, with GL_CLAMP's coordinates clamped to [0, 1] (the
// sampler is CLAMP_TO_BORDER or _TO_EDGE beyond).
vec3 lookup_coords(uint unit, vec4 texcoord) {
  vec3 c = projected(texcoord);
  uint clamped = (unit >> 10u) & 7u;
  for (uint i = 0u; i < 3u; ++i)
    if ((clamped & (1u << i)) != 0u) c[i] = clamp(c[i], 0.0, 1.0);
  return c;
}

// The texel of traced unit `unit` at coordinates `texcoord` (s, t, r, q), level `lod`.
vec4 sample_unit(uint unit, vec4 texcoord, float lod) {
  uint slot = unit_slot(unit) - 1u;
  vec3 c = lookup_coords(unit, texcoord);
  switch (unit_target(unit)) {
    case GLPT_TRACE_TARGET_1D:
      return textureLod(textures_1d[nonuniformEXT(slot)], c.x, lod);
    case GLPT_TRACE_TARGET_3D:
      return textureLod(textures_3d[nonuniformEXT(slot)], c, lod);
    case GLPT_TRACE_TARGET_CUBE:
      return textureLod(textures_cube[nonuniformEXT(slot)], c, lod);
    default:
      return textureLod(textures[nonuniformEXT(slot)], c.xy, lod);
  }
}

// Where a cube map's direction `d` falls on the face of major axis `axis`, in [-1, 1]^2.
vec2 cube_face_coords(vec3 d, uint axis) {
  float major = max(abs(d[axis]), 1.0e-20);
  return axis == 0u ? d.yz / major : axis == 1u ? d.xz / major : d.xy / major;
}

// The mip level of a hit on triangle (p0, p1, p2) with coordinates (t0, t1, t2) on `unit`, by a
// ray cone of width `cone_width` arriving along `direction` at a surface of unit normal
// `normal`: half the log of texels per unit area, plus the log of the cone's footprint. 1-D
// textures take texels per unit length along the steepest edge; 3-D ones the footprint of s and
// t; cube maps that of the three directions projected onto the face the middle one falls on.
float ray_cone_lod(uint unit, vec3 p0, vec3 p1, vec3 p2, vec4 t0, vec4 t1, vec4 t2,
                   float cone_width, vec3 direction, vec3 normal) {
  if (cone_width <= 0.0) return 0.0;
  uint slot = unit_slot(unit) - 1u, target = unit_target(unit);
  vec3 c0 = projected(t0), c1 = projected(t1), c2 = projected(t2);
  float facing = max(abs(dot(normal, direction)), 1.0e-3);
  float footprint = log2(cone_width / facing);
  if (target == GLPT_TRACE_TARGET_1D) {
    float size = float(textureSize(textures_1d[nonuniformEXT(slot)], 0));
    float l01 = length(p1 - p0), l02 = length(p2 - p0), l12 = length(p2 - p1);
    float per_length = 0.0;
    if (l01 > 0.0) per_length = max(per_length, abs(c1.x - c0.x) * size / l01);
    if (l02 > 0.0) per_length = max(per_length, abs(c2.x - c0.x) * size / l02);
    if (l12 > 0.0) per_length = max(per_length, abs(c2.x - c1.x) * size / l12);
    return per_length > 0.0 ? max(0.0, log2(per_length) + footprint) : 0.0;
  }
  vec2 size, u0 = c0.xy, u1 = c1.xy, u2 = c2.xy;
  if (target == GLPT_TRACE_TARGET_3D) {
    size = vec2(textureSize(textures_3d[nonuniformEXT(slot)], 0).xy);
  } else if (target == GLPT_TRACE_TARGET_CUBE) {
    // A face spans 2 in face coordinates: size / 2 texels per unit.
    size = 0.5 * vec2(textureSize(textures_cube[nonuniformEXT(slot)], 0));
    vec3 middle = abs(c0 + c1 + c2);
    uint axis = middle.x >= middle.y && middle.x >= middle.z ? 0u : middle.y >= middle.z ? 1u : 2u;
    u0 = cube_face_coords(c0, axis);
    u1 = cube_face_coords(c1, axis);
    u2 = cube_face_coords(c2, axis);
  } else {
    size = vec2(textureSize(textures[nonuniformEXT(slot)], 0));
  }
  vec2 e1 = (u1 - u0) * size, e2 = (u2 - u0) * size;
  float texel_area = abs(e1.x * e2.y - e1.y * e2.x);
  float world_area = length(cross(p1 - p0, p2 - p0));
  if (!(texel_area > 0.0) || !(world_area > 0.0)) return 0.0;
  return max(0.0, 0.5 * log2(texel_area / world_area) + footprint);
}

// Whether a candidate hit on an alpha-tested instance passes the draw's alpha test: the alpha GL
// computes there (the material's or the current colour's, through the units' environments).
bool candidate_passes_alpha_test(int instance_index, int primitive, vec2 barycentrics) {
  GpuInstance instance = instances[instance_index];
  if (instance.surface.x == 0u) return true;
  VertexArray vertex_array = VertexArray(instance.addresses.zw);
  MaterialArray material_array = MaterialArray(instance.materials.xy);
  uint first = 3u * uint(primitive);
  ShadingVertex v0 = vertex_array.vertices[first];
  ShadingVertex v1 = vertex_array.vertices[first + 1u];
  ShadingVertex v2 = vertex_array.vertices[first + 2u];
  vec3 w = vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics);
  GpuMaterial m = material_array.materials[uint(v0.normal.w)];
  float vertex_alpha = w.x * v0.color.a + w.y * v1.color.a + w.z * v2.color.a;
  bool tracks_diffuse = m.params.z == GLPT_COLOR_SOURCE_AMBIENT_AND_DIFFUSE ||
                        m.params.z == GLPT_COLOR_SOURCE_DIFFUSE;
  vec4 color = vec4(1.0, 1.0, 1.0, m.params.y != 0u && !tracks_diffuse ? m.diffuse.a : vertex_alpha);
  for (uint u = 0u; u < GLPT_TRACE_UNITS; ++u) {
    uint unit = instance.units[u];
    if (unit_slot(unit) == 0u) continue;
    vec4 texcoord = w.x * v0.texcoords[u] + w.y * v1.texcoords[u] + w.z * v2.texcoords[u];
    color = texture_environment(unit_env_mode(unit), color, sample_unit(unit, texcoord, 0.0));
  }
  return alpha_test_passes(instance.surface.x, color.a, uintBitsToFloat(instance.surface.y));
}

#endif  // GLPT_SHADERS_TRACE_TEXTURE_H
