// Data layouts shared by rt_core/raster (C++) and the fixed-function raster shaders
// (raster_ff.vert, raster_ff.frag, raster_ff.geom).
//
// Compiled as C++ (glm types) and as GLSL. Every member is a 16-byte vector or a mat4, so the
// std430 storage-buffer layout equals the C++ layout without padding rules to get wrong; the C++
// side checks sizes with static_assert.
#ifndef GLPT_SHADERS_RASTER_TYPES_H
#define GLPT_SHADERS_RASTER_TYPES_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace glpt::rt::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
#endif

#define GLPT_RASTER_MAX_LIGHTS 8
#define GLPT_RASTER_MAX_UNITS 4
#define GLPT_RASTER_MAX_CLIP_PLANES 6

// ---- descriptor set 0 --------------------------------------------------------------------------
#define GLPT_RASTER_BINDING_STATES 0  // RasterState[]: one per state snapshot of the record
// Combined image samplers: binding GLPT_RASTER_BINDING_TEXTURES + 4 * unit + kind, kind 0..3 =
// 1D, 2D, 3D, cube (unused bindings hold a 1x1 dummy texture).
#define GLPT_RASTER_BINDING_TEXTURES 1
#define GLPT_RASTER_TEXTURE_1D 0
#define GLPT_RASTER_TEXTURE_2D 1
#define GLPT_RASTER_TEXTURE_3D 2
#define GLPT_RASTER_TEXTURE_CUBE 3
// uint[]: per triangle of an unfilled draw, its boundary-edge mask (8 bits per triangle, four
// per uint), starting at RasterPushConstants.indices.y
#define GLPT_RASTER_BINDING_EDGES (GLPT_RASTER_BINDING_TEXTURES + 4 * GLPT_RASTER_MAX_UNITS)
// The same buffer holds the per-vertex materials of draws that have them (RasterPushConstants).
#define GLPT_RASTER_MATERIAL_VEC4S 5  // vec4s of one RasterMaterial

// ---- pixel rectangles (glBitmap, glDrawPixels, glCopyPixels: rt_core/raster/pixel_commands.cpp)
// Their images, as 32-bit words, for raster_ff.frag built with GLPT_PIXELS (1: fragments keep
// the rasterized depth; 2: they take the image's depth).
#define GLPT_RASTER_BINDING_PIXELS (GLPT_RASTER_BINDING_EDGES + 1)
// The colour buffer as an input attachment, for blending and logic ops in the fragment shader
// (raster_framebuffer_ops.h): written where the single-target render pass renders.
#define GLPT_RASTER_BINDING_FRAMEBUFFER (GLPT_RASTER_BINDING_PIXELS + 1)
// How the words hold one pixel (RasterState::pixel_image.x).
#define GLPT_PIXELS_RGBA32F 0u   // 4 words: R, G, B, A floats
#define GLPT_PIXELS_RGBA8 1u     // 1 word: B, G, R, A bytes (a copy of a BGRA8 colour buffer)
#define GLPT_PIXELS_DEPTH32F 2u  // 1 word: a float depth
#define GLPT_PIXELS_DEPTH24 3u  // 1 word: 24-bit depth in the low bits (a copy of the depth buffer)
#define GLPT_PIXELS_VALUE32 4u  // 1 word: a bitmap bit or a stencil index
#define GLPT_PIXELS_VALUE8 5u   // 1 byte, 4 per word (a copy of the stencil buffer)
// Which fragments a pass keeps (push constant indices.z): all, those whose value is not zero
// (bitmaps), or those whose value has bit (n & 7) set (stencil images, one pass per bit).
#define GLPT_PIXELS_KEEP_ALL 0u
#define GLPT_PIXELS_KEEP_NONZERO 0x200u
#define GLPT_PIXELS_KEEP_BIT 0x100u

