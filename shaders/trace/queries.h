// The two ray-query sites of the trace pass: the closest hit (bounces, ambient occlusion) and the
// occlusion test (shadow rays). One call site each: lavapipe inlines the whole BVH traversal at
// every call site, so fewer sites mean faster pipeline compiles and smaller code.
// Needs: `scene` (the TLAS).
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

#endif  // GLPT_SHADERS_TRACE_QUERIES_H
