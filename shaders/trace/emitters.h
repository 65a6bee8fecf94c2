// Emissive surfaces as light sources of the trace pass (docs/light-transport.md, "Emission"):
// GL's emission of lit draws, gathered per frame into an emitter table of eye-space triangles
// (path_tracer.cpp). Next-event estimation picks one in proportion to its power and a point
// uniformly on it; a bounce ray that hits one weighs its emission against that choice (MIS).
// Needs: `emitters`, `frame` (options.z: the table's size), sampling.h.
#ifndef GLPT_SHADERS_TRACE_EMITTERS_H
#define GLPT_SHADERS_TRACE_EMITTERS_H

uint emitter_count() { return frame.options.z; }

// The emitter whose cumulative probability interval holds u (binary search over p0.w).
uint pick_emitter(float u) {
  uint low = 0u, high = emitter_count() - 1u;
  while (low < high) {
    uint middle = (low + high) >> 1u;
    if (u < emitters[middle].p0.w)
      high = middle;
    else
      low = middle + 1u;
  }
  return low;
}

// A point on an emitter as next-event estimation sees it from `origin`.
struct EmitterSample {
  vec3 direction;
  float distance;
  vec3 radiance;
  float pdf;  // per unit solid angle, the choice of the emitter included
};

bool sample_emitter(vec3 origin, float u_choice, vec2 u_point, out EmitterSample found) {
  GpuEmitter e = emitters[pick_emitter(u_choice)];
  found.direction = vec3(0.0, 0.0, 1.0);
  found.distance = 0.0;
  found.radiance = vec3(0.0);
  found.pdf = 0.0;
  if (e.p1.w <= 0.0) return false;
  vec3 w = sample_triangle_uniform(u_point);
  vec3 point = w.x * e.p0.xyz + w.y * e.p1.xyz + w.z * e.p2.xyz;
  vec3 offset = point - origin;
  found.distance = length(offset);
  if (!(found.distance > 0.0)) return false;
  found.direction = offset / found.distance;
  vec3 normal = normalize(cross(e.p1.xyz - e.p0.xyz, e.p2.xyz - e.p0.xyz));
  // A face GL culls is seen by no bounce ray (queries.h): it emits nothing either, so that both
  // techniques of MIS see the same emitter.
  if (e.emission0.a * dot(normal, origin - point) > 0.0) return false;
  found.pdf = e.p1.w * triangle_solid_angle_pdf(e.p2.w, found.distance,
                                                 dot(normal, found.direction));
  found.radiance = w.x * e.emission0.rgb + w.y * e.emission1.rgb + w.z * e.emission2.rgb;
  return found.pdf > 0.0 && !isinf(found.pdf);
}

// The density with which next-event estimation would have produced a ray that hit BLAS
// primitive `primitive` of `instance` at distance t along `direction`; 0 where it never would
// (the instance is not in the table, or nothing emits this frame).
float emitter_direction_pdf(GpuInstance instance, int primitive, vec3 direction, float t) {
  if (emitter_count() == 0u || instance.tables.x == 0u) return 0.0;
  GpuEmitter e = emitters[instance.tables.x - 1u + uint(primitive)];
  vec3 normal = normalize(cross(e.p1.xyz - e.p0.xyz, e.p2.xyz - e.p0.xyz));
  return e.p1.w * triangle_solid_angle_pdf(e.p2.w, t, dot(normal, direction));
}

#endif  // GLPT_SHADERS_TRACE_EMITTERS_H