// ---- vertex inputs (one binding per attribute; a binding's stride is 0 when the record holds
// one value for the whole draw) ------------------------------------------------------------------
#define GLPT_RASTER_ATTR_POSITION 0   // vec4
#define GLPT_RASTER_ATTR_NORMAL 1     // vec3
#define GLPT_RASTER_ATTR_COLOR 2      // vec4
#define GLPT_RASTER_ATTR_SECONDARY 3  // vec4
#define GLPT_RASTER_ATTR_FOG 4        // float
#define GLPT_RASTER_ATTR_EDGE 5       // uint8 as uint (geometry shader only)
#define GLPT_RASTER_ATTR_TEXCOORD0 6  // vec4 x GLPT_RASTER_MAX_UNITS
#define GLPT_RASTER_ATTR_COUNT (GLPT_RASTER_ATTR_TEXCOORD0 + GLPT_RASTER_MAX_UNITS)

// Varyings of raster_ff.vert and raster_ff.frag beyond the front colour (raster_varyings.h): a
// shader variant built with GLPT_VARYINGS declares only those of its bits as interface variables
// (plain integers: the GLSL preprocessor evaluates them).
#define GLPT_VARYING_BACK 1       // back colours (two-sided lighting)
#define GLPT_VARYING_SECONDARY 2  // secondary colours (colour sum)
#define GLPT_VARYING_FOG 4        // fog coordinate
#define GLPT_VARYING_TEXCOORDS 8  // the texture coordinates of every unit
// Not a varying but an input all the same: the fragment shader reads gl_FragCoord (polygon
// stipple). Lavapipe gives a fragment shader that declares gl_FragCoord or gl_FrontFacing one
// more input per triangle (its setup computes and bins coefficients for it: 48 bytes per
// triangle, measured as 23 % more scene memory and page faults for small lit triangles), so
// both are declared only where read: gl_FrontFacing with the back colours.
#define GLPT_VARYING_WINDOW_POSITION 16
#define GLPT_VARYINGS_ALL 31

