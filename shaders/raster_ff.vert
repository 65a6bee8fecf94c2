#version 460
// GL 1.5 fixed-function vertex processing (GL 1.5 2.10-2.14): transform, per-vertex lighting with
// colour material, texture coordinate generation and texture matrices, fog coordinate, user clip
// planes, point size and GL's point rules. Specialization constants (raster_types.h) switch the
// features a state snapshot uses, so each pipeline runs only its own code.
//
// Arithmetic follows Mesa's fixed-function vertex program where it decides pixels: positions are
// transformed as c0*x + c1*y + c2*z + c3*w with the modelview-projection product computed on the
// CPU (Mesa's order), colours are clamped per vertex.
//
// Built twice: GLPT_CLIP 1 declares gl_ClipDistance (user clip planes, exact line clipping). Each
// also in variants declaring fewer varyings (GLPT_VARYINGS, raster_varyings.h).
// GLPT_GBUFFER 1 (path-traced mode's G-buffer pass) also outputs the eye-space position, normal
// and current colour (gbuffer_layout.h) and offsets the position by the frame's sub-pixel jitter.
#extension GL_GOOGLE_include_directive : require

#include "raster_types.h"
#ifndef GLPT_GBUFFER
#define GLPT_GBUFFER 0
#endif
#if GLPT_GBUFFER
#include "gbuffer_layout.h"
#endif

layout(constant_id = GLPT_SC_VS_FLAGS) const uint kFlags = 0u;
layout(constant_id = GLPT_SC_LIGHT_MASK) const uint kLightMask = 0u;
layout(constant_id = GLPT_SC_COLOR_MATERIAL) const uint kColorMaterial = 0u;
layout(constant_id = GLPT_SC_TEXGEN_01) const uint kTexgen01 = 0u;
layout(constant_id = GLPT_SC_TEXGEN_23) const uint kTexgen23 = 0u;
layout(constant_id = GLPT_SC_TEXCOORD_UNITS) const uint kTexcoordUnits = 0u;
layout(constant_id = GLPT_SC_CLIP_PLANES) const uint kClipPlanes = 0u;

layout(std430, set = 0, binding = GLPT_RASTER_BINDING_STATES) readonly buffer States {
  RasterState states[];
};
layout(push_constant) uniform Push { RasterPushConstants push; };
#include "raster_vertex_words.h"
// The draw's state, read field by field where used (never copied whole).
#define S states[push.indices.x]

layout(location = GLPT_RASTER_ATTR_POSITION) in vec4 a_position;
layout(location = GLPT_RASTER_ATTR_NORMAL) in vec3 a_normal;
layout(location = GLPT_RASTER_ATTR_COLOR) in vec4 a_color;
layout(location = GLPT_RASTER_ATTR_SECONDARY) in vec4 a_secondary;
layout(location = GLPT_RASTER_ATTR_FOG) in float a_fog;
layout(location = GLPT_RASTER_ATTR_TEXCOORD0 + 0) in vec4 a_texcoord0;
layout(location = GLPT_RASTER_ATTR_TEXCOORD0 + 1) in vec4 a_texcoord1;
layout(location = GLPT_RASTER_ATTR_TEXCOORD0 + 2) in vec4 a_texcoord2;
layout(location = GLPT_RASTER_ATTR_TEXCOORD0 + 3) in vec4 a_texcoord3;

#define GLPT_VARYING_OUT out
#define GLPT_COLOR_VARYING_OUT out
#include "raster_varyings.h"
#if GLPT_GBUFFER
layout(location = GLPT_GBUFFER_VARYING_EYE) out vec4 v_eye;
layout(location = GLPT_GBUFFER_VARYING_NORMAL) out vec3 v_normal;
layout(location = GLPT_GBUFFER_VARYING_VERTEX_COLOR) out vec4 v_vertex_color;
layout(location = GLPT_GBUFFER_VARYING_NORMAL, component = 3) out float v_term_magnitude;
layout(location = GLPT_GBUFFER_VARYING_VERTEX_INDEX) flat out uint v_vertex_index;
#endif

// Declared in full so the geometry shader (raster_unfilled.geom) can match the block exactly.
out gl_PerVertex {
  vec4 gl_Position;
  float gl_PointSize;
#if GLPT_CLIP
  float gl_ClipDistance[8];
#endif
};

