#version 460
// The raw ray-query loop of bench/ray_ceiling: one ray per invocation, no shading. Each ray
// carries its flags (bit 0: terminate on first hit, the shadow rays) and its cull mask, as the
// trace pass's rays do; every instance is treated as opaque.
// Compiled at build time with: glslangValidator --target-env vulkan1.2 -V
#extension GL_EXT_ray_query : require

layout(local_size_x_id = 0) in;

layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;

struct Ray {
  vec4 org_tmin;  // xyz origin, w tmin
  vec4 dir_tmax;  // xyz direction, w tmax
  uvec4 info;     // x: flags (bit 0 terminate on first hit), y: cull mask
};
layout(std430, set = 0, binding = 1) readonly buffer Rays { Ray rays[]; };

struct Hit {
  float t;        // -1 on miss
  int instance;   // TLAS instance index (instanceCustomIndex), -1 on miss
  int primitive;  // -1 on miss
  uint pad;
};
layout(std430, set = 0, binding = 2) writeonly buffer Hits { Hit hits[]; };

layout(push_constant) uniform PC { uint ray_count; } pc;

void main() {
  uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  uint i = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
  if (i >= pc.ray_count) return;
  Ray r = rays[i];
  uint flags = gl_RayFlagsOpaqueEXT;
  if ((r.info.x & 1u) != 0u) flags |= gl_RayFlagsTerminateOnFirstHitEXT;
  rayQueryEXT rq;
  rayQueryInitializeEXT(rq, tlas, flags, r.info.y & 0xFFu, r.org_tmin.xyz, r.org_tmin.w,
                        r.dir_tmax.xyz, r.dir_tmax.w);
  while (rayQueryProceedEXT(rq)) {
  }
  Hit h;
  if (rayQueryGetIntersectionTypeEXT(rq, true) == gl_RayQueryCommittedIntersectionTriangleEXT) {
    h.t = rayQueryGetIntersectionTEXT(rq, true);
    h.instance = rayQueryGetIntersectionInstanceCustomIndexEXT(rq, true);
    h.primitive = rayQueryGetIntersectionPrimitiveIndexEXT(rq, true);
  } else {
    h.t = -1.0;
    h.instance = -1;
    h.primitive = -1;
  }
  h.pad = 0u;
  hits[i] = h;
}
