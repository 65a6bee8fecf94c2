// Textures and the alpha test as rays see them (docs/light-transport.md, "Textures in the
// tracer"): a traced draw's texture units 0 and 1 (2-D textures) through their environments, at
// bounce hits with a mip level from ray cones (Akenine-Moeller et al., "Texture Level of Detail
// Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20), and GL's alpha test on every
// candidate hit of an alpha-tested draw, so cut-outs neither show nor cast shadows.
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

// The texture of table slot `slot` (+ 1, as GpuInstance stores it) at projective coordinates
// `texcoord`, level `lod`.
vec4 sample_slot(uint slot, vec4 texcoord, float lod) {
  vec2 uv = texcoord.w != 0.0 ? texcoord.xy / texcoord.w : texcoord.xy;
  return textureLod(textures[nonuniformEXT(slot - 1u)], uv, lod);
}

// GL's texture units 0 and 1 as rays see them (slot + 1, GL_TEXTURE_ENV_MODE of each; slot 0:
// the unit is off).
uvec2 unit_of(GpuInstance instance, uint unit) {
  return unit == 0u ? instance.surface.xy : instance.surface1.xy;
}

// The mip level of a hit on triangle (p, uv) by a ray cone of width `cone_width` arriving along
// `direction` at a surface of unit normal `normal`: half the log of texels per unit area, plus
// the log of the cone's footprint.
float ray_cone_lod(uint slot, vec3 p0, vec3 p1, vec3 p2, vec2 uv0, vec2 uv1, vec2 uv2,
                   float cone_width, vec3 direction, vec3 normal) {
  if (cone_width <= 0.0) return 0.0;
  vec2 size = vec2(textureSize(textures[nonuniformEXT(slot - 1u)], 0));
  vec2 e1 = (uv1 - uv0) * size, e2 = (uv2 - uv0) * size;
  float texel_area = abs(e1.x * e2.y - e1.y * e2.x);
  float world_area = length(cross(p1 - p0, p2 - p0));
  if (!(texel_area > 0.0) || !(world_area > 0.0)) return 0.0;
  float facing = max(abs(dot(normal, direction)), 1.0e-3);
  return max(0.0, 0.5 * log2(texel_area / world_area) + log2(cone_width / facing));
}

// Whether a candidate hit on an alpha-tested instance passes the draw's alpha test: the alpha GL
// computes there (the material's or the current colour's, through units 0 and 1's environments).
bool candidate_passes_alpha_test(int instance_index, int primitive, vec2 barycentrics) {
  GpuInstance instance = instances[instance_index];
  if (instance.surface.z == 0u) return true;
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
  if (instance.surface.x != 0u) {
    vec4 texcoord = w.x * v0.texcoord + w.y * v1.texcoord + w.z * v2.texcoord;
    color = texture_environment(instance.surface.y, color, sample_slot(instance.surface.x, texcoord, 0.0));
  }
  if (instance.surface1.x != 0u) {
    vec4 texcoord = w.x * v0.texcoord1 + w.y * v1.texcoord1 + w.z * v2.texcoord1;
    color = texture_environment(instance.surface1.y, color,
                                sample_slot(instance.surface1.x, texcoord, 0.0));
  }
  return alpha_test_passes(instance.surface.z, color.a, uintBitsToFloat(instance.surface.w));
}

#endif  // GLPT_SHADERS_TRACE_TEXTURE_H