bool has(uint flag) { return (kFlags & flag) != 0u; }

// x * column 0 + y * column 1 + ...: the operation order Mesa's vertex program uses.
vec4 transform(mat4 m, vec4 v) { return m[0] * v.x + m[1] * v.y + m[2] * v.z + m[3] * v.w; }

// GL's x^e with 0^0 = 1 (GLSL's pow leaves it undefined).
float power_gl(float x, float e) { return e == 0.0 ? 1.0 : pow(max(x, 0.0), e); }

struct Lit {
  vec4 primary;
  vec3 secondary;  // specular when GL_SEPARATE_SPECULAR_COLOR
};

// The material of this vertex: its own when glMaterial was called between glBegin and glEnd
// (as Mesa's fixed-function program reads per-vertex material attributes), else the state's.
RasterMaterial material_of(uint face) {
  if (push.materials.z == 0u) return S.material[face];
  return vertex_material(uint(gl_VertexIndex), face);
}

// GL 1.5 2.14.1 for one face: `n` faces the viewer side being lit.
Lit light_face(uint face, vec3 n, vec3 eye, vec4 color) {
  RasterMaterial m = material_of(face);
  const uint cm_mode = kColorMaterial & 7u;
  const bool tracked = (kColorMaterial & (face == 0u ? 8u : 16u)) != 0u;
  vec4 ambient = m.ambient, diffuse = m.diffuse, specular = m.specular, emission = m.emission;
  if (tracked) {
    if (cm_mode == 1u || cm_mode == 3u) ambient = color;
    if (cm_mode == 2u || cm_mode == 3u) diffuse = color;
    if (cm_mode == 4u) specular = color;
    if (cm_mode == 5u) emission = color;
  }
  vec3 sum = emission.rgb + ambient.rgb * S.light_model_ambient.rgb;
  vec3 spec_sum = vec3(0.0);
  vec3 to_viewer = has(GLPT_VS_LOCAL_VIEWER) ? normalize(-eye) : vec3(0.0, 0.0, 1.0);
  for (int i = 0; i < GLPT_RASTER_MAX_LIGHTS; ++i) {
    if ((kLightMask & (1u << i)) == 0u) continue;
    RasterLight l = S.lights[i];
    vec3 vp;
    float attenuation = 1.0;
    vec3 half_vector;
    if ((kLightMask & (GLPT_LIGHT_POSITIONAL << i)) != 0u) {  // position.w != 0
      vec3 offset = l.position.xyz / l.position.w - eye;
      float d = length(offset);
      vp = offset / d;
      attenuation = 1.0 / (l.attenuation.x + l.attenuation.y * d + l.attenuation.z * d * d);
      half_vector = normalize(vp + to_viewer);
    } else {
      vp = l.position.xyz;
      half_vector = has(GLPT_VS_LOCAL_VIEWER) ? normalize(vp + to_viewer) : l.half_vector.xyz;
    }
    // GL 1.5 2.14.1 (and Mesa) apply the spotlight to directional lights too, with the light's
    // direction as VP. Mesa's test is strict: cos(cutoff) < spot cosine.
    if ((kLightMask & (GLPT_LIGHT_SPOT << i)) != 0u) {  // spot.w > -1.5
      float spot_cos = dot(-vp, l.spot.xyz);
      attenuation *= spot_cos > l.spot.w ? power_gl(spot_cos, l.attenuation.w) : 0.0;
    }
    float n_dot_vp = dot(n, vp);
    vec3 term = ambient.rgb * l.ambient.rgb;
    if (n_dot_vp > 0.0) {
      term += n_dot_vp * diffuse.rgb * l.diffuse.rgb;
      vec3 s_term = power_gl(dot(n, half_vector), m.shininess.x) * specular.rgb * l.specular.rgb;
      if (has(GLPT_VS_SEPARATE_SPECULAR))
        spec_sum += attenuation * s_term;
      else
        term += s_term;
    }
    sum += attenuation * term;
  }
  Lit lit;
  lit.primary = clamp(vec4(sum, diffuse.a), 0.0, 1.0);
  lit.secondary = clamp(spec_sum, 0.0, 1.0);
  return lit;
}