// ---- specialization constants (constant_id) ----------------------------------------------------
// Vertex stage
#define GLPT_SC_VS_FLAGS 0
#define GLPT_VS_LIGHTING 1u
#define GLPT_VS_TWO_SIDE 2u
#define GLPT_VS_LOCAL_VIEWER 4u
#define GLPT_VS_SEPARATE_SPECULAR 8u
#define GLPT_VS_NORMALIZE 16u
#define GLPT_VS_RESCALE_NORMAL 32u
#define GLPT_VS_POINTS 64u  // point primitives: size, attenuation, GL's point rules
#define GLPT_VS_POINT_ATTENUATION 128u
#define GLPT_VS_LINES 256u             // line primitives: exact view clipping (clip distances)
#define GLPT_VS_FOG_COORD_SOURCE 512u  // fog coordinate from glFogCoord, not eye distance
#define GLPT_VS_NEEDS_EYE 1024u        // eye position needed (fog, texgen, clip planes, lights)
#define GLPT_VS_POINT_SPRITE 2048u     // ARB_point_sprite: the size unrounded, the centre unsnapped
// bit i: GL_LIGHTi enabled; bit 8 + i: it is positional (w != 0); bit 16 + i: it is a spotlight.
// The kinds select the shader's code per light, as Mesa's fixed-function program is generated for
// the enabled lights' kinds (both branches of a test on a value read per draw run for every
// vertex on lavapipe).
#define GLPT_SC_LIGHT_MASK 1
#define GLPT_LIGHT_POSITIONAL 0x100u
#define GLPT_LIGHT_SPOT 0x10000u
// bits 0-2: GL_COLOR_MATERIAL mode (0 off, 1 ambient, 2 diffuse, 3 ambient+diffuse, 4 specular,
// 5 emission); bit 3: front tracked; bit 4: back tracked
#define GLPT_SC_COLOR_MATERIAL 2
// 3 bits per coordinate (s, t, r, q) per unit, 12 bits per unit: 0 off, 1 object linear,
// 2 eye linear, 3 sphere map, 4 reflection map, 5 normal map. Units 0-1, then 2-3.
#define GLPT_SC_TEXGEN_01 3
#define GLPT_SC_TEXGEN_23 4
#define GLPT_SC_TEXCOORD_UNITS 5  // bit u: unit u samples a texture
#define GLPT_SC_CLIP_PLANES 6     // bit i: user clip plane i enabled
// Geometry stage (raster_unfilled.geom): polygon mode GL_LINE / GL_POINT
#define GLPT_SC_UNFILLED 7
#define GLPT_UNFILLED_FRONT_CW 1u    // glFrontFace(GL_CW)
#define GLPT_UNFILLED_CULL_FRONT 2u  // front-facing triangles are not drawn (culling, or the
#define GLPT_UNFILLED_CULL_BACK 4u   // other face's pass); likewise back-facing ones
#define GLPT_UNFILLED_OFFSET 8u      // polygon offset enabled for this mode
#define GLPT_UNFILLED_FLAT 16u       // GL_FLAT: the provoking vertex's colours
#define GLPT_UNFILLED_SPRITE 32u     // GL_POINT mode with ARB_point_sprite: the size unrounded
// Fragment stage
// per unit (10..13): bits 0-2 target (0 off, 1 1D, 2 2D, 3 3D, 4 cube), bits 3-5 env mode
// (0 modulate, 1 decal, 2 blend, 3 replace, 4 add, 5 combine), bits 6-8 base format (0 RGBA,
// 1 RGB, 2 ALPHA, 3 LUMINANCE, 4 LUMINANCE_ALPHA, 5 INTENSITY), bits 9-11: GL_CLAMP on s, t, r
// clamped in the shader, and the GLPT_UNIT_* bits below (rt_core/raster/sampler_setup.hpp)
#define GLPT_SC_UNIT0 10
#define GLPT_UNIT_CLAMP_S 0x200u
#define GLPT_UNIT_CLAMP_PER_FILTER 0x1000u  // GL_CLAMP: nearest or linear decided per quad
#define GLPT_UNIT_COMPARE 0x2000u           // depth comparison done by the shader
#define GLPT_UNIT_DEPTH 0x4000u  // a depth texture: depth in .r, expanded by GL_DEPTH_TEXTURE_MODE
// A rectangle texture (ARB_texture_rectangle) on the 2D binding: s, t are in texels and the
// shader normalizes them
#define GLPT_UNIT_RECT 0x8000u
// ARB_point_sprite's GL_COORD_REPLACE: (s, t, 0, 1) from the position in the sprite
#define GLPT_UNIT_COORD_REPLACE 0x10000u
// EXT_texture_filter_anisotropic on a 2-D texture (an anisotropy of 2 or more): the shader runs
// gallivm's anisotropic filter from Mesa's quad derivatives (raster_ff.frag anisotropic_2d)
#define GLPT_UNIT_ANISOTROPIC 0x20000u
// per unit (14..17): combine rgb function (bits 0-3), alpha function (4-7), rgb sources (8-16,
// 3 bits each), alpha sources (17-25), rgb operands (26-31, 2 bits each)
#define GLPT_SC_COMBINE0 14
// per unit (18..21): alpha operands (bits 0-2, 1 bit each)
#define GLPT_SC_COMBINE_ALPHA_OPERANDS0 18
#define GLPT_SC_FS_FLAGS 22
#define GLPT_FS_TWO_SIDE 1u
#define GLPT_FS_COLOR_SUM 2u  // add the secondary colour after texturing
#define GLPT_FS_POLYGON_STIPPLE 4u
#define GLPT_FS_CLEAR 8u               // the clear pipeline: output the clear colour only
#define GLPT_FS_SPRITE_LOWER_LEFT 16u  // GL_POINT_SPRITE_COORD_ORIGIN GL_LOWER_LEFT: t = 0 below
// Rasterized upside down, as Mesa renders window-system buffers
// (rt_core/raster/mesa_orientation.cpp): Vulkan's quads are Mesa's, derivatives as they come
#define GLPT_FS_MESA_ORIENTED 32u
// A draw split by alpha (path-traced mode, rt_core/scene/fragment_opacity.hpp): only its opaque
// fragments (alpha >= 254.5 / 255), into the G-buffer; only its others, over the trace
#define GLPT_FS_OPAQUE_PART 64u
#define GLPT_FS_TRANSLUCENT_PART 128u
// The alpha from which a fragment of such a draw counts as opaque: an 8-bit alpha of 255,
// allowing for the filter's rounding.
#define GLPT_OPAQUE_ALPHA (254.5 / 255.0)
// bits 8-10: alpha test function (0 off, else GL_NEVER + n - 0x200 + 1); bits 12-13: fog mode
// (0 off, 1 linear, 2 exp, 3 exp2)
#define GLPT_SC_FS_ALPHA_FOG 23

