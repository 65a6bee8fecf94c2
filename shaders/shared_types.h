// Data layouts shared by the C++ host code (rt_core) and the GLSL compute shaders.
//
// This header is compiled twice: as C++ (where vec4/uvec4/mat4 are glm types) and as GLSL (via
// GL_GOOGLE_include_directive). Every member is a 16-byte vec4/uvec4/ivec4 or a mat4, so std430
// (storage buffers), std140 (the uniform block) and the C++ layout are identical without any
// padding rules to get wrong; the C++ side checks the sizes with static_assert.
#ifndef GLPT_SHADERS_SHARED_TYPES_H
#define GLPT_SHADERS_SHARED_TYPES_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace glpt::rt::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
#endif

// ---- descriptor bindings ---------------------------------------------------------------------
// path_trace.comp, set 0
#define GLPT_PT_BINDING_SCENE 0         // accelerationStructureEXT (TLAS)
#define GLPT_PT_BINDING_INSTANCES 1     // GpuInstance[], indexed by instanceCustomIndex
#define GLPT_PT_BINDING_LIGHTS 2        // GpuLight[]
#define GLPT_PT_BINDING_ACCUMULATION 3  // vec4[width*height]: rgb radiance sum, a = coverage sum
#define GLPT_PT_BINDING_COUNTERS 4      // GpuCounters
#define GLPT_PT_BINDING_FRAME 5         // uniform FrameUniforms
// tonemap.comp, set 0
#define GLPT_TM_BINDING_ACCUMULATION 0
#define GLPT_TM_BINDING_OUTPUT 1  // uint[width*height], RGBA8 (R in the lowest byte)
#define GLPT_TM_BINDING_FRAME 2

// Both passes run 8x8 pixel tiles: neighbouring rays stay coherent, which is what lavapipe's
// ray traversal (one SIMD lane per invocation) rewards.
#define GLPT_TILE_SIZE 8

// ---- ray masks -------------------------------------------------------------------------------
// Every instance has GLPT_MASK_VISIBLE set; bits 0..6 say "casts shadows for light i" (lights 7+
// share bit 6). Primary and bounce rays use GLPT_MASK_VISIBLE, shadow rays the light's bit, so an
// instance can be visible yet not shadow a light (see light_setup.cpp: lamp markers).
#define GLPT_MASK_VISIBLE 0x80u
#define GLPT_MASK_SHADOW_BITS 7u

// ---- GpuMaterial::params.z flags and ColorSource values (same numbers as rt::ColorSource) ----
#define GLPT_COLOR_SOURCE_NONE 0u
#define GLPT_COLOR_SOURCE_AMBIENT_AND_DIFFUSE 1u
#define GLPT_COLOR_SOURCE_DIFFUSE 2u
#define GLPT_COLOR_SOURCE_AMBIENT 3u
#define GLPT_COLOR_SOURCE_EMISSION 4u
#define GLPT_COLOR_SOURCE_SPECULAR 5u

// One vertex of a triangle soup, in Morton-sorted triangle order: triangle p (the BLAS primitive
// index) uses vertices 3p..3p+2. The BLAS is built straight from `position.xyz` (stride 48
// bytes), so positions are stored once for both the builder and the shader. Colours stay full
// float so an unlit surface reproduces GL's 8-bit rounding of the same value exactly.
struct ShadingVertex {
  vec4 position;  // xyz: object-space position; w: material index of the triangle, as a float
  vec4 normal;    // xyz: object-space normal as given (not necessarily unit length); w: 0
  vec4 color;     // GL current colour
};

struct GpuMaterial {
  vec4 ambient;
  vec4 diffuse;
  vec4 specular;
  vec4 emission;
  uvec4 params;  // x: floatBits(shininess), y: lit (0/1), z: GLPT_COLOR_SOURCE_*, w: unused
};

// One entry per TLAS instance (instanceCustomIndex indexes this table).
struct GpuInstance {
  // xy: device address of the geometry's ShadingVertex array, zw: of its GpuMaterial array
  // (GL_EXT_buffer_reference_uvec2 turns a uvec2 straight into a buffer reference).
  // Normals are transformed in the shader with the query's world-to-object matrix (the
  // inverse-transpose GL uses), so no matrix is stored here.
  uvec4 addresses;
};

// A GL light in eye space.
struct GpuLight {
  vec4 position;  // w == 0: directional (xyz = unit direction towards the light)
  vec4 ambient;
  vec4 diffuse;
  vec4 specular;
  vec4 spot;         // xyz: unit spot direction, w: cos(cutoff), or -2 for "not a spot light"
  vec4 attenuation;  // x: constant, y: linear, z: quadratic, w: spot exponent
  uvec4 params;      // x: shadow ray cull mask, yzw: unused
};

struct FrameUniforms {
  mat4 inverse_projection;  // clip -> eye, for unprojecting primary rays
  vec4 clear_color;
  vec4 global_ambient;
  ivec4 viewport;  // x, y, width, height (GL window coordinates, y up)
  // x: image width, y: image height, z: light count, w: random seed of this frame
  uvec4 image;
  // x: samples already in the accumulation buffer before this frame (0 = overwrite),
  // y: samples to trace this frame, z: bounces, w: total samples after this frame (tonemap)
  uvec4 sampling;
  // x: ambient-occlusion radius (eye-space units), y: cos(light angular radius),
  // z, w: unused
  vec4 params;
};

struct GpuCounters {
  uvec4 rays;  // x: rays traced this frame (primary + shadow + bounce), yzw: unused
};

#ifdef __cplusplus
static_assert(sizeof(ShadingVertex) == 48);
static_assert(sizeof(GpuMaterial) == 80);
static_assert(sizeof(GpuInstance) == 16);
static_assert(sizeof(GpuLight) == 112);
static_assert(sizeof(FrameUniforms) == 160);
static_assert(sizeof(GpuCounters) == 16);
}  // namespace glpt::rt::gpu
#endif

#endif  // GLPT_SHADERS_SHARED_TYPES_H
