// Surfaces of the trace pass: the G-buffer's (what the camera sees) and those bounce rays hit
// (the BLASes' shading data). Needs: `instances`, `states`, the G-buffer images, the buffer
// reference types PositionArray, VertexArray and MaterialArray.
#ifndef GLPT_SHADERS_TRACE_SURFACE_H
#define GLPT_SHADERS_TRACE_SURFACE_H

#include "gbuffer_material.h"
#include "offset_ray.h"
#include "texture.h"

struct Surface {
  vec3 position;         // eye space, on the triangle
  vec3 shadow_position;  // where secondary rays start (terminator-corrected, offset)
  // The shading normal as GL lights with it: as given, or flipped for faces seen from behind by
  // two-sided lighting. GL's normals decide which side of a surface is lit, in GL and here.
  vec3 normal;
  vec3 offset_normal;    // unit geometric normal on the side secondary rays leave from
  vec3 ambient;          // GL's material ambient
  vec3 diffuse_gl;       // GL's diffuse (after colour material and textures)
  vec3 specular_gl;
  float shininess;
  vec3 emission;
  bool lit;              // false: GL lighting was off; `diffuse_gl` is the GL colour
  uint state;            // record state: lights, ambient, viewer
};

// The direction from `p` towards the viewer of `state` (its projection's centre, or the infinite
// viewer of parallel projections).
vec3 towards_viewer(uint state, vec3 p) {
  vec4 viewer = states[state].viewer;
  return viewer.w != 0.0 ? normalize_or(viewer.xyz - p, vec3(0.0, 0.0, 1.0)) : viewer.xyz;
}

// A surface where a bounce ray hit the traced geometry (BLAS shading data), reached by a ray
// cone of width `cone_width` (texture levels).
Surface load_surface(Hit hit, vec3 ray_direction, float cone_width) {
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
  vec3 shading = normalize_or(shading_object * normal_matrix_t, geometric);
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
  s.shadow_position = offset_ray_origin(hit.object_to_eye * vec4(p_shadow, 1.0), s.offset_normal,
                                        term_magnitude(hit.object_to_eye, p_shadow));

  // Interpolated relative to vertex 0, so a constant colour comes out bit-exact.
  vec3 color = v0.color.rgb + w.y * (v1.color.rgb - v0.color.rgb) +
               w.z * (v2.color.rgb - v0.color.rgb);
  // Two-sided lighting: faces seen from behind take the back material (GL 1.5 2.14.1).
  GpuMaterial m = material_array.materials[uint(v0.normal.w)];
  bool two_side = (states[s.state].info.w & GLPT_STATE_TWO_SIDE) != 0u;
  if (!from_front && two_side) m = material_array.materials[m.params.w];
  s.normal = !from_front && two_side ? -shading : shading;
  s.ambient = m.ambient.rgb;
  s.diffuse_gl = m.diffuse.rgb;
  s.specular_gl = m.specular.rgb;
  s.emission = m.emission.rgb;
  s.shininess = uintBitsToFloat(m.params.x);
  s.lit = m.params.y != 0u;
  // GL_COLOR_MATERIAL: the current colour replaces the tracked material colour(s).
  switch (m.params.z) {
    case GLPT_COLOR_SOURCE_AMBIENT_AND_DIFFUSE: s.ambient = color; s.diffuse_gl = color; break;
    case GLPT_COLOR_SOURCE_DIFFUSE: s.diffuse_gl = color; break;
    case GLPT_COLOR_SOURCE_AMBIENT: s.ambient = color; break;
    case GLPT_COLOR_SOURCE_EMISSION: s.emission = color; break;
    case GLPT_COLOR_SOURCE_SPECULAR: s.specular_gl = color; break;
    default: break;
  }
  if (!s.lit) {
    // Lighting off: the GL colour, which the unlit policy turns into a diffuse reflector or an
    // emitter (path_trace.comp).
    s.ambient = vec3(0.0);
    s.diffuse_gl = color;
    s.specular_gl = vec3(0.0);
    s.emission = vec3(0.0);
  }
  // The units apply, in GL's order, to the diffuse colour (the lit colour's stand-in, as the
  // G-buffer pass applies them, raster_ff.frag) or to the unlit colour. Under GL_SINGLE_COLOR
  // specular is textured too, by the environments' slope f(c) - f(0) (raster_ff.frag). Emission
  // stays untextured here, as next-event estimation sees it.
  bool texture_specular = s.lit && (states[s.state].info.w & GLPT_STATE_SEPARATE_SPECULAR) == 0u;
  vec3 specular_offset = vec3(0.0);
  // The triangle in eye space, for the ray cones' footprint (textured hits only).
  vec3 e0 = vec3(0.0), e1 = vec3(0.0), e2 = vec3(0.0);
  if (any(notEqual(instance.units & uvec4(0xFFu), uvec4(0u)))) {
    e0 = hit.object_to_eye * vec4(p0, 1.0);
    e1 = hit.object_to_eye * vec4(p1, 1.0);
    e2 = hit.object_to_eye * vec4(p2, 1.0);
  }
  for (uint u = 0u; u < GLPT_TRACE_UNITS; ++u) {
    uint unit = instance.units[u];
    if (unit_slot(unit) == 0u) continue;
    vec4 t0 = v0.texcoords[u], t1 = v1.texcoords[u], t2 = v2.texcoords[u];
    vec4 texcoord = w.x * t0 + w.y * t1 + w.z * t2;
    float lod = ray_cone_lod(unit, e0, e1, e2, t0, t1, t2, cone_width, ray_direction, geometric);
    vec4 texel = sample_unit(unit, texcoord, lod);
    uint env = unit_env_mode(unit);
    s.diffuse_gl = texture_environment(env, vec4(s.diffuse_gl, 1.0), texel).rgb;
    if (s.lit) s.ambient = texture_environment(env, vec4(s.ambient, 1.0), texel).rgb;
    if (texture_specular) {
      s.specular_gl = texture_environment(env, vec4(s.specular_gl, 1.0), texel).rgb;
      specular_offset = texture_environment(env, vec4(specular_offset, 1.0), texel).rgb;
    }
  }
  s.specular_gl -= specular_offset;
  return s;
}

// The lit surface a G-buffer pixel shows; `alpha`: GL's fragment alpha there.
Surface load_gbuffer_surface(ivec2 pixel, uvec4 surface) {
  vec4 position = imageLoad(gbuffer_position, pixel);
  GBufferMaterial m = gbuffer_material(surface, imageLoad(gbuffer_material0, pixel),
                                       imageLoad(gbuffer_material1, pixel));
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
  // The terminator fix applies where the vertex normals point to the side rays leave from.
  vec3 base = dot(m.lift, s.offset_normal) > 0.0 ? s.position + m.lift : s.position;
  s.shadow_position =
      offset_ray_origin(base, s.offset_normal, gbuffer_unpack_precision(surface.w));
  s.ambient = m.ambient;
  s.diffuse_gl = m.diffuse.rgb;
  s.specular_gl = m.specular;
  s.shininess = m.shininess;
  s.emission = m.emission;
  s.lit = true;
  return s;
}

#endif  // GLPT_SHADERS_TRACE_SURFACE_H