// Combine sources (3 bits) and functions (4 bits) as encoded above.
#define GLPT_SRC_TEXTURE 0u
#define GLPT_SRC_CONSTANT 1u
#define GLPT_SRC_PRIMARY 2u
#define GLPT_SRC_PREVIOUS 3u
#define GLPT_SRC_TEXTURE0 4u  // + unit (ARB_texture_env_crossbar)
#define GLPT_COMBINE_REPLACE 0u
#define GLPT_COMBINE_MODULATE 1u
#define GLPT_COMBINE_ADD 2u
#define GLPT_COMBINE_ADD_SIGNED 3u
#define GLPT_COMBINE_INTERPOLATE 4u
#define GLPT_COMBINE_SUBTRACT 5u
#define GLPT_COMBINE_DOT3_RGB 6u
#define GLPT_COMBINE_DOT3_RGBA 7u

struct RasterLight {
  vec4 ambient;
  vec4 diffuse;
  vec4 specular;
  vec4 position;     // eye space; w == 0: directional, xyz then normalized (as Mesa)
  vec4 spot;         // xyz: normalized eye-space spot direction, w: cos(cutoff) (-2: none)
  vec4 attenuation;  // x constant, y linear, z quadratic, w spot exponent
  vec4 half_vector;  // directional light, infinite viewer: normalize(VP + (0, 0, 1))
};

struct RasterMaterial {
  vec4 ambient;
  vec4 diffuse;
  vec4 specular;
  vec4 emission;
  vec4 shininess;  // x
};

// Everything a draw's shaders read, one per state snapshot of the record.
struct RasterState {
  mat4 modelview;
  mat4 mvp;            // projection * modelview, computed on the CPU as Mesa does
  mat4 normal_matrix;  // inverse transpose of the modelview (upper 3x3)
  mat4 texture_matrix[GLPT_RASTER_MAX_UNITS];
  vec4 viewport;      // x, y, width, height
  vec4 depth_range;   // near, far
  vec4 normal_scale;  // x: GL_RESCALE_NORMAL factor
  vec4 light_model_ambient;
  RasterLight lights[GLPT_RASTER_MAX_LIGHTS];
  RasterMaterial material[2];                     // front, back
  vec4 texgen_object[GLPT_RASTER_MAX_UNITS * 4];  // [unit * 4 + coord]
  vec4 texgen_eye[GLPT_RASTER_MAX_UNITS * 4];
  vec4 env_color[GLPT_RASTER_MAX_UNITS];
  vec4 env_scale[GLPT_RASTER_MAX_UNITS];  // x: RGB scale, y: alpha scale
  vec4 fog_color;
  vec4 fog_params;                                // x density, y start, z end, w 1 / (end - start)
  vec4 alpha_ref;                                 // x
  vec4 clip_planes[GLPT_RASTER_MAX_CLIP_PLANES];  // eye space
  uvec4 stipple[8];        // 32 rows of the polygon stipple, row r in stipple[r / 4][r % 4]
  vec4 point_size;         // x size, y min, z max, w fade threshold
  vec4 point_attenuation;  // xyz: constant, linear, quadratic
  vec4 clear_color;        // the clear pipeline's colour
  vec4 polygon_offset;     // x: factor, y: units times twice the depth buffer's resolution
  // Pixel rectangles: their image
  uvec4 pixel_image;   // format (GLPT_PIXELS_*), first word, width, height
  uvec4 pixel_stored;  // the groups the words hold: x0, y0, width, height (others read as 0)
  // The group of the image a fragment takes (rt_core/raster/pixel_quad.hpp): with a table
  // (x = its first word), group column = word[x + window column - y] (low half in the quad's first
  // triangle, high half in the second), group row = word[x + w + window row - z]; without one
  // (x = ~0u: bitmaps) the group is (window column - y, window row - z). y and z hold ints.
  uvec4 pixel_table;
  vec4 pixel_diagonal;  // a * x + b * y + c >= 0 in the quad's first triangle (window coordinates)
  vec4 pixel_scale;     // colour copies: pixel transfer scale and bias (GL 1.5 3.6.5)
  vec4 pixel_bias;
  // Texture units: what the fragment shader's own lookups (depth comparison, GL_CLAMP per
  // filter, anisotropic filtering) need; rt_core/raster/sampler_setup.hpp
  vec4 tex_size[GLPT_RASTER_MAX_UNITS];    // base level width, height, depth; w: level count
  // x: sampler lod bias, y: min lod, z: max lod, w: anisotropy (its whole part; 0: none)
  vec4 tex_lod[GLPT_RASTER_MAX_UNITS];
  vec4 tex_border[GLPT_RASTER_MAX_UNITS];  // border colour (texel layout, clamped)
  uvec4 tex_mode[GLPT_RASTER_MAX_UNITS];   // x: wrap s, t, r (GLPT_WRAP_*, 4 bits each),
                                           // y: GLPT_TEX_* flags, z: compare function (0-7)
  uvec4 drawable;  // x: the drawable's height (Mesa's 2x2 pixel quads count rows from its top)
};