uint texgen_mode(uint unit, uint coord) {
  uint bits = unit < 2u ? kTexgen01 : kTexgen23;
  return (bits >> ((unit & 1u) * 12u + coord * 3u)) & 7u;
}

vec4 tex_coord_input(uint unit) {
  if (unit == 0u) return a_texcoord0;
  if (unit == 1u) return a_texcoord1;
  if (unit == 2u) return a_texcoord2;
  return a_texcoord3;
}

void main() {
  v_state = push.indices.x;  // GLPT_RASTER_VARYING_STATE
  vec4 position = a_position;
  vec4 clip = transform(S.mvp, position);
  vec3 eye = vec3(0.0);
  if (has(GLPT_VS_NEEDS_EYE)) {
    vec4 eye4 = transform(S.modelview, position);
    eye = eye4.xyz / eye4.w;
  }

  // Normal in eye space, as GL 2.11.3 (inverse transpose; then rescale or normalize).
  vec3 normal = vec3(0.0, 0.0, 1.0);
  const bool needs_normal =
      has(GLPT_VS_LIGHTING) || kTexgen01 != 0u || kTexgen23 != 0u || GLPT_GBUFFER != 0;
  if (needs_normal) {
    mat3 nm = mat3(S.normal_matrix);
    normal = nm[0] * a_normal.x + nm[1] * a_normal.y + nm[2] * a_normal.z;
    if (has(GLPT_VS_RESCALE_NORMAL)) normal *= S.normal_scale.x;
    if (has(GLPT_VS_NORMALIZE)) normal = normalize(normal);
  }

  // Colours.
  vec4 color = a_color;
  if (has(GLPT_VS_LIGHTING)) {
    Lit front = light_face(0u, normal, eye, color);
    v_front_color = front.primary;
    v_front_secondary = vec4(front.secondary, 0.0);
    if (has(GLPT_VS_TWO_SIDE)) {
      Lit back = light_face(1u, -normal, eye, color);
      v_back_color = back.primary;
      v_back_secondary = vec4(back.secondary, 0.0);
    } else {
      v_back_color = v_front_color;
      v_back_secondary = v_front_secondary;
    }
  } else {
    v_front_color = clamp(color, 0.0, 1.0);
    v_back_color = v_front_color;
    v_front_secondary = clamp(vec4(a_secondary.rgb, 0.0), 0.0, 1.0);
    v_back_secondary = v_front_secondary;
  }

  // Texture coordinates: generation, then the texture matrix.
  for (uint u = 0u; u < GLPT_RASTER_MAX_UNITS; ++u) {
    if ((kTexcoordUnits & (1u << u)) == 0u) {
      v_texcoord[u] = vec4(0.0, 0.0, 0.0, 1.0);
      continue;
    }
    vec4 t = tex_coord_input(u);
    vec3 u_eye = normalize(eye);
    vec3 reflected = reflect(u_eye, normal);
    for (uint c = 0u; c < 4u; ++c) {
      uint mode = texgen_mode(u, c);
      if (mode == 0u) continue;
      float value = t[c];
      if (mode == 1u) value = dot(S.texgen_object[u * 4u + c], position);
      if (mode == 2u) {
        vec4 eye4 = transform(S.modelview, position);
        value = dot(S.texgen_eye[u * 4u + c], eye4);
      }
      if (mode == 3u) {  // sphere map (GL 1.5 2.11.4)
        float m = 2.0 * sqrt(reflected.x * reflected.x + reflected.y * reflected.y +
                             (reflected.z + 1.0) * (reflected.z + 1.0));
        value = c == 0u ? reflected.x / m + 0.5 : reflected.y / m + 0.5;
      }
      if (mode == 4u) value = reflected[c];
      if (mode == 5u) value = normal[c];
      t[c] = value;
    }
    v_texcoord[u] = transform(S.texture_matrix[u], t);
  }

  // Fog coordinate: the eye distance (approximated by |z|, as Mesa) or glFogCoord.
  v_fog = has(GLPT_VS_FOG_COORD_SOURCE) ? a_fog : abs(eye.z);

#if GLPT_CLIP
  // User clip planes first, then (lines only) the four side planes of the view volume: GL clips
  // lines exactly where Vulkan implementations may use a guard band.
  int slot = 0;
  for (int i = 0; i < GLPT_RASTER_MAX_CLIP_PLANES; ++i) {
    if ((kClipPlanes & (1u << i)) == 0u) continue;
    vec4 eye4 = transform(S.modelview, position);
    gl_ClipDistance[slot++] = dot(S.clip_planes[i], eye4);
  }
  if (has(GLPT_VS_LINES) && slot + 4 <= 8) {
    gl_ClipDistance[slot++] = clip.w + clip.x;
    gl_ClipDistance[slot++] = clip.w - clip.x;
    gl_ClipDistance[slot++] = clip.w + clip.y;
    gl_ClipDistance[slot++] = clip.w - clip.y;
  }
  for (; slot < 8; ++slot) gl_ClipDistance[slot] = 1.0;
#endif

  if (has(GLPT_VS_POINTS)) {
    float size = S.point_size.x;
    if (has(GLPT_VS_POINT_ATTENUATION)) {
      float d = abs(eye.z);
      vec3 a = S.point_attenuation.xyz;
      size *= inversesqrt(a.x + a.y * d + a.z * d * d);
    }
    size = clamp(size, S.point_size.y, S.point_size.z);
    if (has(GLPT_VS_POINT_SPRITE)) {
      // Sprites are squares of the exact size centred on the exact position, as llvmpipe
      // rasterizes points whose size is not rounded (and as Vulkan rasterizes every point).
      if (any(greaterThan(abs(clip.xy), vec2(clip.w)))) clip = vec4(2.0, 2.0, 2.0, 1.0);
      gl_PointSize = size;
    } else {
      // GL's aliased points (GL 1.5 3.3) as llvmpipe rasterizes them: the size rounds to an
      // integer (halves down), the square is centred on floor(x) + 0.5 for odd sizes and on
      // floor(x + 0.5) for even ones, and a point whose centre is outside the view volume is not
      // drawn.
      float width = max(1.0, ceil(size - 0.5));
      bool outside = any(greaterThan(abs(clip.xy), vec2(clip.w)));
      vec2 ndc = clip.xy / clip.w;
      vec2 window = (ndc * 0.5 + 0.5) * S.viewport.zw + S.viewport.xy;
      window = floor(window * 256.0 + 0.5) / 256.0;  // llvmpipe's fixed-point vertex positions
      bool odd = mod(width, 2.0) == 1.0;
      vec2 centre = odd ? floor(window) + 0.5 : floor(window + 0.5);
      vec2 snapped_ndc = (centre - S.viewport.xy) / S.viewport.zw * 2.0 - 1.0;
      clip.xy = snapped_ndc * clip.w;
      if (outside) clip = vec4(2.0, 2.0, 2.0, 1.0);  // beyond the view volume: culled
      gl_PointSize = width;
    }
  }
#if GLPT_GBUFFER
  // Homogeneous, so a projective modelview (planar shadows) interpolates correctly; the fragment
  // shader divides.
  v_eye = transform(S.modelview, position);
  // How coarse the eye-space position is: its float error scales with the terms of the product,
  // not with the result (a vertex 1e5 from its object's origin under a modelview that brings it
  // back near the eye is 1/128 coarse, as the BLAS holding the same coordinates). offset_ray.h.
  vec4 terms = abs(S.modelview[0]) * abs(position.x) + abs(S.modelview[1]) * abs(position.y) +
               abs(S.modelview[2]) * abs(position.z) + abs(S.modelview[3]) * abs(position.w);
  v_term_magnitude = max(max(terms.x, terms.y), terms.z) / max(abs(v_eye.w), 1.0e-30);
  v_normal = normal;
  v_vertex_color = a_color;
  v_vertex_index = uint(gl_VertexIndex);
  // Sub-pixel jitter of the projection (anti-aliasing by accumulation): push.indices.zw hold the
  // offset in pixels as float bits.
  vec2 jitter = uintBitsToFloat(push.indices.zw);
  clip.xy += jitter * 2.0 / S.viewport.zw * clip.w;
#endif
  gl_Position = clip;
}
