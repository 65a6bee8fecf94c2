// The two ray-query sites of the trace pass: the closest hit (bounces, ambient occlusion) and the
// occlusion test (shadow rays). One call site each: lavapipe inlines the whole BVH traversal at
// every call site, so fewer sites mean faster pipeline compiles and smaller code.
// Needs: `scene` (the TLAS), `clip_planes`, texture.h (the alpha test of candidate hits).
#ifndef GLPT_SHADERS_TRACE_QUERIES_H
#define GLPT_SHADERS_TRACE_QUERIES_H

// Bounce and directional-light shadow rays have no natural end.
const float kUnboundedRay = 1.0e30;

struct Hit {
  float t;
  int instance;
  int primitive;
  vec2 barycentrics;
  mat4x3 object_to_eye;
  mat4x3 eye_to_object;
};

// Whether eye-space point p is on the side of every user clip plane of `instance` GL keeps.
bool inside_clip_planes(GpuInstance instance, vec3 p) {
  if (instance.tables.y == 0u) return true;
  GpuClipPlanes planes = clip_planes[instance.tables.y - 1u];
  for (uint i = 0u; i < min(planes.count.x, uint(GLPT_MAX_CLIP_PLANES)); ++i)
    if (dot(planes.planes[i], vec4(p, 1.0)) < 0.0) return false;
  return true;
}

// Only alpha-tested and clipped instances are not opaque (their TLAS instances lack
// FORCE_OPAQUE): their hits arrive as candidates, kept where GL keeps the fragment: inside the
// clip planes and passing the alpha test (texture.h).
void confirm_if_visible(rayQueryEXT query) {
  if (rayQueryGetIntersectionTypeEXT(query, false) != gl_RayQueryCandidateIntersectionTriangleEXT)
    return;
  int index = rayQueryGetIntersectionInstanceCustomIndexEXT(query, false);
  vec3 p = rayQueryGetWorldRayOriginEXT(query) +
           rayQueryGetIntersectionTEXT(query, false) * rayQueryGetWorldRayDirectionEXT(query);
  if (!inside_clip_planes(instances[index], p)) return;
  if (candidate_passes_alpha_test(index, rayQueryGetIntersectionPrimitiveIndexEXT(query, false),
                                  rayQueryGetIntersectionBarycentricsEXT(query, false)))
    rayQueryConfirmIntersectionEXT(query);
}

// Faces GL culls (TracedSurface::culled_side, the TLAS's back faces of draws that cull) are seen
// by no ray that looks out from a surface, as GL's camera never sees them: bounce rays and
// ambient occlusion (which measures how near the geometry a point sees is) skip back faces.
// Shadow rays stand for light arriving from a light, which meets a face from the far end of the
// ray: they skip front faces and are blocked by a culling draw only where light meets its drawn
// side (as a shadow map drawn with the program's own culling would be). Closed objects block
// both kinds; an open or inside-out one (a lamp drawn from the inside with its near wall
// culled) lets light through its culled side, as GL's image shows. Draws that do not cull are
// solid from both sides.
const uint kLookingRayFlags = gl_RayFlagsCullBackFacingTrianglesEXT;
const uint kLightRayFlags = gl_RayFlagsCullFrontFacingTrianglesEXT;

// The closest hit on the instances `mask` selects (GLPT_MASK_VISIBLE: the world; GLPT_MASK_SKY:
// the sky).
bool trace_closest(vec3 origin, vec3 direction, float t_max, uint mask, out Hit hit) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, scene, kLookingRayFlags, mask, origin, 0.0, direction, t_max);
  while (rayQueryProceedEXT(query)) confirm_if_visible(query);
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

// Whether anything the mask selects lies along the ray before t_max; `first_hit`: any hit will
// do (shadow rays), else the closest is found. `facing`: kLightRayFlags or kLookingRayFlags.
// `t` and `instance`: the committed hit.
bool query_occlusion(vec3 origin, vec3 direction, float t_max, uint cull_mask, bool first_hit,
                     uint facing, out float t, out int instance) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, scene, facing | (first_hit ? gl_RayFlagsTerminateOnFirstHitEXT : 0u),
                        cull_mask, origin, 0.0, direction, t_max);
  while (rayQueryProceedEXT(query)) confirm_if_visible(query);
  bool hit = rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionNoneEXT;
  t = hit ? rayQueryGetIntersectionTEXT(query, true) : t_max;
  instance = hit ? rayQueryGetIntersectionInstanceCustomIndexEXT(query, true) : 0;
  return hit;
}

#endif  // GLPT_SHADERS_TRACE_QUERIES_H