// RasterState::tex_mode
#define GLPT_WRAP_REPEAT 0u
#define GLPT_WRAP_CLAMP 1u
#define GLPT_WRAP_CLAMP_TO_EDGE 2u
#define GLPT_WRAP_CLAMP_TO_BORDER 3u
#define GLPT_WRAP_MIRRORED_REPEAT 4u
#define GLPT_TEX_MIN_LINEAR 1u
#define GLPT_TEX_MAG_LINEAR 2u
#define GLPT_TEX_MIP_NEAREST 4u
#define GLPT_TEX_MIP_LINEAR 8u
// gallivm's static sampler state (lp_sampler_static_sampler_state): which lod adjustments apply
#define GLPT_TEX_LOD_BIAS 16u
#define GLPT_TEX_APPLY_MIN_LOD 32u
#define GLPT_TEX_APPLY_MAX_LOD 64u
#define GLPT_TEX_MIN_MAX_LOD_EQUAL 128u

// The draw's state index (its RasterState in GLPT_RASTER_BINDING_STATES) is
// RasterPushConstants::indices.x, pushed for the vertex stage alone (its own push constant range,
// the first 4 bytes), which hands it on as this flat varying (through the geometry shaders).
// llvmpipe loads a storage buffer with one scalar load per field only where the offset comes from
// a push constant or a constant (nir_src_is_always_uniform); indexed by gl_InstanceIndex, every
// field was a bounds-checked load per vertex lane (glxgears: most of lavapipe's vertex shading).
// Pushing it for the vertex stage alone leaves the other stages' push constants untouched: the
// fragment stage's would renew llvmpipe's fragment state on every draw. Location 12: geometry
// shaders take at most 16 input locations; the G-buffer pass's geometry shader hands it on at
// GLPT_GBUFFER_VARYING_STATE (its outputs from 12 on are the triangle's).
#define GLPT_RASTER_VARYING_STATE 12

struct RasterPushConstants {
  uvec4 indices;  // x: the state index (vertex stage only), y: first edge-mask word of an unfilled draw
  // Per-vertex materials (glMaterial between glBegin and glEnd), in the vertex buffer (bound as
  // GLPT_RASTER_BINDING_EDGES): x: first vec4, y: vec4s per vertex (10: the front then the back
  // RasterMaterial; 0: one pair for the whole draw), z: 1 when the draw has them (else the
  // state's material applies).
  uvec4 materials;
  // Blend factors, equations, logic op and constant colour of a draw whose fragment shader
  // blends (raster_framebuffer_ops.h: framebuffer_ops() has the layout); else zero.
  uvec4 framebuffer_ops;
};

#ifdef __cplusplus
static_assert(sizeof(RasterLight) == 112);
static_assert(sizeof(RasterMaterial) == 80);
static_assert(sizeof(RasterPushConstants) == 48);
}  // namespace glpt::rt::gpu
#endif

#endif  // GLPT_SHADERS_RASTER_TYPES_H
